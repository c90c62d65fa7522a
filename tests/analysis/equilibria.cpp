// Equilibria by multi-start Newton (analysis/equilibria.hpp) against closed forms: the bead on the
// rotating hoop (Ex. 3.7) on both sides of its bifurcation, the double pendulum's four, the spring
// chain's four; steady motions with cyclic coordinates: the circular orbit on the smooth cone
// (Fig. 2.9), the heavy top's steady precession at given rates and at given momenta (Routh's
// amended potential), the rolling disk circling (checked by simulating it).
#include "unidyn/analysis/equilibria.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

std::vector<Equilibrium> equilibria(const std::string& model, const std::vector<std::string>& at,
                                    const std::vector<std::pair<std::string, double>>& set = {},
                                    const std::vector<std::string>& cyclic = {}) {
  const System system = load_model(test::model_path(model));
  const CompiledSystem compiled(system, lagrange_equations(system));
  return find_equilibria(system, compiled, parse_given_values(system, at, !cyclic.empty()),
                         initial_state(system, set).parameters, {.cyclic = cyclic})
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
// or e2 (intermediate), either way up, 8 in all, ψ ignorable, each with ω along a principal axis
// (Ex. 9.12); about e1 the 3-2-1 angles are at gimbal lock (θ = ±π/2), and those are counted as
// left out, not dropped in silence.
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
    // Ex. 9.12: Euler's equations with ω̇ = 0 leave ω × Jω = 0, ω along a principal axis. ω from the
    // 3-2-1 rates, ψ̇ E3 + θ̇ R3(ψ)E2 + φ̇ Q E1 with Q = R3(ψ)R2(θ)R1(φ), in the body's components
    const Eigen::VectorXd& q = e.point.q;
    const Eigen::VectorXd& rate = e.point.qdot;
    const Eigen::Matrix3d R3 = Eigen::AngleAxisd(q[0], Eigen::Vector3d::UnitZ()).toRotationMatrix();
    const Eigen::Matrix3d Q = R3 * Eigen::AngleAxisd(q[1], Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(q[2], Eigen::Vector3d::UnitX());
    const Eigen::Vector3d omega = rate[0] * Eigen::Vector3d::UnitZ() +
                                  rate[1] * R3 * Eigen::Vector3d::UnitY() +
                                  rate[2] * Q * Eigen::Vector3d::UnitX();
    const Eigen::Vector3d w = Q.transpose() * omega;
    const Eigen::Vector3d Jw(2.0 * w[0], 4.0 * w[1], 5.0 * w[2]);  // λ = (2, 4, 5)
    EXPECT_NEAR(w.norm(), 5.0, 1e-9);
    EXPECT_LT(w.cross(Jw).norm(), 1e-9) << "ω = " << w.transpose() << " is no principal axis";
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

namespace unidyn {
namespace {

// The largest |Im λ| of a linearisation's modes: its fastest oscillation.
double fastest_frequency(const Equilibrium& e) {
  double most = 0.0;
  for (const Mode& mode : e.modes.modes) most = std::max(most, std::abs(mode.eigenvalue.imag()));
  return most;
}

// Fig. 2.9 (dimensionless, α = 20°, h = 5, ω² = 10): at the momentum p(θ) = h the circular orbit
// w0 solves h²/(w0³ cos²α) − ω²(w0 − 1) − sin α = 0 (2.22): 1.6252669 (the figure's 1.58896 drops
// the cos²α), its rate h/(w0² cos²α); the orbit is stable (the amended potential's minimum) and
// oscillates at ω_r² = 3h²/(w0⁴ cos²α) + ω² ≈ 22.17 (the derivative of (2.22)'s right side).
TEST(Equilibria, SmoothConesCircularOrbitOfFigure2_9) {
  const double alpha = std::numbers::pi / 9, h = 5, omega2 = 10, c2 = std::pow(std::cos(alpha), 2);
  const auto found = equilibria("smooth-cone", {"p(theta)=h"}, {}, {"theta"});
  // R > 0 (R < 0 is the cone's other nappe, below O)
  ASSERT_EQ(found.size(), 2u);
  const Equilibrium& e = found[1];
  const double w0 = e.point.q[0];
  EXPECT_NEAR(h * h / (w0 * w0 * w0 * c2) - omega2 * (w0 - 1) - std::sin(alpha), 0.0, 1e-12);
  EXPECT_NEAR(w0, 1.6252669, 1e-7);
  EXPECT_NEAR(e.point.q[2], std::numbers::pi / 2 - alpha, 1e-14);
  EXPECT_NEAR(e.point.qdot[1], h / (w0 * w0 * c2), 1e-12);
  const double frequency2 = 3 * h * h / (std::pow(w0, 4) * c2) + omega2;
  EXPECT_NEAR(frequency2, 22.17, 0.005);
  EXPECT_NEAR(std::pow(fastest_frequency(e), 2), frequency2, 1e-9 * frequency2);
  EXPECT_EQ(e.modes.verdict, Stability::linearly_stable) << e.modes.reason;
  EXPECT_TRUE(e.amended);
  EXPECT_TRUE(e.potential_minimum.value_or(false));
}

// The heavy top (3-1-3 angles, A_O = A + m l² about O): steady precession at rates ψ̇, φ̇ has
// A_O ψ̇² cos θ − C ω3 ψ̇ + m g l = 0 with ω3 = φ̇ + ψ̇ cos θ, so cos θ = (C φ̇ ψ̇ − m g l) /
// ((A_O − C) ψ̇²). At momenta p_ψ, p_φ instead, Routh's amended potential
//   V(θ) = m g l cos θ + (p_ψ − p_φ cos θ)² / (2 A_O sin²θ)
// has its minimum there, and the nutation's frequency² is V''(θ)/A_O (here by differences).
TEST(Equilibria, HeavyTopsSteadyPrecessionAtRatesAndAtMomenta) {
  const double m = 1, g = 9.81, l = 0.05, A = 0.004, C = 0.002, A_O = A + m * l * l;
  const auto at_rates =
      equilibria("heavy-top", {"der(psi)=4.5", "der(phi)=60"}, {}, {"psi", "phi"});
  ASSERT_EQ(at_rates.size(), 2u);  // θ and −θ (the same motion, ψ and φ turned by π)
  const double cos_theta = (C * 60 * 4.5 - m * g * l) / ((A_O - C) * 4.5 * 4.5);
  EXPECT_NEAR(at_rates[1].point.q[1], std::acos(cos_theta), 1e-12);
  EXPECT_NEAR(at_rates[0].point.q[1], -std::acos(cos_theta), 1e-12);

  const double p_psi = 0.06, p_phi = 0.12;
  const auto at_momenta =
      equilibria("heavy-top", {"p(psi)=0.06", "p(phi)=0.12"}, {}, {"psi", "phi"});
  ASSERT_EQ(at_momenta.size(), 2u);
  const Equilibrium& e = at_momenta[1];
  const double theta = e.point.q[1];
  const auto V = [&](double x) {
    return m * g * l * std::cos(x) +
           std::pow(p_psi - p_phi * std::cos(x), 2) / (2 * A_O * std::pow(std::sin(x), 2));
  };
  const double d = 1e-4;
  EXPECT_NEAR((V(theta + d) - V(theta - d)) / (2 * d), 0.0, 1e-8);
  const double V2 = (V(theta + d) - 2 * V(theta) + V(theta - d)) / (d * d);
  EXPECT_NEAR(std::pow(fastest_frequency(e), 2), V2 / A_O, 1e-6 * V2 / A_O);
  // its rates keep the momenta: ω3 = p_φ/C, ψ̇ = (p_ψ − p_φ cos θ)/(A_O sin²θ)
  EXPECT_NEAR(e.point.qdot[2] + e.point.qdot[0] * std::cos(theta), p_phi / C, 1e-10);
  EXPECT_NEAR(e.point.qdot[0],
              (p_psi - p_phi * std::cos(theta)) / (A_O * std::pow(std::sin(theta), 2)), 1e-10);
  EXPECT_TRUE(e.amended);
  EXPECT_TRUE(e.potential_minimum.value_or(false));
  EXPECT_EQ(e.modes.verdict, Stability::linearly_stable) << e.modes.reason;
}

// The rolling disk circling (nonholonomic: its centre's rates follow from the rolling and turn
// with it): at ψ̇ = 1.5, φ̇ = 12 the lean θ that keeps it steady, checked by simulating from it:
// θ stays where it was to round-off, and ψ̇, φ̇ do too.
TEST(Equilibria, RollingDiskCirclesSteadily) {
  const auto found =
      equilibria("rolling-disk", {"der(psi)=1.5", "der(phi)=12"}, {}, {"x1", "x2", "psi", "phi"});
  ASSERT_FALSE(found.empty());
  const Equilibrium& e = found.back();  // above the plane: x3 > 0
  ASSERT_GT(e.point.q[2], 0.0);
  EXPECT_TRUE(e.linearization.velocity_constraints);
  EXPECT_FALSE(e.potential_minimum.has_value());  // no energy method with rolling
  std::vector<std::pair<std::string, double>> start;
  for (const std::string name : {"x1", "x2", "x3", "psi", "theta", "phi"}) {
    const Eigen::Index i =
        std::find(e.linearization.coordinates.begin(), e.linearization.coordinates.end(), name) -
        e.linearization.coordinates.begin();
    start.push_back({name, e.point.q[i]});
    start.push_back({"der(" + name + ")", e.point.qdot[i]});
  }
  const test::ModelRun run =
      test::run_model("rolling-disk", start, [](SimulationOptions& o) { o.t_end = 2; });
  for (std::size_t row = 0; row < run.rows.size(); ++row) {
    EXPECT_NEAR(run.at(row, "theta"), e.point.q[4], 1e-10) << run.at(row, "t");
    EXPECT_NEAR(run.at(row, "der(psi)"), 1.5, 1e-9) << run.at(row, "t");
    EXPECT_NEAR(run.at(row, "der(phi)"), 12, 1e-9) << run.at(row, "t");
  }
}

// The torque-free body with ψ cyclic (3-2-1 angles): Routh's amended potential p²/(2 M_ψψ) is
// least where M_ψψ is largest, about the major axis e3 — the 4 steady rotations there are its
// minima; about the intermediate axis e2 it has none (and they are unstable).
TEST(Equilibria, RouthsMinimaOfATorqueFreeBodyAreAboutItsMajorAxis) {
  const auto found = equilibria("torque-free-body", {"der(psi)=5"}, {}, {"psi"});
  ASSERT_EQ(found.size(), 8u);
  int minima = 0;
  for (const Equilibrium& e : found) {
    ASSERT_TRUE(e.potential_minimum.has_value());
    EXPECT_EQ(*e.potential_minimum, e.modes.verdict == Stability::linearly_stable);
    // e3 along E3, either way: θ and φ multiples of π
    const bool major = std::abs(std::remainder(e.point.q[2], std::numbers::pi)) < 1e-9;
    EXPECT_EQ(*e.potential_minimum, major) << e.point.q.transpose();
    minima += *e.potential_minimum ? 1 : 0;
  }
  EXPECT_EQ(minima, 4);
}

// The rotor pinned, its centre x, y turning with its angle ψ (ignorable): points that differ only
// along ψ — the centre anywhere on its circle — are one equilibrium; the four left are the rotor
// either way up in the pin, each with ψ any.
TEST(Equilibria, DependentCoordinatesMovingWithAnIgnorableOneAreOneEquilibrium) {
  const auto found = equilibria("unbalanced-rotor-pinned", {});
  EXPECT_EQ(found.size(), 4u);
  for (const Equilibrium& e : found) {
    EXPECT_EQ(e.linearization.ignorable, (std::vector<std::string>{"psi"}));
  }
}

// Friction is refused, not searched: stick and slip are not smooth. A contact whose coefficients
// are 0 is smooth: on the sphere (μ_d = 0), unilateral, the particle rests only on top (unstable);
// at the bottom the contact would have to pull, and is lost.
TEST(Equilibria, RoughContactsRefusedUnilateralOnesMustPush) {
  EXPECT_THROW(equilibria("block-incline", {}), std::invalid_argument);
  const auto sphere = equilibria("particle-leaving-sphere", {});
  ASSERT_EQ(sphere.size(), 1u);
  EXPECT_NEAR(sphere[0].point.q[2], 1.0, 1e-12);
  EXPECT_EQ(sphere[0].modes.verdict, Stability::unstable);
  EXPECT_THROW(equilibria("particle-leaving-sphere", {}, {{"mu_d", 0.1}}), std::invalid_argument);
}

// What cannot be asked: a momentum of a coordinate not said to be cyclic, both a rate and a
// momentum, a cyclic name that is not a coordinate.
TEST(Equilibria, CyclicInputRefusedWithItsReason) {
  EXPECT_THROW(equilibria("smooth-cone", {"p(theta)=5"}, {}, {"R"}), std::invalid_argument);
  EXPECT_THROW(equilibria("smooth-cone", {"p(theta)=5", "der(theta)=1"}, {}, {"theta"}),
               std::invalid_argument);
  EXPECT_THROW(equilibria("smooth-cone", {}, {}, {"nope"}), std::invalid_argument);
  const System system = load_model(test::model_path("smooth-cone"));
  EXPECT_THROW(parse_given_values(system, {"p(theta)=5"}), std::invalid_argument);
}

// A body hung at its pivot O (centre L0 e3) and turned by a spring from its point x̄ + e1 − L0 e3
// = e1 to 3 E1: U = m g L0 Q33 − 3 k Q11 + const, a linear function of Q whose coefficient matrix
// diag(−3k, 0, m g L0) has distinct singular values, so its critical points on SO(3) are the four
// rotations diag(±1, ±1, ±1) with det +1 — and only diag(1, −1, −1) (e1 = E1, e3 = −E3) is its
// minimum. Each is reached by two solutions of its 3-2-1 angles, (ψ, θ, φ) and
// (ψ + π, π − θ, φ + π), both away from gimbal lock (θ = 0 or π): four attitudes, listed once.
TEST(Equilibria, OneAttitudeUnderTwoEulerDescriptionsIsOneEquilibrium) {
  const System system = parse_model(
      "unidyn: 1\nparameters: {m: 1.0, g: 9.81, L0: 0.5, k: 2.0}\ncoordinates: [psi, theta, phi]\n"
      "bodies:\n  B: {mass: m, inertia: [0.1, 0.2, 0.3], rotation: {euler: 3-2-1, angles: [psi, "
      "theta, phi]}, center: L0*B.e3}\n"
      "forces:\n  - gravity: -g*E3\n"
      "  - spring: {from: {on: B, point: [1, 0, -L0]}, to: [3, 0, 0], stiffness: k}\n",
      "hung.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  const EquilibriumSearchResult result =
      find_equilibria(system, compiled, {}, initial_state(system, {}).parameters);
  ASSERT_EQ(result.equilibria.size(), 4u);
  int minima = 0;
  for (const Equilibrium& e : result.equilibria) {
    const double psi = e.point.q[0], theta = e.point.q[1], phi = e.point.q[2];
    // Q11 = cos ψ cos θ, Q33 = cos θ cos φ for 3-2-1 angles: each ±1
    EXPECT_NEAR(std::abs(std::cos(psi) * std::cos(theta)), 1.0, 1e-9);
    EXPECT_NEAR(std::abs(std::cos(theta) * std::cos(phi)), 1.0, 1e-9);
    if (e.potential_minimum.value_or(false)) {
      ++minima;
      EXPECT_NEAR(std::cos(psi) * std::cos(theta), 1.0, 1e-9);
      EXPECT_NEAR(std::cos(theta) * std::cos(phi), -1.0, 1e-9);
    }
  }
  EXPECT_EQ(minima, 1);
}

}  // namespace
}  // namespace unidyn
