// The degrees in several symbols at once (symbolic/polynomial_degrees.hpp) against GiNaC's
// is_polynomial and degree, one symbol at a time.
#include <gtest/gtest.h>

#include <random>

#include "unidyn/symbolic/polynomial_degrees.hpp"

namespace unidyn {
namespace {

TEST(PolynomialDegrees, AreGiNaCsOneSymbolAtATime) {
  const GiNaC::symbol s("s"), c("c"), u("u"), m("m");
  const std::vector<Expr> xs{s, c, u};
  const std::vector<Expr> factors{s,
                                  c,
                                  u,
                                  m,
                                  GiNaC::pow(s, 2),
                                  GiNaC::pow(c, 3),
                                  GiNaC::pow(u, -1),
                                  GiNaC::sqrt(s),
                                  GiNaC::sin(u),
                                  GiNaC::pow(s + m, 2),
                                  GiNaC::pow(c + u, -2),
                                  Expr(3)};
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::size_t> pick(0, factors.size() - 1);
  std::uniform_int_distribution<int> count(1, 4);
  int polynomial = 0, not_polynomial = 0;
  for (int k = 0; k < 300; ++k) {
    // a sum of up to four products of up to four factors
    Expr p = 0;
    for (int t = count(rng); t > 0; --t) {
      Expr term = 1;
      for (int f = count(rng); f > 0; --f) term *= factors[pick(rng)];
      p += term;
    }
    const auto degrees = polynomial_degrees(p, xs);
    for (std::size_t i = 0; i < xs.size(); ++i) {
      const GiNaC::symbol& x = GiNaC::ex_to<GiNaC::symbol>(xs[i]);
      if (p.is_polynomial(x)) {
        ++polynomial;
        ASSERT_TRUE(degrees[i].has_value()) << p << " in " << x;
        EXPECT_EQ(*degrees[i], p.degree(x)) << p << " in " << x;
      } else {
        ++not_polynomial;
        EXPECT_FALSE(degrees[i].has_value()) << p << " in " << x;
      }
    }
  }
  // (both kinds met)
  EXPECT_GT(polynomial, 100);
  EXPECT_GT(not_polynomial, 100);
}

}  // namespace
}  // namespace unidyn
