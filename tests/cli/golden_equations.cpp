// The printed equations are the same text in every run (symbolic/canonical_text.hpp,
// cli/fixed_layout.hpp): `unidyn derive` of twelve bundled models by every method in every format
// equals the golden file kept in tests/golden (tests/golden/update.sh rewrites them when a change
// is intended), also with the process layout left random, which moves GiNaC's own order of terms
// (and the bicycle's, against a run in the fixed layout);
// and a simulation's CSV is byte-identical from run to run, by native code or the tape.
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

// The golden files; under the sanitizers the first of each method and format (the printers' code
// on one model each: 12 `derive` processes rather than 145, 170 s of the sanitized run — the texts
// of every model are the optimised build's to check).
std::vector<std::string> golden_files() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(UNIDYN_GOLDEN_DIR)) {
    const std::string name = entry.path().filename().string();
    if (name.ends_with(".text") || name.ends_with(".latex") || name.ends_with(".json")) {
      names.push_back(name);
    }
  }
  std::sort(names.begin(), names.end());
#ifdef UNIDYN_SANITIZED
  std::vector<std::string> kinds, first;
  for (const auto& name : names) {
    const std::string kind = name.substr(name.find('.'));  // .method.format
    if (std::find(kinds.begin(), kinds.end(), kind) != kinds.end()) continue;
    kinds.push_back(kind);
    first.push_back(name);
  }
  names = first;
#endif
  return names;
}

// `derive` with the arguments the file's name gives: <model>.<method>.<format>.
std::string derive_arguments(const std::string& file) {
  const std::size_t first = file.find('.'), second = file.find('.', first + 1);
  return "derive " + file.substr(0, first) + " --method " +
         file.substr(first + 1, second - first - 1) + " --format " + file.substr(second + 1);
}

// Where two texts first differ, as "line N: expected … got …".
std::string first_difference(const std::string& expected, const std::string& got) {
  const auto a = lines_of(expected), b = lines_of(got);
  for (std::size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    const std::string x = i < a.size() ? a[i] : "<none>", y = i < b.size() ? b[i] : "<none>";
    if (x != y) return "line " + std::to_string(i + 1) + ":\n  expected " + x + "\n  got      " + y;
  }
  return "equal";
}

class GoldenEquations : public ::testing::TestWithParam<std::string> {};

TEST_P(GoldenEquations, DeriveGivesTheGoldenText) {
  const std::string expected = read_file(std::string(UNIDYN_GOLDEN_DIR) + "/" + GetParam());
  ASSERT_FALSE(expected.empty());
  const Outcome r = run(derive_arguments(GetParam()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(r.out == expected) << GetParam() << ", " << first_difference(expected, r.out);
}

std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  std::replace_if(
      name.begin(), name.end(), [](char c) { return !std::isalnum(c); }, '_');
  return name;
}

INSTANTIATE_TEST_SUITE_P(Bundled, GoldenEquations, ::testing::ValuesIn(golden_files()), test_name);

// With the layout random in every run, GiNaC keeps the terms in another order each time; the text
// is still the golden one.
TEST(GoldenEquations, RandomLayoutsGiveTheSameText) {
  for (const char* file : {"heavy-top.lagrange.text", "double-pendulum.kane.latex",
                           "rolling-disk.newton-euler.json", "chaplygin-car.second-form.text"}) {
    const std::string expected = read_file(std::string(UNIDYN_GOLDEN_DIR) + "/" + file);
    for (int run_number = 0; run_number < 3; ++run_number) {
      const Outcome r = run(derive_arguments(file), "UNIDYN_RANDOM_LAYOUT=1");
      ASSERT_EQ(r.status, 0) << r.err;
      EXPECT_TRUE(r.out == expected) << file << ", " << first_difference(expected, r.out);
    }
  }
}

// The bicycle's equations hold a radical (its front contact point), whose normal forms GiNaC
// writes with either sign of a sum by the layout; its text is still one (too long for a golden
// file: 400 kB).
TEST(GoldenEquations, TheBicycleInAnyLayout) {
#if defined(__SANITIZE_ADDRESS__)
  // (a question of layout, not of memory: 80 s under the sanitizers, which run every other test)
  GTEST_SKIP() << "the bicycle's text in two layouts is compared in the plain build";
#endif
  const Outcome fixed = run("derive bicycle");
  ASSERT_EQ(fixed.status, 0) << fixed.err;
  ASSERT_GT(fixed.out.size(), 100000u);
  const Outcome random = run("derive bicycle", "UNIDYN_RANDOM_LAYOUT=1");
  ASSERT_EQ(random.status, 0) << random.err;
  EXPECT_TRUE(random.out == fixed.out) << first_difference(fixed.out, random.out);
}

// The compiled equations and so the generated code and every bit of a simulation's rows are the
// same under any layout too (GiNaC writes a sum in a product with either sign by its layout: the
// signs travel with the values, numeric/tape.cpp); the spherical pendulum's initial rate is a zero
// that GiNaC's form gave either sign.
TEST(GoldenEquations, CodeAndRowsInAnyLayout) {
  for (const char* command :
       {"derive rolling-disk --format c --method kane", "derive double-pendulum --format python",
        "simulate sphere-turntable --t-end 1", "simulate spherical-pendulum-cartesian --t-end 1",
        "derive torque-free-body --form zees"}) {
    const Outcome fixed = run(command);
    ASSERT_EQ(fixed.status, 0) << fixed.err;
    for (int run_number = 0; run_number < 2; ++run_number) {
      const Outcome random = run(command, "UNIDYN_RANDOM_LAYOUT=1");
      ASSERT_EQ(random.status, 0) << random.err;
      EXPECT_TRUE(random.out == fixed.out)
          << command << ", " << first_difference(fixed.out, random.out);
    }
  }
}

// The rows of a simulation, from native code and from the tape, in two runs each: one CSV.
TEST(GoldenEquations, SimulationRowsAreByteIdentical) {
  std::vector<std::string> texts;
  for (const char* evaluation : {"native", "tape", "native", "tape"}) {
    const Outcome r = run("simulate heavy-top --t-end 2 --evaluation " + std::string(evaluation));
    ASSERT_EQ(r.status, 0) << r.err;
    texts.push_back(r.out);
  }
  ASSERT_GT(texts[0].size(), 1000u);
  for (std::size_t i = 1; i < texts.size(); ++i) {
    EXPECT_TRUE(texts[i] == texts[0])
        << "run " << i << ", " << first_difference(texts[0], texts[i]);
  }
}

}  // namespace
}  // namespace unidyn
