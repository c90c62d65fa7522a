// Parameters: numbers as typed, or expressions of numbers and earlier parameters (2*L, pi/10,
// 30*deg) evaluated where they are read; anything else is refused at its position.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

System model_with(const std::string& parameters) {
  return parse_model("unidyn: 1\nparameters: " + parameters +
                         "\ncoordinates: [x]\nparticles:\n  P: {mass: m, position: [x, 0, 0]}\n",
                     "parameters.yaml");
}

TEST(Parameters, NumbersAndExpressionsOfEarlierParameters) {
  const System s = model_with("{m: 1.5, L: 0.25, L2: 2*L, lam: pi/10, tilt: 30*deg, k: 1e3}");
  ASSERT_EQ(s.parameters.size(), 6u);
  EXPECT_EQ(s.parameters[0].value, 1.5);
  EXPECT_FALSE(s.parameters[0].derived);
  EXPECT_EQ(s.parameters[2].value, 0.5);
  EXPECT_TRUE(s.parameters[2].derived);
  EXPECT_TRUE((s.parameters[2].definition - 2 * s.parameters[1].symbol).is_zero());
  EXPECT_DOUBLE_EQ(s.parameters[3].value, std::numbers::pi / 10);
  EXPECT_DOUBLE_EQ(s.parameters[4].value, std::numbers::pi / 6);
  EXPECT_EQ(s.parameters[5].value, 1000.0);
}

// Refused where it stands: a later parameter, a coordinate, t, no real value.
TEST(Parameters, WhatAParameterCannotBe) {
  for (const auto& [text, column] : {std::pair<std::string, int>{"{m: 1, a: 2*b, b: 1}", 25},
                                     {"{m: 1, a: t + 1}", 23},
                                     {"{m: 1, a: log(-1)}", 23},
                                     {"{m: 1, a: 1/0}", 24},
                                     {"{m: 1, a: E1}", 23}}) {
    try {
      (void)model_with(text);
      ADD_FAILURE() << "no error for " << text;
    } catch (const ModelError& e) {
      EXPECT_EQ(e.where().line, 2) << e.what();
      EXPECT_EQ(e.where().column, column) << text << ": " << e.what();
    }
  }
  // deg is a reserved name now
  EXPECT_THROW((void)model_with("{m: 1, deg: 2}"), ModelError);
}

}  // namespace
}  // namespace unidyn
