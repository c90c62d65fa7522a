// Partial derivatives (symbolic/derivative.hpp) against GiNaC's own diff, the independent oracle:
// the same expression node for node on the book's kinds of expressions, and the rules themselves
// on closed forms.
#include <gtest/gtest.h>

#include <random>

#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {
namespace {

const GiNaC::realsymbol q1("q1"), q2("q2"), u("u"), m("m"), L("L");

// A random expression of depth ≤ `depth` in q1, q2, u and the parameters m, L: sums, products,
// integer and half powers, sines, cosines, and an exponential and atan2 (left to GiNaC).
Expr random_expression(std::mt19937& rng, int depth) {
  const std::vector<Expr> leaves{q1, q2, u, m, L, Expr(2), GiNaC::numeric(1, 3)};
  std::uniform_int_distribution<int> kind(0, depth > 0 ? 8 : 0);
  const auto leaf = [&] {
    return leaves[std::uniform_int_distribution<std::size_t>(0, leaves.size() - 1)(rng)];
  };
  const auto below = [&] { return random_expression(rng, depth - 1); };
  switch (kind(rng)) {
    case 1:
      return below() + below() + below();
    case 2:
      return below() * below() * below();
    case 3:
      return GiNaC::pow(below(), 3);
    case 4:
      return GiNaC::sqrt(below());
    case 5:
      return GiNaC::sin(below());
    case 6:
      return GiNaC::cos(below() - below());
    case 7:
      return GiNaC::exp(below());
    case 8:
      return GiNaC::atan2(below(), below());
    default:
      return leaf();
  }
}

TEST(Derivative, IsGiNaCsDiffNodeForNode) {
  std::mt19937 rng(20261126);
  int nonzero = 0;
  for (int k = 0; k < 400; ++k) {
    const Expr e = random_expression(rng, 4);
    // (as expressions: a realsymbol copied into a symbol would be another symbol)
    const std::vector<Expr> xs{q1, q2, u};
    const std::vector<Expr> g = gradient(e, xs);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(xs[i]);
      const Expr theirs = e.diff(x);
      EXPECT_TRUE(derivative(e, x).is_equal(theirs))
          << "d/d" << x << " of " << e << ":\n  " << derivative(e, x) << "\n  " << theirs;
      EXPECT_TRUE(g[i].is_equal(theirs)) << "gradient " << i << " of " << e;
      nonzero += theirs.is_zero() ? 0 : 1;
    }
  }
  // (the expressions do depend on the variables: most derivatives are not 0)
  EXPECT_GT(nonzero, 600);
}

TEST(Derivative, TheRules) {
  // (d/dq1) of m L² cos(q1 − q2) q̇: −m L² sin(q1 − q2) u
  EXPECT_TRUE(
      (derivative(m * L * L * GiNaC::cos(q1 - q2) * u, q1) + m * L * L * GiNaC::sin(q1 - q2) * u)
          .expand()
          .is_zero());
  // √(q1² + q2²)' = q1 / √(q1² + q2²)
  const Expr r = GiNaC::sqrt(q1 * q1 + q2 * q2);
  EXPECT_TRUE((derivative(r, q1) - q1 / r).normal().is_zero());
  // constants and other symbols
  EXPECT_TRUE(derivative(m * L, q1).is_zero());
  EXPECT_TRUE(derivative(q1, q1).is_equal(1));
  EXPECT_TRUE(derivative(GiNaC::sin(q2), q1).is_zero());
}

}  // namespace
}  // namespace unidyn
