// Partial derivatives (symbolic/derivative.hpp) against GiNaC's own diff, the independent oracle:
// the same expression node for node on the book's kinds of expressions, and the rules themselves
// on closed forms.
#include <gtest/gtest.h>

#include "support/random_expressions.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {
namespace {

using test::L;
using test::m;
using test::q1;
using test::q2;
using test::random_expression;
using test::u;

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
