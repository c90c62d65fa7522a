// Ctrl-C during a simulation: the run ends at the next row with every row before it kept and
// counted, the summary printed with "interrupted at t = …", and exit status 130.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <thread>

#include <algorithm>
#include <functional>
#include <optional>

#include "cli_support.hpp"

extern char** environ;

namespace unidyn {
namespace {

using namespace cli_test;

// `unidyn ARGS...` with its standard output to `summary`, SIGINT, SIGTERM and SIGHUP at their
// default and not blocked in the child, whatever the test inherited (a shell's background job
// ignores it, and unidyn leaves an ignored SIGINT alone). Its pid, or -1.
pid_t spawn_unidyn(std::vector<std::string> words, const std::string& summary) {
  words.insert(words.begin(), UNIDYN_EXECUTABLE);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, summary.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  sigaddset(&interrupt, SIGTERM);
  sigaddset(&interrupt, SIGHUP);
  posix_spawnattr_setsigdefault(&attributes, &interrupt);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return error == 0 ? pid : -1;
}

// `signal` sent to `pid`, and its end waited for: its wait status and the seconds that took.
struct Ending {
  int status = 0;
  double seconds = 0;
};
Ending end_with(pid_t pid, int signal) {
  Ending ending;
  const auto sent = std::chrono::steady_clock::now();
  if (::kill(pid, signal) != 0 || ::waitpid(pid, &ending.status, 0) != pid) ending.status = -1;
  ending.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  return ending;
}

TEST(Interrupt, CtrlCKeepsTheRowsAndTheSummary) {
  const std::string csv = temp_path("interrupted.csv"), summary = temp_path("summary.txt");
  const pid_t pid = spawn_unidyn({"simulate", "kepler", "--t-end", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  // interrupted once it is writing rows (its size from a stat: reading a file written at hundreds
  // of MB/s chases its end until the run is over)
  const auto written = [&] {
    std::error_code error;
    const auto size = std::filesystem::file_size(csv, error);
    return error ? std::uintmax_t{0} : size;
  };
  for (int wait = 0; wait < 200 && written() < 10000; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal, not by the handler";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "INTERRUPTED")) << out;
  EXPECT_TRUE(contains(out, "interrupted at t = ")) << out;
  EXPECT_TRUE(contains(out, "energy: initial")) << out;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);
  EXPECT_TRUE(contains(out, std::to_string(rows.rows.size()) + " rows written")) << out;
  EXPECT_LT(rows.rows.back()[0], 1e5);
  // the steps taken until then are counted
  EXPECT_FALSE(contains(out, "; 0 steps")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

// Ctrl-C is looked at every step, not only when a row is written: a run with one row at each end
// (12 s of steps between them) ends within a second of it, with its first row and the summary.
TEST(Interrupt, CtrlCBetweenRowsEndsTheRunAtOnce) {
  const std::string csv = temp_path("sparse.csv"), summary = temp_path("sparse.txt");
  // the native code in the cache first: the run's pace is the compiled code's from its start
  ASSERT_EQ(run("simulate kepler --t-end 1 -o /dev/null").status, 0);
  const pid_t pid = spawn_unidyn(
      {"simulate", "kepler", "--t-end", "1e5", "--output-step", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const Ending ending = end_with(pid, SIGINT);
  ASSERT_TRUE(WIFEXITED(ending.status));
  EXPECT_EQ(WEXITSTATUS(ending.status), 130);
  EXPECT_LT(ending.seconds, 1.0);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "INTERRUPTED")) << out;
  EXPECT_TRUE(contains(out, "1 rows written")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

// SIGTERM (a batch system's time limit) as Ctrl-C: the rows whole, the summary naming it, exit
// 143 (it used to kill the process, a torn last row in 3 of 20 trials).
TEST(Interrupt, SigtermKeepsWholeRowsAndTheSummary) {
  const std::string csv = temp_path("terminated.csv"), summary = temp_path("terminated.txt");
  ASSERT_EQ(run("simulate kepler --t-end 1 -o /dev/null").status, 0);  // cached native code
  const pid_t pid = spawn_unidyn({"simulate", "kepler", "--t-end", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal, not by the handler";
  EXPECT_EQ(WEXITSTATUS(status), 143);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "(SIGTERM)")) << out;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);
  EXPECT_TRUE(contains(out, std::to_string(rows.rows.size()) + " rows written")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

// An environment variable of this process (so of the commands it spawns) set while this lives,
// restored after.
class ScopedVariable {
 public:
  ScopedVariable(const char* name, const std::string& value) : name_(name) {
    const char* before = std::getenv(name);
    had_ = before != nullptr;
    if (had_) before_ = before;
    ::setenv(name, value.c_str(), 1);
  }
  ~ScopedVariable() { had_ ? ::setenv(name_, before_.c_str(), 1) : ::unsetenv(name_); }
  ScopedVariable(const ScopedVariable&) = delete;
  ScopedVariable& operator=(const ScopedVariable&) = delete;

 private:
  const char* name_;
  std::string before_;
  bool had_ = false;
};

// A cache directory of its own (UNIDYN_CACHE_DIR for the commands this test spawns): the native
// code is compiled, not found.
class PrivateCache {
 public:
  PrivateCache() : path_(temp_path("cache")), variable_("UNIDYN_CACHE_DIR", path_) {
    std::filesystem::create_directories(path_);
  }
  ~PrivateCache() {
    std::error_code error;
    std::filesystem::remove_all(path_, error);
  }
  const std::string& path() const { return path_; }
  // the build directories in it (build-<pid>-XXXXXX, one per compilation under way)
  int build_directories() const {
    int count = 0;
    std::error_code error;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(path_, error)) {
      if (entry.path().filename().string().rfind("build-", 0) == 0) ++count;
    }
    return count;
  }

 private:
  std::string path_;
  ScopedVariable variable_;
};

// $CXX a compiler that takes a minute (sleep 60, then c++) while this lives: the signal comes
// while it compiles.
class SlowCompiler {
 public:
  SlowCompiler() : path_(temp_path("slow-c++")), variable_("CXX", path_) {
    write_file(path_, "#!/bin/sh\nsleep 60\nexec c++ \"$@\"\n");
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all);
  }
  ~SlowCompiler() { std::remove(path_.c_str()); }

 private:
  std::string path_;
  ScopedVariable variable_;
};

// The processes whose command line names `text` (a compiler writing into the cache).
int processes_naming(const std::string& text) {
  int count = 0;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator("/proc", error)) {
    std::string line = read_file((entry.path() / "cmdline").string());
    std::replace(line.begin(), line.end(), '\0', ' ');
    if (contains(line, text)) ++count;
  }
  return count;
}

// Waits (up to 20 s) until `ready` holds.
bool wait_for(const std::function<bool()>& ready) {
  for (int k = 0; k < 400; ++k) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// SIGTERM while the native code compiles in the background of a run: the run ends at once (it
// waited for the compiler, ~13 s), the compiler is killed and reaped, its build directory removed.
TEST(Interrupt, SigtermStopsTheBackgroundCompiler) {
  const PrivateCache cache;
  const SlowCompiler compiler;
  const std::string csv = temp_path("compiling.csv"), summary = temp_path("compiling.txt");
  const pid_t pid = spawn_unidyn({"simulate", "kepler", "--t-end", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for([&] { return processes_naming(cache.path()) > 0; }))
      << "no compiler started";
  ASSERT_EQ(cache.build_directories(), 1);
  const Ending ending = end_with(pid, SIGTERM);
  ASSERT_TRUE(WIFEXITED(ending.status));
  EXPECT_EQ(WEXITSTATUS(ending.status), 143);
  EXPECT_LT(ending.seconds, 2.0);
  EXPECT_EQ(processes_naming(cache.path()), 0);
  EXPECT_EQ(cache.build_directories(), 0);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "(SIGTERM)")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

// SIGTERM while a report compiles its native code (in the foreground, no run to end): the process
// ends by the signal, and so does its compiler (it was left compiling for nobody); the build
// directory it leaves is removed by the next compilation.
TEST(Interrupt, SigtermDuringAReportLeavesNoCompiler) {
  const PrivateCache cache;
  std::optional<SlowCompiler> compiler(std::in_place);
  const std::string page = temp_path("page.html"), summary = temp_path("page.txt");
  const pid_t pid = spawn_unidyn({"report", "kepler", "--t-end", "1", "-o", page}, summary);
  ASSERT_GT(pid, 0);
  ASSERT_TRUE(wait_for([&] { return processes_naming(cache.path()) > 0; }))
      << "no compiler started";
  const Ending ending = end_with(pid, SIGTERM);
  ASSERT_TRUE(WIFSIGNALED(ending.status));
  EXPECT_EQ(WTERMSIG(ending.status), SIGTERM);
  // killed by unidyn's handler before unidyn ended: reaped by init at once
  EXPECT_TRUE(wait_for([&] { return processes_naming(cache.path()) == 0; }));
  EXPECT_EQ(cache.build_directories(), 1);
  EXPECT_FALSE(std::filesystem::exists(page));
  compiler.reset();
  ASSERT_EQ(run("simulate kepler --t-end 0.1 -o /dev/null").status, 0);
  EXPECT_EQ(cache.build_directories(), 0);
  std::remove(summary.c_str());
}

}  // namespace
}  // namespace unidyn
