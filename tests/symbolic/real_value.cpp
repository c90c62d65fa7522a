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

// GiNaC gives a product its sign, and puts it into one of its sums, by its order of terms (which
// follows the memory layout): one product is −(L + a)(a − b + c) in one run, (L + a)(b − a − c)
// in another (made here as such, held from GiNaC's evaluation). One value to the last bit, and a
// zero without a sign (a zero's sign would move atan2 by 2π).
TEST(RealValue, EitherSignOfASumGivesOneValue) {
  const GiNaC::realsymbol L("L"), a("a"), b("b"), c("c");
  const auto held = [](const GiNaC::exvector& factors) -> Expr {
    return GiNaC::mul(factors).hold();
  };
  const Expr negated = held({a - b + c, L + a, Expr(-1)}), turned = held({b - a - c, L + a});
  ASSERT_FALSE(negated.is_equal(turned));
  const GiNaC::exmap values{{L, GiNaC::numeric(7, 3)},
                            {a, GiNaC::numeric(1, 10)},
                            {b, GiNaC::numeric(-2, 7)},
                            {c, GiNaC::numeric(5, 11)}};
  EXPECT_EQ(*real_value(negated, values), *real_value(turned, values));
  const GiNaC::exmap zero{{L, 2}, {a, 1}, {b, 1}, {c, 0}};
  for (const Expr& product : {negated, turned}) {
    const double v = *real_value(product, zero);
    EXPECT_EQ(v, 0.0);
    EXPECT_FALSE(std::signbit(v));
    EXPECT_EQ(*real_value(GiNaC::atan2(product, -L), zero), std::numbers::pi);
  }
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
