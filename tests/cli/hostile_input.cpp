// Hostile and unlucky input, as a user (or another user) can give it: models piped through
// /dev/stdin keyed by their own bytes, output that cannot be written, names with control
// characters or formula prefixes, expressions that would expand without end, initial values that
// divide by zero. Each ends in the documented exit status with the reason, never in wrong
// results, a crash or lost data.
#include <chrono>
#include <string>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

#ifdef UNIDYN_SANITIZED
constexpr bool kSanitized = true;  // commands run several times slower
#else
constexpr bool kSanitized = false;
#endif

std::string model_text(const std::string& body) {
  return "unidyn: 1\nparameters: {m: 1, g: 9.81}\ncoordinates: [x, y]\nparticles:\n"
         "  P: {mass: m, position: [x, y, 0]}\n" +
         body;
}

// A file in a fresh directory of its own (the cache directories need one).
std::string fresh_directory(const std::string& name) {
  const std::string path = temp_path(name);
  std::filesystem::remove_all(path);
  std::filesystem::create_directories(path);
  return path;
}

// A run's summary says its native code was compiled for it (in the background, perhaps still
// compiling when the run ended), not taken from the cache.
bool compiled_anew(const std::string& summary) {
  return contains(summary, "native code (compiled") ||
         contains(summary, "still compiling in the background");
}

// Two models piped one after the other through /dev/stdin, which can be read once: each is keyed
// by the bytes that were parsed, so the second never runs the first one's compiled equations.
TEST(HostileInput, PipedModelsAreKeyedByTheBytesParsed) {
  const std::string cache = "UNIDYN_CACHE_DIR='" + fresh_directory("cache") + "'";
  const std::string falling = temp_path("falling.yaml"), spring = temp_path("spring.yaml");
  write_file(falling, model_text("forces:\n  - gravity: -g*E2\ninitial: {der(x): 1}\n"));
  write_file(spring, model_text("forces:\n  - spring: {from: [0, 0, 0], to: P, stiffness: 4, "
                                "rest_length: 0}\ninitial: {x: 1, der(y): 1}\n"));
  for (const std::string& model : {falling, spring}) {
    const std::string csv = temp_path("piped.csv"), reference = temp_path("reference.csv");
    const Outcome piped =
        run("simulate /dev/stdin --t-end 1 -o '" + csv + "'", "cat '" + model + "' | " + cache);
    ASSERT_EQ(piped.status, 0) << piped.err;
    EXPECT_TRUE(compiled_anew(piped.out)) << piped.out;
    const Outcome tape =
        run("simulate '" + model + "' --t-end 1 --evaluation tape -o '" + reference + "'", cache);
    ASSERT_EQ(tape.status, 0) << tape.err;
    EXPECT_EQ(read_file(csv), read_file(reference)) << model;
  }
}

// The cache's key is what determines the code: a comment, another start or other settings reuse
// the library; another force compiles anew.
TEST(HostileInput, CacheKeyIsWhatDeterminesTheCode) {
  const std::string cache = "UNIDYN_CACHE_DIR='" + fresh_directory("code-key") + "'";
  const std::string path = temp_path("code-key.yaml");
  const std::string forces = "forces:\n  - gravity: -g*E2\n";
  write_file(path, model_text(forces + "initial: {der(x): 1}\n"));
  EXPECT_TRUE(compiled_anew(run("simulate '" + path + "' --t-end 0.1 -o /dev/null", cache).out));
  write_file(path,
             "# a comment\n" + model_text(forces + "initial: {x: 2}\nsimulate: {t_end: 3}\n"));
  EXPECT_TRUE(contains(run("simulate '" + path + "' --t-end 0.1 -o /dev/null", cache).out,
                       "native code (cached"));
  write_file(path, model_text("forces:\n  - gravity: -g*E1\n"));
  EXPECT_TRUE(compiled_anew(run("simulate '" + path + "' --t-end 0.1 -o /dev/null", cache).out));
}

// Output that cannot be written is a failed run: exit 1 with the reason; a file cut by a size
// limit ends with its last complete row, and the summary counts only those rows.
TEST(HostileInput, UnwritableOutputFailsTheRun) {
  const Outcome full = run("simulate spherical-pendulum -o /dev/full");
  EXPECT_EQ(full.status, 1);
  EXPECT_TRUE(contains(full.err, "No space left on device")) << full.err;
  // equations to a full standard output
  const std::string derive =
      std::string("'") + UNIDYN_EXECUTABLE + "' derive spherical-pendulum >/dev/full 2>/dev/null";
  const int status = std::system(derive.c_str());
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << status;

  const std::string csv = temp_path("limited.csv");
  const Outcome limited =
      run("simulate spherical-pendulum --t-end 100 -o '" + csv + "'", "trap '' XFSZ; ulimit -f 8;");
  EXPECT_EQ(limited.status, 1) << limited.out << limited.err;
  EXPECT_TRUE(contains(limited.out, "File too large")) << limited.out;
  EXPECT_TRUE(contains(limited.out, "the file ends with the last complete row")) << limited.out;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);  // every row complete
  EXPECT_TRUE(contains(limited.out, std::to_string(rows.rows.size()) + " rows written"))
      << limited.out;
}

// Names reach the terminal and the CSV header: control characters, bidirectional overrides and
// spreadsheet formula prefixes are refused with the position; messages never echo them raw.
TEST(HostileInput, NamesArePrintableText) {
  const std::string bad_names[] = {
      "outputs:\n  \"a\\nb\": x\n",          // a line break would split the header
      "outputs:\n  \"=HYPERLINK(1)\": x\n",  // a formula in a spreadsheet
      "outputs:\n  \"@SUM(A1)\": x\n",
      "outputs:\n  \"x\\e[2J\": x\n",        // clears the screen
      "conserved:\n  \"\\u202Eevil\": x\n",  // reverses what follows
  };
  for (const std::string& body : bad_names) {
    const std::string path = temp_path("name.yaml");
    write_file(path, model_text(body));
    const Outcome r = run("simulate '" + path + "' --t-end 0.1");
    expect_bad_input(r, body);
    EXPECT_TRUE(contains(r.err, path + ":7:3:")) << r.err;
    EXPECT_FALSE(contains(r.err, "\x1b")) << r.err;
    EXPECT_FALSE(contains(r.err, "\xe2\x80\xae")) << r.err;
  }
  const std::string title = temp_path("title.yaml");
  write_file(title, "name: \"Pendulum \\e[31m\"\n" + model_text(""));
  expect_bad_input(run("check '" + title + "'"), "name");
  // a misspelt key full of escapes is named, escaped
  const std::string key = temp_path("key.yaml");
  write_file(key, model_text("\"forc\\e]0;owned\\a\": []\n"));
  const Outcome r = run("check '" + key + "'");
  expect_bad_input(r, "key");
  EXPECT_TRUE(contains(r.err, "unknown key 'forc\\e]0;owned\\x07'")) << r.err;
  // a quoted name with a comma and quotes: one RFC 4180 field
  const std::string quoted = temp_path("quoted.yaml");
  write_file(quoted, model_text("outputs:\n  'x, \"doubled\"': 2*x\n"));
  const Outcome ok = run("simulate '" + quoted + "' --t-end 0.1");
  ASSERT_EQ(ok.status, 0) << ok.err;
  EXPECT_EQ(lines_of(ok.out).at(0), "t,x,y,der(x),der(y),energy,\"x, \"\"doubled\"\"\"");
}

// A forty-character power of a sum would expand to millions of terms: refused at its '^' at once
// (exit 2), whatever the exponent; a smaller one whose derivation grows past the budget stops
// with the budget's reason and the position of the model's largest power of a sum.
TEST(HostileInput, ExpansionsStopWithinTheBudget) {
  for (const int n : {20, 40, 200}) {
    const std::string path = temp_path("power.yaml");
    write_file(path, model_text("constraints:\n  - {name: c, velocity: \"(x+y+t+m+g+1)^" +
                                std::to_string(n) + "*der(x)\"}\n"));
    for (const std::string command : {"derive", "check", "simulate"}) {
      const auto start = std::chrono::steady_clock::now();
      const Outcome r = run(command + " '" + path + "'");
      const double seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      EXPECT_EQ(r.status, 2) << command << " " << n << ": " << r.err;
      EXPECT_TRUE(contains(r.err, path + ":7:39: this power of a sum would expand")) << r.err;
      EXPECT_LT(seconds, 10.0) << command << " " << n;
    }
  }
  const std::string path = temp_path("position.yaml");
  write_file(path,
             "unidyn: 1\nparameters: {m: 1, g: 1}\ncoordinates: [x, y]\nparticles:\n"
             "  P: {mass: m, position: [\"(x+y+m+g+1)^13\", y, 0]}\n");
  // printing groups by products of rates, so expands (check decides by exact evaluation, without
  // expanding)
  const Outcome r = run("derive --form matrix '" + path + "'");
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_TRUE(contains(r.err, path + ":5:28: grouping: an expansion would make")) << r.err;
  EXPECT_TRUE(contains(r.err, "the model's largest power of a sum is here")) << r.err;
  const Outcome checked = run("check '" + path + "'");
  EXPECT_EQ(checked.status, 0) << checked.out << checked.err;
  EXPECT_TRUE(contains(checked.out, "symbolic agreement: yes")) << checked.out;
}

// A fifty-character potential whose derivatives are fractions of high powers of sums: bringing
// them to one fraction (GiNaC's normal(), its greatest common divisors) took 34 s at N = 10 and
// more than 120 s at N = 12 in derive, check and simulate alike. Past normal()'s budget a
// fraction is left as it is: each command ends within seconds, and Newton–Euler still agrees
// with Lagrange.
TEST(HostileInput, FractionsPastTheBudgetAreNotBroughtToOneDenominator) {
  const std::string path = temp_path("fraction.yaml");
  write_file(path, model_text("forces:\n  - potential: 1/((x+y+m+2)^12-(x-y+g)^12+1)\n"
                              "initial: {x: 0.1, y: 0.2}\n"));
  for (const std::string command : {"derive", "check", "simulate --t-end 0.1 -o /dev/null"}) {
    const auto start = std::chrono::steady_clock::now();
    const Outcome r = run(command + " '" + path + "'");
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(r.status, 0) << command << ": " << r.out << r.err;
    EXPECT_LT(seconds, kSanitized ? 60.0 : 10.0) << command;
    if (command == "check") {
      EXPECT_TRUE(contains(r.out, "symbolic agreement: yes")) << r.out;
    }
  }
}

// An initial value that divides by zero is refused (exit 2, position) — under LeakSanitizer too:
// GiNaC's exception from inside its evaluation used to leak what it had built.
TEST(HostileInput, InitialValueDividingByZero) {
  const std::string path = temp_path("zero.yaml");
  write_file(path,
             "unidyn: 1\nparameters: {m: 0}\ncoordinates: [x]\nparticles:\n"
             "  P: {mass: 1, position: [x, 0, 0]}\ninitial:\n  der(x): \"1/m\"\n");
  const Outcome r = run("check '" + path + "'");
  expect_bad_input(r, "1/m");
  EXPECT_TRUE(contains(r.err, path + ":7:11:")) << r.err;
  const Outcome set = run("simulate spherical-pendulum --set L=0 --t-end 0.1");
  EXPECT_NE(set.status, 0);
  EXPECT_NE(set.status, 23) << set.err;  // LeakSanitizer's exit status
}

// A model file past 4 MiB (/dev/zero, a log named by mistake) is refused before it is parsed:
// exit 2, not gigabytes of memory or std::bad_alloc.
TEST(HostileInput, ModelFilesHaveASizeBound) {
  const Outcome zero = run("check /dev/zero");
  expect_bad_input(zero, "/dev/zero");
  EXPECT_TRUE(contains(zero.err, "larger than 4194304 bytes")) << zero.err;
  const std::string big = temp_path("big.yaml");
  write_file(big, model_text("") + "# " + std::string(5u << 20, 'x') + "\n");
  expect_bad_input(run("check '" + big + "'"), "5 MiB");
  std::remove(big.c_str());
}

// A model without `name:` is named by its file, escaped like any name: a file name with an
// escape sequence does not reach the terminal raw.
TEST(HostileInput, AFileNameAsTheModelsNameIsPrintable) {
  const std::string path = temp_path("a\x1b[31mb.yaml");
  write_file(path, model_text(""));
  const Outcome r = run("simulate '" + path + "' --t-end 0.1 -o /dev/null");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_FALSE(contains(r.out, "\x1b")) << r.out;
  EXPECT_TRUE(contains(r.out, "a\\e[31mb.yaml")) << r.out;
  std::remove(path.c_str());
}

// `sweep plan` refuses what it would turn into something else: a negative seed (2^64 - 1 once
// converted), a negative t_end, output step or tolerance (silently dropped before).
TEST(HostileInput, SweepPlanRefusesNegativeValues) {
  for (const char* option : {"--seed -1", "--t-end -1", "--output-step -0.1", "--rtol -1e-6"}) {
    const Outcome r = run("sweep plan rotating-hoop --grid Omega=1:2:2 " + std::string(option) +
                          " -o '" + temp_path("plan.yaml") + "'");
    EXPECT_EQ(r.status, 2) << option << ": " << r.out << r.err;
  }
}

// Past a file-size limit (ulimit -f, in KiB) the CSV cannot grow: the run fails (exit 1, not
// SIGXFSZ's 153) with the file cut back to its last whole row, all of them counted.
TEST(HostileInput, AFileSizeLimitEndsTheRunWithWholeRows) {
  const std::string csv = temp_path("limited.csv");
  const Outcome r = run("simulate kepler --t-end 1000 -o '" + csv + "'", "ulimit -f 2048;");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_LE(text.size(), 2048u * 1024u);
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);
  EXPECT_TRUE(contains(r.out, std::to_string(rows.rows.size()) + " rows written")) << r.out;
  std::remove(csv.c_str());
}

}  // namespace
}  // namespace unidyn
