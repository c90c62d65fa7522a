// Pulling out the common monomial (symbolic/common_factor.hpp).
#include "unidyn/symbolic/common_factor.hpp"

#include <gtest/gtest.h>

#include "unidyn/symbolic/canonical_text.hpp"

namespace unidyn {
namespace {

const GiNaC::realsymbol a("a"), m("m"), x("x"), th("theta");

TEST(CommonFactor, MonomialAndNumberOut) {
  // the tautochrone's 2 (m a² + m cos θ a²) = 2 m a² (1 + cos θ)
  const Expr e = 2 * (m * a * a + m * GiNaC::cos(th) * a * a);
  const Expr f = pull_common_factor(GiNaC::expand(e));
  EXPECT_EQ(canonical_text(f), "2*(1+cos(theta))*a^2*m");
  EXPECT_TRUE(GiNaC::expand(f - e).is_zero());
  // numbers: gcd of numerators over lcm of denominators
  const Expr g = pull_common_factor(m / 2 + 3 * m * x / 4);
  EXPECT_EQ(canonical_text(g), "1/4*(2+3*x)*m");
  // nothing in common, or not a sum: as it was
  EXPECT_EQ(canonical_text(pull_common_factor(m + x)), "m+x");
  EXPECT_EQ(canonical_text(pull_common_factor(3 * m * x)), "3*m*x");
  // a negative exponent is never common
  EXPECT_EQ(canonical_text(pull_common_factor(m / x + a / x)), "a*x^(-1)+m*x^(-1)");
}

}  // namespace
}  // namespace unidyn
