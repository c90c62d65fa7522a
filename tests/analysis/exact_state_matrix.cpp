// ẋ = A x in closed form for constrained systems (analysis/exact_state_matrix.hpp): the upright
// rolling disk (§10.7; its critical spin φ̇² = g/(3R)), the spring chain with its plane
// constraints (§5.2), the satellite's relative equilibrium (Ex. 9.9, Euler parameters); each the
// numeric linearisation's A at the parameters' values, and left numeric where it cannot be exact.
#include "unidyn/analysis/exact_state_matrix.hpp"

#include <gtest/gtest.h>

#include "support/model_run.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

struct Exact {
  System system;
  EquationsOfMotion equations;
  std::vector<GivenValue> given;
  OperatingPoint point;
  Linearization linearization;
  std::optional<ExprMatrix> A;
  Exact(const std::string& model, const std::vector<std::string>& at)
      : system(load_model(test::model_path(model))), equations(lagrange_equations(system)) {
    const CompiledSystem compiled(system, equations);
    given = parse_given_values(system, at);
    point = operating_point(system, compiled, given, initial_state(system, {}).parameters);
    linearization = linearize(system, compiled, point);
    A = exact_state_matrix(system, equations, given, point, linearization);
  }
  Expr parameter(const std::string& name) const {
    return system.parameters[*system.find_parameter(name)].symbol;
  }
  // |A − the numeric A| at the parameters' values, relative to the largest entry.
  double numeric_difference() const {
    const GiNaC::exmap values = system.parameter_values();
    const double scale = std::max(1.0, linearization.A.cwiseAbs().maxCoeff());
    double most = 0.0;
    for (std::size_t i = 0; i < A->rows; ++i) {
      for (std::size_t j = 0; j < A->cols; ++j) {
        const auto v = real_value((*A)(i, j), values);
        if (!v) return INFINITY;
        const auto ii = static_cast<Eigen::Index>(i), jj = static_cast<Eigen::Index>(j);
        most = std::max(most, std::abs(*v - linearization.A(ii, jj)) / scale);
      }
    }
    return most;
  }
};

::testing::AssertionResult equal(const Expr& a, const Expr& b) {
  if (GiNaC::normal(GiNaC::expand(a - b)).is_zero()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " is not " << b;
}

// Upright, spinning at φ̇ = 10 (state θ, ψ̇, θ̇, φ̇): θ̈ = (4g/5R) θ − (6/5) φ̇ ψ̇, ψ̈ = 2 φ̇ θ̇, φ̈ = 0,
// so λ² = 4g/(5R) − (12/5) φ̇² = (12/5)(g/(3R) − φ̇²): the lean is stable above the critical spin.
// The numeric A has round-off where these have 0 (cos(π/2) = 6e-17).
TEST(ExactStateMatrix, UprightRollingDisk) {
  const Exact disk("rolling-disk", {"theta=pi/2", "der(phi)=10", "der(psi)=0", "der(theta)=0"});
  ASSERT_TRUE(disk.A.has_value());
  ASSERT_EQ(disk.linearization.state,
            (std::vector<std::string>{"theta", "der(psi)", "der(theta)", "der(phi)"}));
  const Expr g = disk.parameter("g"), R = disk.parameter("R");
  const ExprMatrix& A = *disk.A;
  EXPECT_TRUE(equal(A(0, 2), 1));
  EXPECT_TRUE(equal(A(1, 2), 20));
  EXPECT_TRUE(equal(A(2, 0), 4 * g / (5 * R)));
  EXPECT_TRUE(equal(A(2, 1), -12));
  EXPECT_TRUE(equal(A(2, 0) + A(2, 1) * A(1, 2), GiNaC::numeric(12, 5) * (g / (3 * R) - 100)));
  for (const std::size_t j : {0u, 1u, 2u, 3u}) EXPECT_TRUE(equal(A(3, j), 0)) << j;
  EXPECT_LT(disk.numeric_difference(), 1e-13);
}

// Two masses between springs along E1, their other coordinates held by plane constraints:
// m1 x1'' = −(K1 + K2) x1 + K2 x2, m2 x2'' = K2 x1 − K2 x2 (5.1)–(5.2).
TEST(ExactStateMatrix, SpringChainWithItsPlaneConstraints) {
  const Exact chain("spring-chain", {"x1=0", "x2=0"});
  ASSERT_TRUE(chain.A.has_value());
  const Expr K1 = chain.parameter("K1"), K2 = chain.parameter("K2"), m1 = chain.parameter("m1"),
             m2 = chain.parameter("m2");
  const ExprMatrix& A = *chain.A;
  EXPECT_TRUE(equal(A(2, 0), -(K1 + K2) / m1));
  EXPECT_TRUE(equal(A(2, 1), K2 / m1));
  EXPECT_TRUE(equal(A(3, 0), K2 / m2));
  EXPECT_TRUE(equal(A(3, 1), -K2 / m2));
  EXPECT_LT(chain.numeric_difference(), 1e-13);
}

// The satellite's relative equilibrium with its principal axes on the orbiting frame's (e0 = 1):
// the entries the numeric linearisation gives, now as expressions in the inertias and GM.
TEST(ExactStateMatrix, SatelliteRelativeEquilibriumAgreesWithTheNumericOne) {
  const Exact satellite("satellite-relative-equilibria", {"e0=1"});
  ASSERT_TRUE(satellite.A.has_value());
  EXPECT_LT(satellite.numeric_difference(), 1e-12);
}

// Not in closed form: the bicycle (13 unknowns in its saddle-point system: elimination with
// symbols takes minutes), whose A stays numeric.
TEST(ExactStateMatrix, LeftNumericWhereTooLarge) {
  EXPECT_FALSE(Exact("bicycle", {"der(thR)=v/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"})
                   .A.has_value());
}

}  // namespace
}  // namespace unidyn
