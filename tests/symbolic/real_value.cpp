// Evaluating an expression in doubles: the value where there is one, nothing (and no exception,
// no leak) where there is none, such as 1/m at m = 0.
#include "unidyn/symbolic/real_value.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace unidyn {
namespace {

TEST(RealValue, ValuesOfTheModelLanguagesFunctions) {
  const GiNaC::realsymbol m("m"), x("x");
  const GiNaC::exmap values{{m, GiNaC::numeric(3, 2)}, {x, GiNaC::numeric(-1, 4)}};
  EXPECT_DOUBLE_EQ(*real_value(m * x + 1, values), 1.0 - 0.375);
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::pow(m, GiNaC::numeric(1, 2)), values), std::sqrt(1.5));
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::sin(x) + GiNaC::cos(m), values),
                   std::sin(-0.25) + std::cos(1.5));
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::atan2(x, m), values), std::atan2(-0.25, 1.5));
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::abs(x) + GiNaC::csgn(x) + GiNaC::step(x), values), -0.75);
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::Pi * m, values), std::numbers::pi * 1.5);
  EXPECT_DOUBLE_EQ(*real_value(GiNaC::exp(GiNaC::log(m)), values), 1.5);
}

TEST(RealValue, NoValueWithoutAnException) {
  const GiNaC::realsymbol m("m"), x("x");
  const GiNaC::exmap zero{{m, 0}};
  EXPECT_FALSE(real_value(1 / m, zero));
  EXPECT_FALSE(real_value(GiNaC::pow(m, -3) + 1, zero));
  EXPECT_FALSE(real_value(GiNaC::log(m - 1), zero));
  EXPECT_FALSE(real_value(GiNaC::sqrt(m - 1), zero));
  EXPECT_FALSE(real_value(x + m, zero));  // x has no value
  EXPECT_FALSE(real_value(GiNaC::exp(m + 1000), zero));
}

}  // namespace
}  // namespace unidyn
