// The total time derivative along a motion (symbolic/coordinates.hpp, book (1.7)–(1.8)).
#include <gtest/gtest.h>

#include "unidyn/symbolic/coordinates.hpp"

namespace unidyn {
namespace {

// §1.5's example: Φ = q¹ + (q̇³)² + 10 t has Φ̇ = q̇¹ + 2 q̇³ q̈³ + 10, not its partial derivative
// ∂Φ/∂t = 10; the convective part (q̈ = 0) drops 2 q̇³ q̈³.
TEST(TotalDerivative, ExampleOfSection15) {
  Configuration config;
  for (const char* name : {"q1", "q2", "q3"}) config.add(name);
  const auto& q = config.coordinates();
  const Expr t = config.time();
  const Expr phi = q[0].value + GiNaC::pow(q[2].rate, 2) + 10 * t;
  const Expr expected = q[0].rate + 2 * q[2].rate * q[2].acceleration + 10;
  EXPECT_TRUE((config.total_derivative(phi) - expected).expand().is_zero())
      << config.total_derivative(phi);
  EXPECT_TRUE((phi.diff(GiNaC::ex_to<GiNaC::symbol>(t)) - 10).is_zero());
  EXPECT_TRUE((config.convective_derivative(q[0].value + 10 * t) - (q[0].rate + 10)).is_zero());
}

}  // namespace
}  // namespace unidyn
