// The expansion budget: the structural bound on the terms of an expansion (exact for powers of
// sums of distinct symbols, an upper bound always), the checked expansion equal to GiNaC's where
// the bound is loose, and the refusal of expansions past the budget.
#include "unidyn/symbolic/expansion_budget.hpp"

#include "support/random_expressions.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>
#include <vector>

namespace unidyn {
namespace {

std::size_t terms(const Expr& e) {
  return GiNaC::is_a<GiNaC::add>(e) ? e.nops() : 1;
}

// C(n, k)
double choose(double n, double k) {
  return std::round(std::exp(std::lgamma(n + 1) - std::lgamma(k + 1) - std::lgamma(n - k + 1)));
}

// is_expanded says yes only where GiNaC's expand gives the expression back, node for node; and
// says it of every expansion GiNaC makes of a polynomial in symbols and functions.
TEST(ExpansionBudget, ExpandedIsWhatExpandGivesBack) {
  std::mt19937 rng(20261128);
  int expanded = 0;
  for (int k = 0; k < 600; ++k) {
    const Expr e = test::random_expression(rng, 3);
    if (is_expanded(e)) {
      ++expanded;
      EXPECT_TRUE(e.expand().is_equal(e)) << e;
    }
  }
  // every polynomial in symbols, sines and cosines is called expanded once GiNaC expanded it
  const std::vector<Expr> atoms{test::q1, test::m, GiNaC::sin(test::q1), GiNaC::cos(test::q2),
                                GiNaC::numeric(2, 3)};
  std::uniform_int_distribution<std::size_t> pick(0, atoms.size() - 1);
  for (int k = 0; k < 100; ++k) {
    Expr p = 1;
    for (int f = 0; f < 3; ++f) p *= atoms[pick(rng)] + atoms[pick(rng)] - atoms[pick(rng)];
    EXPECT_TRUE(is_expanded(GiNaC::pow(p, 2).expand())) << p;
  }
  EXPECT_GE(expanded, 100);
  using test::m;
  using test::q1;
  using test::q2;
  const Expr s = GiNaC::sin(q1), c = GiNaC::cos(q2 + q1);
  EXPECT_TRUE(is_expanded(2 * m * s * s * c - 3 * q2 / m + GiNaC::sin(GiNaC::pow(q1 + q2, 2)) + 5));
  EXPECT_FALSE(is_expanded(m * (s + c)));
  EXPECT_FALSE(is_expanded(GiNaC::pow(s + c, 2)));
  EXPECT_FALSE(is_expanded(q1 + 1 / (s + c)));  // expand works inside a reciprocal's sum
  EXPECT_FALSE(is_expanded(GiNaC::sqrt(q1 + q2)));
}

TEST(ExpansionBudget, BoundOfPowersOfSums) {
  const GiNaC::symbol x("x"), y("y"), z("z"), w("w");
  for (int n = 1; n <= 12; ++n) {
    const Expr e = GiNaC::pow(x + y + z + w + 1, n);
    // the monomials of degree ≤ n in four symbols: C(n + 4, 4), all present
    EXPECT_DOUBLE_EQ(expanded_terms_bound(e), choose(n + 4, 4)) << n;
    EXPECT_EQ(terms(e.expand()), choose(n + 4, 4)) << n;
  }
  // (x + y + t + m + g + 1)^40: the audit's example, bounded without being expanded
  const GiNaC::symbol t("t"), m("m"), g("g");
  EXPECT_NEAR(expanded_terms_bound(GiNaC::pow(x + y + t + m + g + 1, 40)), choose(45, 5), 1.0);
  EXPECT_GT(expanded_terms_bound(GiNaC::pow(x + y + t + m + g + 1, 999999999)), 1e40);
  // sums add, products multiply, functions count once but their arguments are looked at
  EXPECT_DOUBLE_EQ(expanded_terms_bound((x + y) * (z + w + 1)), 6);
  EXPECT_DOUBLE_EQ(expanded_terms_bound(GiNaC::sin(GiNaC::pow(x + y, 30)) + 1), 31);
  EXPECT_DOUBLE_EQ(largest_power_terms(GiNaC::pow(x + y, 3) * GiNaC::pow(x + y + z, 2)), 6);
}

// normal()'s bound multiplies the denominators out: 1/(x + y + z + w + 1)^n has the C(n + 4, 4)
// monomials of its denominator; added to x/(y + 1) (over (y + 1)(x + y + z + w + 1)^n) it bounds
// the numerator and the denominator that GiNaC's normal makes. A fraction whose denominator is a
// symbol or a short sum is affordable, 1/(x + y + z + w + 1)^30 not.
TEST(ExpansionBudget, FractionBoundCountsTheDenominatorsMultipliedOut) {
  const GiNaC::symbol x("x"), y("y"), z("z"), w("w");
  for (int n = 1; n <= 6; ++n) {
    const Expr e = GiNaC::pow(x + y + z + w + 1, -n);
    EXPECT_DOUBLE_EQ(fraction_terms_bound(e), choose(n + 4, 4)) << n;
    EXPECT_DOUBLE_EQ(expanded_terms_bound(e), 5) << n;  // expand leaves it as it is
    const Expr sum = e + x / (y + 1);
    const Expr normal = GiNaC::numer_denom(sum.normal());
    EXPECT_DOUBLE_EQ(fraction_terms_bound(sum), 2 * choose(n + 4, 4)) << n;
    EXPECT_GE(fraction_terms_bound(sum), terms(normal.op(0).expand())) << n;
    EXPECT_GE(fraction_terms_bound(sum), terms(normal.op(1).expand())) << n;
  }
  EXPECT_TRUE(normal_affordable(x / (y + z) + 1 / x));
  EXPECT_TRUE(normal_affordable(GiNaC::pow(x + y + z + w + 1, 30)));  // no denominator
  EXPECT_FALSE(normal_affordable(GiNaC::pow(x + y + z + w + 1, -30)));
  EXPECT_THROW(normal_within_budget(1 / (GiNaC::pow(x + y + z + w + 1, 30) + 1), "here"),
               ExpressionTooLarge);
}

// An upper bound on every expansion of a mixed expression.
TEST(ExpansionBudget, BoundIsAnUpperBound) {
  const GiNaC::symbol x("x"), y("y"), z("z");
  const std::vector<Expr> cases = {
      (x + 1) * (x - 1),
      GiNaC::pow(x + y, 3) * GiNaC::pow(x - y, 2) + z * (x + z),
      GiNaC::pow(GiNaC::sin(x) + GiNaC::cos(x), 4) * (GiNaC::sin(x) - 2),
      GiNaC::pow(x + y, -2) * (x + y + z),
      (x + y + z) * (x + y + z) * (x - z),
  };
  for (const Expr& e : cases) EXPECT_GE(expanded_terms_bound(e), terms(e.expand())) << e;
}

// Where the bound is loose (like terms combine), the checked expansion decides and equals
// GiNaC's: seven eight-term sums of the same seven symbols bound 8^7 terms; their product has the
// C(14, 7) monomials of degree ≤ 7 in seven symbols.
TEST(ExpansionBudget, CheckedExpansionEqualsGinacs) {
  std::vector<GiNaC::symbol> a(7);
  Expr sum = 0;
  for (const auto& s : a) sum += s;
  Expr product = 1;
  for (int k = 1; k <= 7; ++k) product *= sum + k;
  const Expr e = GiNaC::mul(product, GiNaC::sin(a[0]) + 2);
  ASSERT_GT(expanded_terms_bound(e), kMaxExpandedTerms);
  const Expr expanded = expand_within_budget(e, "test");
  EXPECT_EQ(terms(expanded), 2 * choose(14, 7));
  EXPECT_TRUE((expanded - e.expand()).expand().is_zero());
  EXPECT_NO_THROW(check_expansion_budget(e, "test"));
}

// Past the budget: refused at once, saying what was being done.
TEST(ExpansionBudget, PastTheBudgetIsRefusedQuickly) {
  const GiNaC::symbol x("x"), y("y"), t("t"), m("m"), g("g");
  const auto start = std::chrono::steady_clock::now();
  const Expr huge = GiNaC::pow(x + y + t + m + g + 1, 200) * y;
  try {
    (void)expand_within_budget(huge, "simplifying");
    ADD_FAILURE() << "no error";
  } catch (const ExpressionTooLarge& e) {
    EXPECT_NE(std::string(e.what()).find("simplifying"), std::string::npos) << e.what();
  }
  // a product of two expanded sums whose terms do not combine
  Expr p = 0, q = 0;
  for (int k = 0; k < 1100; ++k) {
    p += GiNaC::pow(x, k);
    q += GiNaC::pow(y, k);
  }
  EXPECT_THROW((void)expand_within_budget(p * q, "test"), ExpressionTooLarge);
  EXPECT_THROW((void)normal_within_budget(p * q, "test"), ExpressionTooLarge);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
}

}  // namespace
}  // namespace unidyn
