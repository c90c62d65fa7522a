// Native code: every tape operation compiled by the system compiler gives the tape's own value,
// bit for bit; the cache by source hash; failures that leave the tape in charge.
#include "unidyn/numeric/native_code.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace unidyn {
namespace {

NativeOptions in_temporary_cache(const std::string& name) {
  NativeOptions options;
  options.cache_directory = ::testing::TempDir() + "unidyn-native-" + name;
  std::filesystem::remove_all(options.cache_directory);
  return options;
}

// Every operation of the tape, shared subexpressions, sincos, constants (π, 1/3) and an output
// that is an input.
Tape every_operation() {
  const GiNaC::realsymbol x("x"), y("y"), z("z");
  const GiNaC::ex third = GiNaC::numeric(1, 3);
  const std::vector<GiNaC::ex> outputs{
      x + y,
      x - y * third,
      x * y * z,
      x / y,
      -x,
      1 / (x + z),
      GiNaC::sqrt(GiNaC::abs(z) + 1),
      GiNaC::pow(GiNaC::abs(x) + 1, y),
      GiNaC::sin(x) * GiNaC::cos(x) + GiNaC::Pi,
      GiNaC::tan(y) + GiNaC::asin(z / 10) + GiNaC::acos(z / 10) + GiNaC::atan(x),
      GiNaC::atan2(y, x),
      GiNaC::sinh(z) + GiNaC::cosh(z) + GiNaC::tanh(z),
      GiNaC::exp(x) + GiNaC::log(GiNaC::abs(y) + 2),
      GiNaC::csgn(x) + GiNaC::step(y),
      GiNaC::pow(x, 7) + GiNaC::pow(y, -3),
      z,
  };
  return Tape::compile(outputs, std::vector<GiNaC::realsymbol>{x, y, z});
}

TEST(NativeCode, EveryOperationAgreesWithTheTapeBitForBit) {
  const Tape tape = every_operation();
  const auto library = NativeLibrary::build({{"f", &tape}}, in_temporary_cache("ops"));
  const NativeFunction f = library->function("f");
  std::mt19937 random(7);
  std::uniform_real_distribution<double> value(-3, 3);
  std::vector<double> native(tape.output_count());
  std::size_t compared = 0;
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> in{value(random), value(random), value(random)};
    if (trial == 0) in = {0.0, 0.0, 1.0};  // sign and step at 0
    const std::vector<double> expected = tape.evaluate(in);
    f(in.data(), native.data());
    for (std::size_t k = 0; k < expected.size(); ++k) {
      if (std::isnan(expected[k])) {
        EXPECT_TRUE(std::isnan(native[k])) << k;
        continue;
      }
      EXPECT_EQ(native[k], expected[k]) << "output " << k << " trial " << trial;
      ++compared;
    }
  }
  EXPECT_GT(compared, 3000u);
}

// The second build of the same source loads the cached library; another source compiles anew.
TEST(NativeCode, CachedByTheHashOfItsSource) {
  const NativeOptions options = in_temporary_cache("cache");
  const Tape tape = every_operation();
  const auto first = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_FALSE(first->cached());
  EXPECT_GT(first->compile_seconds(), 0.0);
  EXPECT_GT(first->source_bytes(), 500u);
  const auto second = NativeLibrary::build({{"f", &tape}}, options);
  EXPECT_TRUE(second->cached());
  EXPECT_EQ(second->path(), first->path());
  const auto renamed = NativeLibrary::build({{"g", &tape}}, options);
  EXPECT_FALSE(renamed->cached());
  EXPECT_NE(renamed->path(), first->path());
  EXPECT_THROW((void)renamed->function("f"), NativeCodeError);
}

// No compiler, or a compiler that fails: NativeCodeError that says which command and why.
TEST(NativeCode, FailuresSayWhy) {
  const Tape tape = every_operation();
  NativeOptions missing = in_temporary_cache("missing");
  missing.compiler = "/nonexistent/c++";
  try {
    (void)NativeLibrary::build({{"f", &tape}}, missing);
    ADD_FAILURE() << "no error";
  } catch (const NativeCodeError& error) {
    EXPECT_NE(std::string(error.what()).find("/nonexistent/c++"), std::string::npos)
        << error.what();
  }
  NativeOptions bad_flag = in_temporary_cache("bad-flag");
  bad_flag.flags += " --no-such-flag";
  try {
    (void)NativeLibrary::build({{"f", &tape}}, bad_flag);
    ADD_FAILURE() << "no error";
  } catch (const NativeCodeError& error) {
    EXPECT_NE(std::string(error.what()).find("no-such-flag"), std::string::npos) << error.what();
  }
  // nothing half-made is left in the cache
  for (const auto& entry : std::filesystem::directory_iterator(bad_flag.cache_directory)) {
    ADD_FAILURE() << entry.path();
  }
}

}  // namespace
}  // namespace unidyn
