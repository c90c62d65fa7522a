// Zero testing by exact evaluation at random points (symbolic/zero_test.hpp): identities of the
// sine and cosine that no expansion sees are zero, anything off by one term is proven non-zero, and
// what cannot be evaluated exactly is left undecided.
#include "unidyn/symbolic/zero_test.hpp"

#include <gtest/gtest.h>

namespace unidyn {
namespace {

using GiNaC::cos;
using GiNaC::sin;
using GiNaC::tan;

const GiNaC::realsymbol a("a"), b("b"), c("c"), m("m"), L("L"), w("w"), t("t"), v("v");

TEST(ZeroTest, IdentitiesOfSinesAndCosinesAreZero) {
  const Expr identities[] = {
      pow(sin(a), 2) + pow(cos(a), 2) - 1,
      // the angle sums, double and triple angles, and the chain's cos(a + b + c)
      sin(a + b) - sin(a) * cos(b) - cos(a) * sin(b),
      cos(a - b) - cos(a) * cos(b) - sin(a) * sin(b),
      sin(2 * a) - 2 * sin(a) * cos(a),
      cos(3 * a) - 4 * pow(cos(a), 3) + 3 * cos(a),
      cos(a + b + c) - cos(a + b) * cos(c) + sin(a + b) * sin(c),
      // half angles, a product Ω t as one angle, a quarter turn, tangents
      sin(a) - 2 * sin(a / 2) * cos(a / 2),
      sin(w * t + a) - sin(w * t) * cos(a) - cos(w * t) * sin(a),
      // Ω t an angle while Ω is also a factor (the rotating hoop's T): t is the angle's own
      w * w * (pow(sin(w * t), 2) + pow(cos(w * t), 2)) - w * w,
      t * (pow(sin(w * t), 2) + pow(cos(w * t), 2)) - t,  // ... or w the angle's own
      sin(a + GiNaC::Pi / 2) - cos(a),
      cos(a - 3 * GiNaC::Pi) + cos(a),
      tan(a) * cos(a) - sin(a),
      // rates, masses and lengths as polynomials and in denominators
      m * L * L * v * (cos(a) * cos(b) + sin(a) * sin(b)) / (m + L) -
          m * L * L * v * cos(a - b) / (L + m),
  };
  for (const Expr& e : identities) {
    EXPECT_EQ(vanishes_identically(e), std::optional<bool>(true)) << e;
    EXPECT_TRUE(identically_zero(e)) << e;
  }
}

TEST(ZeroTest, AnythingElseIsProvenNonZero) {
  const Expr differences[] = {
      pow(sin(a), 2) + pow(cos(a), 2) - 1 + 1 / (m * 1000000),
      sin(a + b) - sin(a) * cos(b) + cos(a) * sin(b),
      cos(2 * a) - 2 * pow(cos(a), 2),
      sin(a + GiNaC::Pi / 2) + cos(a),
      v * v - v,
      m * (cos(a) * cos(b) + sin(a) * sin(b)) - m * cos(a + b),
  };
  for (const Expr& e : differences) {
    EXPECT_EQ(vanishes_identically(e), std::optional<bool>(false)) << e;
    EXPECT_FALSE(identically_zero(e)) << e;
  }
}

TEST(ZeroTest, WhatCannotBeEvaluatedExactlyIsUndecided) {
  const Expr undecided[] = {
      // a radical, an angle that is also a polynomial variable, a constant angle, another function
      GiNaC::sqrt(pow(m + L, 2)) - GiNaC::sqrt(m * m + 2 * m * L + L * L),
      a * (pow(sin(a), 2) + pow(cos(a), 2)) - a,
      // Ω t an angle and a factor: neither symbol is the angle's own
      w * t * (pow(sin(w * t), 2) + pow(cos(w * t), 2)) - w * t,
      sin(a + 1) - sin(a) * cos(Expr(1)) - cos(a) * sin(Expr(1)),
      GiNaC::exp(a) * GiNaC::exp(b) - GiNaC::exp(a + b),
      // a denominator 0 at every point: no point where it is defined
      m / (pow(sin(a), 2) + pow(cos(a), 2) - 1),
  };
  for (const Expr& e : undecided) EXPECT_EQ(vanishes_identically(e), std::nullopt) << e;
  // ... and then decided by simplification
  EXPECT_TRUE(
      identically_zero(GiNaC::sqrt(pow(sin(a), 2) + pow(cos(a), 2) + L) - GiNaC::sqrt(1 + L)));
}

}  // namespace
}  // namespace unidyn
