// Linearisation about an operating point (analysis/linearization.hpp) against closed forms and the
// bicycle benchmark.
#include "unidyn/analysis/linearization.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/bicycle_benchmark.hpp"
#include "support/linearized_model.hpp"

namespace unidyn {
namespace {

using test::LinearizedModel;

::testing::AssertionResult near(double a, double b, double relative = 1e-12) {
  if (std::abs(a - b) <= relative * (1.0 + std::abs(b))) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs " << b << " (difference " << a - b << ")";
}

// The double pendulum (Ex. 4.1, absolute angles) hanging down: T = ½ (m1 + m2) l1² θ1'² +
// m2 l1 l2 cos(θ1 − θ2) θ1' θ2' + ½ m2 l2² θ2'², U = −(m1 + m2) g l1 cos θ1 − m2 g l2 cos θ2, so
// M = [(m1 + m2) l1², m2 l1 l2; m2 l1 l2, m2 l2²], C = 0, K = diag((m1 + m2) g l1, m2 g l2).
TEST(Linearization, DoublePendulumHasTheTextbookMassAndStiffness) {
  const double m1 = 1.5, m2 = 0.7, l1 = 1.2, l2 = 0.8, g = 9.81;
  const LinearizedModel p("double-pendulum", {"theta1=0", "theta2=0"},
                          {{"m1", m1}, {"m2", m2}, {"l1", l1}, {"l2", l2}});
  ASSERT_TRUE(p.linearization.second_order.has_value());
  const SecondOrderForm& f = *p.linearization.second_order;
  EXPECT_TRUE(near(f.M(0, 0), (m1 + m2) * l1 * l1));
  EXPECT_TRUE(near(f.M(0, 1), m2 * l1 * l2));
  EXPECT_TRUE(near(f.M(1, 0), m2 * l1 * l2));
  EXPECT_TRUE(near(f.M(1, 1), m2 * l2 * l2));
  EXPECT_LT(f.C.cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_TRUE(near(f.K(0, 0), (m1 + m2) * g * l1));
  EXPECT_TRUE(near(f.K(1, 1), m2 * g * l2));
  EXPECT_LT(std::abs(f.K(0, 1)) + std::abs(f.K(1, 0)), 1e-12);
  // the state (θ1, θ2, θ1', θ2'): ẋ = [0 I; −M⁻¹K 0]
  EXPECT_EQ(p.linearization.state,
            (std::vector<std::string>{"theta1", "theta2", "der(theta1)", "der(theta2)"}));
  const Eigen::MatrixXd MK = -f.M.inverse() * f.K;
  EXPECT_LT((p.linearization.A.bottomLeftCorner(2, 2) - MK).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((p.linearization.A.topRightCorner(2, 2) - Eigen::Matrix2d::Identity()).norm(),
            0.0 + 1e-15);
}

// The bead on the rotating hoop (Ex. 3.7, (3.25)): φ'' = (Ω² cos φ + g/R0) sin φ, so about an
// equilibrium δφ'' = k δφ with k = −Ω² sin² φ + (Ω² cos φ + g/R0) cos φ: Ω² + g/R0 at the top,
// Ω² − g/R0 at the bottom, −Ω² sin² φ* at cos φ* = −g/(R0 Ω²) (when Ω² > g/R0). The model's
// position turns with the hoop, Ω t: the equations do not change with t all the same.
TEST(Linearization, RotatingHoopOnBothSidesOfTheBifurcation) {
  const double g = 9.81, R0 = 0.5;
  for (const double Omega : {6.264183905346329, 3.0}) {
    const double w2 = Omega * Omega, gR = g / R0;
    const auto k = [&](const std::string& phi) {
      const LinearizedModel hoop("rotating-hoop", {"phi=" + phi}, {{"Omega", Omega}});
      EXPECT_EQ(hoop.linearization.state, (std::vector<std::string>{"phi", "der(phi)"}));
      EXPECT_EQ(hoop.linearization.A(0, 1), 1.0);
      return hoop.linearization.A(1, 0);
    };
    EXPECT_TRUE(near(k("0"), w2 + gR));
    EXPECT_TRUE(near(k("pi"), w2 - gR));
    if (w2 > gR) {
      const double phi = std::acos(-gR / w2);
      EXPECT_TRUE(near(k("acos(-g/(R0*Omega^2))"), -w2 * std::sin(phi) * std::sin(phi)));
    }
  }
}

// The spring chain (§5.2) held in its line by four position constraints: the dependent coordinates
// are y1, y2, z1, z2, and (x1, x2) oscillate with M = diag(m1, m2), K = [K1 + K2, −K2; −K2, K2]:
// ω² = (35 ± √825)/4 for the model's m1 = 1, m2 = 2, K1 = 10, K2 = 5.
TEST(Linearization, SpringChainKeepsItsConstraints) {
  const LinearizedModel chain("spring-chain", {"x1=0", "x2=0"});
  EXPECT_EQ(chain.linearization.dependent_coordinates,
            (std::vector<std::string>{"y1", "y2", "z1", "z2"}));
  EXPECT_EQ(chain.linearization.state,
            (std::vector<std::string>{"x1", "x2", "der(x1)", "der(x2)"}));
  const auto lambda = test::sorted_eigenvalues(chain.linearization.A);
  ASSERT_EQ(lambda.size(), 4u);
  const double high = std::sqrt((35 + std::sqrt(825.0)) / 4),
               low = std::sqrt((35 - std::sqrt(825.0)) / 4);
  std::vector<double> frequencies;
  for (const auto& l : lambda) {
    EXPECT_LT(std::abs(l.real()), 1e-12);
    frequencies.push_back(std::abs(l.imag()));
  }
  std::sort(frequencies.begin(), frequencies.end());
  EXPECT_TRUE(near(frequencies[0], low));
  EXPECT_TRUE(near(frequencies[1], low));
  EXPECT_TRUE(near(frequencies[2], high));
  EXPECT_TRUE(near(frequencies[3], high));
}

// The Whipple–Carvallo bicycle upright and straight at speed v: eight coordinates, one holonomic
// and four rolling constraints. Its position, heading and wheel angles drop out; its eigenvalues
// are the benchmark's (Meijaard et al. 2007: (A1)–(A4), their Table 2), and one more is 0: the
// neighbouring steady motions at other speeds.
TEST(Linearization, BicycleEigenvaluesAreTheBenchmarks) {
  for (const double v :
       {0.0, 1.0, 2.0, test::kWeaveSpeed, 4.6, 5.0, test::kCapsizeSpeed, 8.0, 10.0}) {
    const LinearizedModel bike(
        "bicycle", {"der(thR)=" + std::to_string(v / test::kBenchmarkRearRadius), "der(phi)=0",
                    "der(delta)=0", "der(psi)=0"});
    std::vector<std::string> ignorable = bike.linearization.ignorable;
    std::sort(ignorable.begin(), ignorable.end());
    EXPECT_EQ(ignorable, (std::vector<std::string>{"psi", "thF", "thR", "x", "y"}));
    EXPECT_EQ(bike.linearization.dependent_coordinates, (std::vector<std::string>{"theta"}));
    std::vector<std::complex<double>> ours = test::sorted_eigenvalues(bike.linearization.A);
    const double speed =
        std::stod(std::to_string(v / test::kBenchmarkRearRadius)) * test::kBenchmarkRearRadius;
    for (const auto& theirs : test::sorted_eigenvalues(test::benchmark_state_matrix(speed))) {
      const auto nearest = std::min_element(ours.begin(), ours.end(), [&](auto a, auto b) {
        return std::abs(a - theirs) < std::abs(b - theirs);
      });
      ASSERT_NE(nearest, ours.end());
      EXPECT_LT(std::abs(*nearest - theirs), 1e-10 * (1 + std::abs(theirs)))
          << "v = " << v << ": " << *nearest << " vs the benchmark's " << theirs;
      ours.erase(nearest);
    }
    for (const auto& rest : ours) EXPECT_LT(std::abs(rest), 1e-9) << "v = " << v;
  }
}

// A state that moves is refused, saying what moves.
TEST(Linearization, PointsThatMoveAreRefused) {
  try {
    LinearizedModel("double-pendulum", {"theta1=0.3"});
    ADD_FAILURE() << "a tilted pendulum at rest is no equilibrium";
  } catch (const NotAnOperatingPoint& e) {
    EXPECT_NE(std::string(e.what()).find("the acceleration of theta1"), std::string::npos)
        << e.what();
  }
  try {
    LinearizedModel("double-pendulum", {"theta1=0", "theta2=0", "der(theta2)=1"});
    ADD_FAILURE() << "a swinging pendulum is no equilibrium";
  } catch (const NotAnOperatingPoint& e) {
    EXPECT_NE(std::string(e.what()).find("der(theta2) = 1"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unidyn
