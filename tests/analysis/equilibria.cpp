// Equilibria by multi-start Newton (analysis/equilibria.hpp) against closed forms: the bead on the
// rotating hoop (Ex. 3.7) on both sides of its bifurcation, the double pendulum's four, the spring
// chain's four.
#include "unidyn/analysis/equilibria.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

std::vector<Equilibrium> equilibria(const std::string& model, const std::vector<std::string>& at,
                                    const std::vector<std::pair<std::string, double>>& set = {}) {
  const System system = load_model(test::model_path(model));
  const CompiledSystem compiled(system, lagrange_equations(system));
  return find_equilibria(system, compiled, parse_given_values(system, at),
                         initial_state(system, set).parameters)
      .equilibria;
}

// φ'' = (Ω² cos φ + g/R0) sin φ: 0 and π, and ±φ* with cos φ* = −g/(R0 Ω²) when Ω² > g/R0,
// the only stable ones then (the amended potential's minima); below, π alone is stable.
TEST(Equilibria, RotatingHoopOnBothSidesOfTheBifurcation) {
  const double pi = std::numbers::pi, g = 9.81, R0 = 0.5, Omega = 6.264183905346329;
  const auto fast = equilibria("rotating-hoop", {});
  ASSERT_EQ(fast.size(), 4u);
  const double star = std::acos(-g / (R0 * Omega * Omega));
  const double expected[] = {-star, 0.0, star, pi};
  const Stability verdicts[] = {Stability::linearly_stable, Stability::unstable,
                                Stability::linearly_stable, Stability::unstable};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(fast[k].point.q[0], expected[k], 1e-10) << k;
    EXPECT_EQ(fast[k].modes.verdict, verdicts[k]) << k << ": " << fast[k].modes.reason;
    ASSERT_TRUE(fast[k].potential_minimum.has_value());
    EXPECT_EQ(*fast[k].potential_minimum, verdicts[k] == Stability::linearly_stable);
  }
  const auto slow = equilibria("rotating-hoop", {}, {{"Omega", 3.0}});
  ASSERT_EQ(slow.size(), 2u);
  EXPECT_NEAR(slow[0].point.q[0], 0.0, 1e-10);
  EXPECT_EQ(slow[0].modes.verdict, Stability::unstable);
  EXPECT_NEAR(slow[1].point.q[0], pi, 1e-10);
  EXPECT_TRUE(slow[1].potential_minimum.value_or(false));
}

// Hanging, upside down, and the two mixed ones; only hanging is a minimum of U.
TEST(Equilibria, DoublePendulumHasFour) {
  const double pi = std::numbers::pi;
  const auto found = equilibria("double-pendulum", {});
  ASSERT_EQ(found.size(), 4u);
  int stable = 0;
  for (const Equilibrium& e : found) {
    for (const double angle : {e.point.q[0], e.point.q[1]}) {
      EXPECT_LT(std::min(std::abs(angle), std::abs(std::abs(angle) - pi)), 1e-10) << angle;
    }
    if (e.potential_minimum.value_or(false)) {
      ++stable;
      EXPECT_LT(std::abs(e.point.q[0]) + std::abs(e.point.q[1]), 1e-10);
      EXPECT_EQ(e.modes.verdict, Stability::linearly_stable);
    } else {
      EXPECT_EQ(e.modes.verdict, Stability::unstable);
    }
  }
  EXPECT_EQ(stable, 1);
  // a coordinate held: θ1 = 0 leaves θ2 = 0 or π
  EXPECT_EQ(equilibria("double-pendulum", {"theta1=0"}).size(), 2u);
}

// The spring chain in its line: each spring at its rest length L = 1 on either side of the point it
// hangs from (the one from the origin to P1 = (1 + x1, 0, 0) is at rest at x1 = 0 and x1 = −2), so
// four equilibria, x1 ∈ {0, −2}, x2 − x1 ∈ {0, −2}, all minima of the springs' energy with the same
// frequencies; the plane constraints hold the weight.
TEST(Equilibria, SpringChainHasFour) {
  const auto found = equilibria("spring-chain", {});
  ASSERT_EQ(found.size(), 4u);
  const double expected[4][2] = {{-2, -4}, {-2, -2}, {0, -2}, {0, 0}};
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_NEAR(found[k].point.q[0], expected[k][0], 1e-10);
    EXPECT_NEAR(found[k].point.q[1], expected[k][1], 1e-10);
    EXPECT_LT(found[k].point.q.tail(4).cwiseAbs().maxCoeff(), 1e-10);  // y1, y2, z1, z2
    EXPECT_TRUE(found[k].potential_minimum.value_or(false));
  }
}

// Steady rotation at 5 rad/s about E3 of the torque-free body (3-2-1 angles): about e3 (major axis)
// or e2 (intermediate), either way up, 8 in all, ψ ignorable; about e1 the 3-2-1 angles are at
// gimbal lock (θ = ±π/2), and those are counted as left out, not dropped in silence.
TEST(Equilibria, SteadyRotationsOfATorqueFreeBody) {
  const System system = load_model(test::model_path("torque-free-body"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const EquilibriumSearchResult result =
      find_equilibria(system, compiled, parse_given_values(system, {"der(psi)=5"}),
                      initial_state(system, {}).parameters);
  ASSERT_EQ(result.equilibria.size(), 8u);
  int stable = 0;
  for (const Equilibrium& e : result.equilibria) {
    EXPECT_EQ(e.linearization.ignorable, (std::vector<std::string>{"psi"}));
    stable += e.modes.verdict == Stability::linearly_stable ? 1 : 0;
  }
  EXPECT_EQ(stable, 4);  // about the major axis, e3
  EXPECT_GT(result.singular, 0u);
}

// The knife-edge car at rest, no force on it: every heading is an equilibrium, and each one found
// says it lies on a 1-dimensional continuum (its position ignorable); the hoop's are isolated. The
// Kepler problem at rest has none: gravitation only fades far away, and Newton's steps grow there.
TEST(Equilibria, ContinuaSaidAndInfinityRefused) {
  const auto car = equilibria("chaplygin-car", {});
  ASSERT_FALSE(car.empty());
  for (const Equilibrium& e : car) EXPECT_EQ(e.continuum, 1u);
  for (const Equilibrium& e : equilibria("rotating-hoop", {})) EXPECT_EQ(e.continuum, 0u);
  EXPECT_TRUE(equilibria("kepler", {}).empty());
}

// Ex. 9.9(e), Lagrange's 24 relative equilibria of a satellite on a circular orbit (its attitude
// relative to the orbiting frame by Euler parameters, e and −e one rotation): each with its
// principal axes along the radial, along-track and normal directions — the rotation a signed
// permutation, all 24 different — and stable exactly where the least-inertia axis e1 is radial and
// the most-inertia axis e3 normal to the orbit (4 of them, Lagrange–Dirichlet); the others
// unstable.
TEST(Equilibria, SatellitesTwentyFourRelativeEquilibria) {
  const auto found = equilibria("satellite-relative-equilibria", {});
  ASSERT_EQ(found.size(), 24u);
  std::vector<Eigen::Matrix3d> rotations;
  int stable = 0;
  for (const Equilibrium& e : found) {
    const double e0 = e.point.q[0];
    const Eigen::Vector3d v(e.point.q[1], e.point.q[2], e.point.q[3]);
    Eigen::Matrix3d skew;
    skew << 0, -v[2], v[1], v[2], 0, -v[0], -v[1], v[0], 0;
    // (6.47) the rotation of Euler parameters
    const Eigen::Matrix3d R =
        (e0 * e0 - v.dot(v)) * Eigen::Matrix3d::Identity() + 2 * v * v.transpose() + 2 * e0 * skew;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        EXPECT_LT(std::min(std::abs(R(i, j)), std::abs(std::abs(R(i, j)) - 1)), 1e-8) << R;
      }
    }
    for (const Eigen::Matrix3d& other : rotations) EXPECT_GT((R - other).norm(), 1e-3);
    rotations.push_back(R);
    const bool lagrange =
        std::abs(std::abs(R(0, 0)) - 1) < 1e-8 && std::abs(std::abs(R(2, 2)) - 1) < 1e-8;
    if (e.modes.verdict == Stability::linearly_stable) {
      ++stable;
      EXPECT_TRUE(lagrange) << R;
      EXPECT_TRUE(e.potential_minimum.value_or(false));
    } else {
      EXPECT_EQ(e.modes.verdict, Stability::unstable);
      EXPECT_FALSE(lagrange) << R;
    }
  }
  EXPECT_EQ(stable, 4);
}

}  // namespace
}  // namespace unidyn
