// Validation of models/double-pendulum.yaml (Exercise 4.1(d), the planar double pendulum; §5 (5.19)
// in the notes): its small oscillations against the normal modes of the linearised equations, its
// energy, and an independent integration of the textbook equations written here; and Exercise
// 5.4's three constraints on the representative point, with (e)'s non-integrable fourth.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <string>
#include <utility>

#include "support/eigen_solvers.hpp"
#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::record;

struct Parameters {
  double m1, m2, l1, l2, g;
};

// The model's defaults.
constexpr Parameters kDefault{1.0, 1.0, 1.0, 1.0, 9.81};

// θ1, θ2 measured from the downward vertical (P1 = l1 (sinθ1, −cosθ1)). Linearised about θ = 0:
// M θ̈ + K θ = 0 with M = [[(m1+m2) l1², m2 l1 l2], [m2 l1 l2, m2 l2²]], K = diag((m1+m2) g l1, m2 g
// l2).
Eigen::Matrix2d linear_mass(const Parameters& p) {
  Eigen::Matrix2d M;
  M << (p.m1 + p.m2) * p.l1 * p.l1, p.m2 * p.l1 * p.l2, p.m2 * p.l1 * p.l2, p.m2 * p.l2 * p.l2;
  return M;
}

Eigen::Matrix2d linear_stiffness(const Parameters& p) {
  Eigen::Matrix2d K;
  K << (p.m1 + p.m2) * p.g * p.l1, 0.0, 0.0, p.m2 * p.g * p.l2;
  return K;
}

// E = T + U of the double pendulum.
double energy(const Parameters& p, double t1, double t2, double w1, double w2, double* scale) {
  const double T = 0.5 * (p.m1 + p.m2) * p.l1 * p.l1 * w1 * w1 +
                   0.5 * p.m2 * p.l2 * p.l2 * w2 * w2 +
                   p.m2 * p.l1 * p.l2 * w1 * w2 * std::cos(t1 - t2);
  const double U = -(p.m1 + p.m2) * p.g * p.l1 * std::cos(t1) - p.m2 * p.g * p.l2 * std::cos(t2);
  if (scale) *scale = T + std::abs(U);
  return T + U;
}

// The textbook equations of the double pendulum (angles from the vertical):
//   (m1+m2) l1 θ̈1 + m2 l2 θ̈2 cos(θ1−θ2) + m2 l2 θ̇2² sin(θ1−θ2) + (m1+m2) g sinθ1 = 0
//   l2 θ̈2 + l1 θ̈1 cos(θ1−θ2) − l1 θ̇1² sin(θ1−θ2) + g sinθ2 = 0
using State = std::array<double, 4>;  // θ1, θ2, θ̇1, θ̇2

State textbook_rate(const Parameters& p, const State& y) {
  const double d = y[0] - y[1], c = std::cos(d), s = std::sin(d);
  const double a11 = (p.m1 + p.m2) * p.l1, a12 = p.m2 * p.l2 * c;
  const double a21 = p.l1 * c, a22 = p.l2;
  const double b1 = -p.m2 * p.l2 * y[3] * y[3] * s - (p.m1 + p.m2) * p.g * std::sin(y[0]);
  const double b2 = p.l1 * y[2] * y[2] * s - p.g * std::sin(y[1]);
  const double det = a11 * a22 - a12 * a21;
  return {y[2], y[3], (b1 * a22 - a12 * b2) / det, (a11 * b2 - a21 * b1) / det};
}

// Classical RK4 with n steps from 0 to t.
State textbook_rk4(const Parameters& p, State y, double t, int n) {
  const double h = t / n;
  const auto axpy = [](const State& a, double k, const State& b) {
    return State{a[0] + k * b[0], a[1] + k * b[1], a[2] + k * b[2], a[3] + k * b[3]};
  };
  for (int i = 0; i < n; ++i) {
    const State k1 = textbook_rate(p, y);
    const State k2 = textbook_rate(p, axpy(y, h / 2, k1));
    const State k3 = textbook_rate(p, axpy(y, h / 2, k2));
    const State k4 = textbook_rate(p, axpy(y, h, k3));
    for (std::size_t j = 0; j < 4; ++j) y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y;
}

// Runs the model from θ = amplitude · shape at rest, and returns the largest deviation of (θ1, θ2)
// from amplitude · shape · cos ωt, relative to the amplitude of θ1.
double deviation_from_mode(const std::vector<std::pair<std::string, double>>& parameters,
                           const Eigen::Vector2d& shape, double omega, double amplitude,
                           double t_end) {
  auto overrides = parameters;
  overrides.insert(overrides.end(), {{"theta1", amplitude * shape[0]},
                                     {"theta2", amplitude * shape[1]},
                                     {"der(theta1)", 0.0},
                                     {"der(theta2)", 0.0}});
  const auto run = test::run_model("double-pendulum", overrides,
                                   [&](SimulationOptions& options) { options.t_end = t_end; });
  EXPECT_TRUE(run.summary.ok) << run.summary.message;
  double worst = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double c = std::cos(omega * run.at(i, "t"));
    worst = std::max({worst, std::abs(run.at(i, "theta1") - amplitude * shape[0] * c),
                      std::abs(run.at(i, "theta2") - amplitude * shape[1] * c)});
  }
  return worst / std::abs(amplitude * shape[0]);
}

// The tests below assume the model file's parameter values.
TEST(DoublePendulum, ModelFileParameters) {
  const System system = load_model(test::model_path("double-pendulum"));
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  EXPECT_EQ(value("m1"), kDefault.m1);
  EXPECT_EQ(value("m2"), kDefault.m2);
  EXPECT_EQ(value("l1"), kDefault.l1);
  EXPECT_EQ(value("l2"), kDefault.l2);
  EXPECT_EQ(value("g"), kDefault.g);
}

// Normal modes of the linearised (5.19) for m1 = m2, l1 = l2 = l: ω² = (g/l)(2 ∓ √2) with
// θ2/θ1 = ±√2; at amplitude 1e-4 the motion in each mode is θ = A shape cos ωt.
TEST(DoublePendulum, NormalModesOfTheSymmetricPendulum) {
  const double g = kDefault.g, l = kDefault.l1;
  const double slow = std::sqrt(g / l * (2.0 - std::sqrt(2.0)));
  const double fast = std::sqrt(g / l * (2.0 + std::sqrt(2.0)));
  // the closed form is the linearisation's: det(K − ω² M) = 0 and (K − ω² M) shape = 0
  const Eigen::Matrix2d M = linear_mass(kDefault), K = linear_stiffness(kDefault);
  for (const auto& [omega, ratio] : {std::pair{slow, std::sqrt(2.0)}, {fast, -std::sqrt(2.0)}}) {
    EXPECT_NEAR(((K - omega * omega * M) * Eigen::Vector2d(1.0, ratio)).norm(), 0.0, 1e-12);
  }
  // Three periods of each. The linearisation's error is the O(A²) frequency shift: a phase error
  // ≈ c A² ω t, c ≈ 2.5 for the fast mode (whose relative angle θ1 − θ2 is largest), i.e. ≈ 5e-7
  // after three periods at A = 1e-4 (measured: it scales as A² down to A = 1e-5); the integration
  // error at rtol 1e-12, atol 1e-14 is ~1e-9 of A.
  const double slow_error =
      deviation_from_mode({}, {1.0, std::sqrt(2.0)}, slow, 1e-4, 3 * 2 * kPi / slow);
  const double fast_error =
      deviation_from_mode({}, {1.0, -std::sqrt(2.0)}, fast, 1e-4, 3 * 2 * kPi / fast);
  EXPECT_LT(slow_error, 1e-6);
  EXPECT_LT(fast_error, 1e-6);
  record("slow_mode_relative_error", slow_error);
  record("fast_mode_relative_error", fast_error);

  // A wrong frequency would be seen: 0.1% off gives an error of order 1e-2 over three periods.
  const double detuned =
      deviation_from_mode({}, {1.0, std::sqrt(2.0)}, slow * 1.001, 1e-4, 3 * 2 * kPi / slow);
  EXPECT_GT(detuned, 1e-3);
}

// Unequal masses and lengths: the small-oscillation frequencies are the square roots of the
// eigenvalues of M⁻¹K, which equal the notes' closed form (units g/l1, α = m2/m1, β = l2/l1)
// ω² = [(1+α)(1+β) ∓ √((1+α)²(1+β)² − 4β(1+α))]/(2β); the model oscillates in each eigenvector.
TEST(DoublePendulum, SmallOscillationsOfAnUnequalPendulum) {
  const Parameters p{1.5, 0.7, 0.8, 1.3, 9.81};
  const std::vector<std::pair<std::string, double>> overrides{
      {"m1", p.m1}, {"m2", p.m2}, {"l1", p.l1}, {"l2", p.l2}, {"g", p.g}};
  const test::SymmetricEigen modes =
      test::generalized_symmetric_eigen(linear_stiffness(p), linear_mass(p));
  ASSERT_EQ(modes.info(), Eigen::Success);
  const double alpha = p.m2 / p.m1, beta = p.l2 / p.l1;
  const double b = (1 + alpha) * (1 + beta);
  const double root = std::sqrt(b * b - 4 * beta * (1 + alpha));
  const double unit = p.g / p.l1;
  EXPECT_NEAR(modes.eigenvalues()[0], unit * (b - root) / (2 * beta), 1e-12 * unit);
  EXPECT_NEAR(modes.eigenvalues()[1], unit * (b + root) / (2 * beta), 1e-12 * unit);

  for (Eigen::Index k = 0; k < 2; ++k) {
    const double omega = std::sqrt(modes.eigenvalues()[k]);
    const Eigen::Vector2d shape = modes.eigenvectors().col(k) / modes.eigenvectors()(0, k);
    const double error = deviation_from_mode(overrides, shape, omega, 1e-4, 3 * 2 * kPi / omega);
    // as for the symmetric pendulum: O(A²) nonlinear corrections, ≲ 5e-7 after three periods
    EXPECT_LT(error, 1e-6) << "mode " << k << ", ω = " << omega;
    record("mode" + std::to_string(k) + "_relative_error", error);
  }
}

// Exercise 5.6(h): E = T + U is conserved along the large-amplitude (chaotic) default motion over
// 20 s; the energy column is that E.
TEST(DoublePendulum, EnergyConservedInChaoticMotion) {
  const auto run = test::run_model("double-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.at(run.rows.size() - 1, "t"), 20.0);
  double scale = 0.0;
  const double E0 = energy(kDefault, run.at(0, "theta1"), run.at(0, "theta2"),
                           run.at(0, "der(theta1)"), run.at(0, "der(theta2)"), &scale);
  double drift = 0.0, column_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    double row_scale = 0.0;
    const double E = energy(kDefault, run.at(i, "theta1"), run.at(i, "theta2"),
                            run.at(i, "der(theta1)"), run.at(i, "der(theta2)"), &row_scale);
    scale = std::max(scale, row_scale);
    drift = std::max(drift, std::abs(E - E0));
    column_error = std::max(column_error, std::abs(run.at(i, "energy") - E));
  }
  // local errors ≤ rtol = 1e-12 per step; energy errors do not grow exponentially even when the
  // trajectory's do
  EXPECT_LT(drift / scale, 1e-10);
  EXPECT_LT(column_error / scale, 1e-14);
  record("energy_relative_drift", drift / scale);
}

// Exercise 4.1(d): the model against an RK4 integration of the textbook equations written here
// (step 1e-4, whose own error, estimated by halving the step, is ~1e-13): θ, θ̇ agree at t = 2.
TEST(DoublePendulum, AgreesWithIndependentIntegration) {
  const auto run = test::run_model("double-pendulum", {},
                                   [](SimulationOptions& options) { options.t_end = 2.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_EQ(run.at(last, "t"), 2.0);
  const State start{run.at(0, "theta1"), run.at(0, "theta2"), run.at(0, "der(theta1)"),
                    run.at(0, "der(theta2)")};
  ASSERT_EQ(start[0], 1.0);
  ASSERT_EQ(start[1], 2.0);
  const State fine = textbook_rk4(kDefault, start, 2.0, 20000);
  const State coarse = textbook_rk4(kDefault, start, 2.0, 10000);
  const State model{run.at(last, "theta1"), run.at(last, "theta2"), run.at(last, "der(theta1)"),
                    run.at(last, "der(theta2)")};
  double rk4_error = 0.0, difference = 0.0;
  for (std::size_t j = 0; j < 4; ++j) {
    rk4_error = std::max(rk4_error, std::abs(fine[j] - coarse[j]) / 15.0);  // Richardson, order 4
    difference = std::max(difference, std::abs(model[j] - fine[j]));
  }
  ASSERT_LT(rk4_error, 1e-11);
  // the model's local errors (rtol 1e-12) grow with the flow's sensitivity over 2 s, which stays
  // far below the 1e-3 it would take to reach 1e-9
  EXPECT_LT(difference, 1e-9);
  record("rk4_error_estimate", rk4_error);
  record("model_minus_rk4", difference);
}

// Exercise 5.4: the same pendulum in the coordinates of Exercise 5.3 — m1 cylindrical, m2 relative
// to m1 spherical — held by the three constraints r1 = L1, z1 = 0, R2 = L0 on the representative
// point, started in the plane: it stays there (φ2 = π/2) and its angles, measured from E1, are
// double-pendulum's from the downward vertical less π/2, row by row.
TEST(DoublePendulum, ThreeConstraintsOnTheRepresentativePointOfExercise54) {
  const double half_pi = std::acos(0.0);
  const test::ModelRun constrained = test::run_model("double-pendulum-constrained");
  const test::ModelRun pendulum = test::run_model(
      "double-pendulum",
      {{"theta1", 0.5}, {"theta2", -0.3}, {"der(theta1)", 0.4}, {"der(theta2)", -0.2}},
      [](SimulationOptions& o) { o.t_end = 10.0; });
  ASSERT_TRUE(constrained.summary.ok && pendulum.summary.ok) << constrained.summary.message;
  ASSERT_EQ(constrained.rows.size(), pendulum.rows.size());
  for (std::size_t i = 0; i < pendulum.rows.size(); ++i) {
    ASSERT_EQ(constrained.at(i, "t"), pendulum.at(i, "t"));
    EXPECT_NEAR(constrained.at(i, "theta1") + half_pi, pendulum.at(i, "theta1"), 1e-9);
    EXPECT_NEAR(constrained.at(i, "theta2") + half_pi, pendulum.at(i, "theta2"), 1e-9);
    EXPECT_NEAR(constrained.at(i, "phi2"), half_pi, 1e-12);
    EXPECT_NEAR(constrained.at(i, "z1"), 0.0, 1e-12);
  }
}

// Exercise 5.4(e): a non-integrable constraint f1 · v1 + f2 · v2 + e = 0 added to the three of
// double-pendulum-constrained.yaml. Here f1 = 0, f2 = E3 × (x2 − x1) and e constant: the part of
// m2's velocity along the horizontal E3 × (x2 − x1) is held at −e/(L0 sin φ2). With a = θ1, p = φ2,
// b = θ2, d = b − a, S = sin p, C = cos p (r1 = L1, z1 = 0, R2 = L0),
//   v2 = L1 ȧ e_θ1 + L0 (ṗ e_φ2 + S ḃ e_θ2),  e_θ1 · e_φ2 = C sin d,  e_θ1 · e_θ2 = cos d,
// and the constraint is L0 S (L1 cos d ȧ + L0 S ḃ) + e = 0, i.e. A · q̇ + e = 0 with
// A = (L0 L1 S cos d, 0, L0² S²) = L0 S a, a = (L1 cos d, 0, L0 S), rot a = (L0 C, −L1 sin d, 0):
// a · rot a = L0 L1 C cos d ≠ 0 off the plane, so the constraint is not integrable (Frobenius).
// By hand (k = m2 L1 L0), T̃ = ½(m1+m2) L1² ȧ² + ½ m2 L0² (ṗ² + S² ḃ²) + k ȧ (C sin d ṗ + S cos d
// ḃ), Ũ = (m1+m2) g L1 sin a + m2 g L0 S sin b (gravity −g E2), and Lagrange's equations with the
// multiplier, d/dt(∂T̃/∂q̇) − ∂T̃/∂q = −∂Ũ/∂q + μ A:
//   (m1+m2) L1² ä + k C sin d p̈ + k S cos d b̈ + k (2 C cos d ṗ ḃ − S sin d (ṗ² + ḃ²))
//       = −(m1+m2) g L1 cos a + μ L0 L1 S cos d,
//   k C sin d ä + m2 L0² p̈ − k C cos d ȧ² − m2 L0² S C ḃ² = −m2 g L0 C sin b,
//   k S cos d ä + m2 L0² S² b̈ + 2 m2 L0² S C ṗ ḃ + k S sin d ȧ² = −m2 g L0 S cos b + μ L0² S²,
// closed by A · q̈ = −L0 L1 ȧ (C ṗ cos d − S sin d ḋ) − 2 L0² S C ṗ ḃ (the constraint's rate), and
// F_c2 = μ f2, F_c1 = μ f1 = 0 (§5.2). (At p = π/2 with ṗ = 0 these are (5.19) with one more
// force.)
using Pendulum54State = std::array<double, 6>;  // a, p, b, ȧ, ṗ, ḃ

struct Pendulum54 {
  double m1, m2, L1, L0, g, e;
  bool extra = true;  // false: (d)'s equations, without the fourth constraint (μ = 0)

  // q̈ and μ from the equations above.
  std::pair<Eigen::Vector3d, double> accelerations(const Pendulum54State& y) const {
    const double a = y[0], p = y[1], b = y[2], ad = y[3], pd = y[4], bd = y[5], d = b - a;
    const double S = std::sin(p), C = std::cos(p), k = m2 * L1 * L0;
    Eigen::Matrix4d K = Eigen::Matrix4d::Zero();
    K(0, 0) = (m1 + m2) * L1 * L1;
    K(0, 1) = K(1, 0) = k * C * std::sin(d);
    K(0, 2) = K(2, 0) = k * S * std::cos(d);
    K(1, 1) = m2 * L0 * L0;
    K(2, 2) = m2 * L0 * L0 * S * S;
    const Eigen::Vector3d A(L0 * L1 * S * std::cos(d), 0.0, L0 * L0 * S * S);
    K.block<3, 1>(0, 3) = -A;
    K.block<1, 3>(3, 0) = A.transpose();
    Eigen::Vector4d rhs;
    rhs << -k * (2 * C * std::cos(d) * pd * bd - S * std::sin(d) * (pd * pd + bd * bd)) -
               (m1 + m2) * g * L1 * std::cos(a),
        k * C * std::cos(d) * ad * ad + m2 * L0 * L0 * S * C * bd * bd -
            m2 * g * L0 * C * std::sin(b),
        -2 * m2 * L0 * L0 * S * C * pd * bd - k * S * std::sin(d) * ad * ad -
            m2 * g * L0 * S * std::cos(b),
        -L0 * L1 * ad * (C * pd * std::cos(d) - S * std::sin(d) * (bd - ad)) -
            2 * L0 * L0 * S * C * pd * bd;
    if (!extra) return {K.topLeftCorner<3, 3>().partialPivLu().solve(rhs.head<3>()), 0.0};
    const Eigen::Vector4d x = K.partialPivLu().solve(rhs);
    return {x.head<3>(), x[3]};
  }

  Pendulum54State rates(const Pendulum54State& y) const {
    const Eigen::Vector3d qdd = accelerations(y).first;
    return {y[3], y[4], y[5], qdd[0], qdd[1], qdd[2]};
  }

  Pendulum54State rk4(Pendulum54State y, double h, int n) const {
    const auto add = [](const Pendulum54State& x, const Pendulum54State& r, double f) {
      Pendulum54State z;
      for (std::size_t j = 0; j < z.size(); ++j) z[j] = x[j] + f * r[j];
      return z;
    };
    for (int i = 0; i < n; ++i) {
      const Pendulum54State k1 = rates(y), k2 = rates(add(y, k1, h / 2)),
                            k3 = rates(add(y, k2, h / 2)), k4 = rates(add(y, k3, h));
      for (std::size_t j = 0; j < y.size(); ++j)
        y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    return y;
  }
};

// Exercise 5.4(e) run: the model file with m2 = 0.6, L0 = 0.7 (so that no factor of the masses
// or lengths can hide), the constraint above with e = 0.1 added and outputs of its forces on P1
// and P2, started in the plane but moving out of it (φ̇2 = 0.4; θ̇2 from the constraint). The
// run's θ1, φ2, θ2, their rates and λ(extra) against the reduced equations above integrated by
// RK4 (h = 0.1 ms, its error estimated against h = 0.2 ms), and the constraint's forces against
// F_c1 = 0, F_c2 = μ E3 × (x2 − x1) with the RK4's μ. m2 leaves the plane: φ2 swings between ~1.0
// and ~2.1.
TEST(DoublePendulum, ExtraNonIntegrableConstraintOfExercise54e) {
  const Pendulum54 hand{1.0, 0.6, 1.0, 0.7, 9.81, 0.1};
  const double half_pi = std::acos(0.0), a0 = 0.5 - half_pi, b0 = -0.3 - half_pi, ad0 = 0.4;
  // L0 (L1 cos d ȧ + L0 ḃ) + e = 0 at φ2 = π/2
  const double bd0 = (-hand.e / hand.L0 - hand.L1 * std::cos(b0 - a0) * ad0) / hand.L0;
  std::ifstream file(test::model_path("double-pendulum-constrained"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const auto replace_line = [&](const std::string& start, const std::string& by) {
    const std::size_t from = text.find(start);
    ASSERT_NE(from, std::string::npos) << start;
    text.replace(from, text.find('\n', from) - from, by);
  };
  std::ostringstream numbers;
  numbers << std::setprecision(17) << "parameters: {m1: " << hand.m1 << ", m2: " << hand.m2
          << ", L1: " << hand.L1 << ", L0: " << hand.L0 << ", g: " << hand.g << ", e: " << hand.e
          << "}";
  replace_line("parameters:", numbers.str());
  numbers.str("");
  numbers << std::setprecision(17) << "  - {name: rod2, position: R2 - L0}\n"
          << "  - {name: extra, velocity: \"dot(P2.velocity, cross(E3, P2.position - "
             "P1.position)) + e\"}";
  replace_line("  - {name: rod2", numbers.str());
  numbers.str("");
  numbers << std::setprecision(17) << "initial: {r1: L1, theta1: " << a0
          << ", R2: L0, phi2: pi/2, theta2: " << b0 << ", der(theta1): " << ad0
          << ", der(phi2): 0.4, der(theta2): " << bd0 << "}";
  replace_line("initial:", numbers.str());
  text += "outputs:\n  F1: extra.force.P1\n  F2: extra.force.P2\n";
  const System system = parse_model(text, "double-pendulum-54e.yaml");
  ASSERT_EQ(system.constraints.size(), 4u);
  const test::ModelRun run =
      test::run_system(system, {}, [](SimulationOptions& o) { o.t_end = 5.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.max_velocity_residual, 1e-10);
  ASSERT_EQ(run.parameter("L0"), hand.L0);
  Pendulum54State fine{run.at(0, "theta1"),      run.at(0, "phi2"),      run.at(0, "theta2"),
                       run.at(0, "der(theta1)"), run.at(0, "der(phi2)"), run.at(0, "der(theta2)")};
  Pendulum54State coarse = fine;
  double rk4_error = 0, angle_error = 0, rate_error = 0, mu_error = 0, force_error = 0;
  double out_of_plane = 0, largest_mu = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    ASSERT_NEAR(run.at(k, "t"), 0.01 * static_cast<double>(k), 1e-12);
    if (k > 0) {
      fine = hand.rk4(fine, 1e-4, 100);
      coarse = hand.rk4(coarse, 2e-4, 50);
    }
    for (std::size_t j = 0; j < 6; ++j)
      rk4_error = std::max(rk4_error, std::abs(fine[j] - coarse[j]) / 15.0);
    angle_error =
        std::max({angle_error, std::abs(run.at(k, "theta1") - fine[0]),
                  std::abs(run.at(k, "phi2") - fine[1]), std::abs(run.at(k, "theta2") - fine[2])});
    rate_error = std::max({rate_error, std::abs(run.at(k, "der(theta1)") - fine[3]),
                           std::abs(run.at(k, "der(phi2)") - fine[4]),
                           std::abs(run.at(k, "der(theta2)") - fine[5])});
    const double mu = hand.accelerations(fine).second;
    mu_error = std::max(mu_error, std::abs(run.at(k, "lambda(extra)") - mu));
    // E3 × (x2 − x1) = L0 sin φ2 (−sin θ2, cos θ2, 0)
    const double S = std::sin(fine[1]);
    force_error =
        std::max({force_error, std::abs(run.at(k, "F2.x") + mu * hand.L0 * S * std::sin(fine[2])),
                  std::abs(run.at(k, "F2.y") - mu * hand.L0 * S * std::cos(fine[2])),
                  std::abs(run.at(k, "F2.z")), std::abs(run.at(k, "F1.x")),
                  std::abs(run.at(k, "F1.y")), std::abs(run.at(k, "F1.z"))});
    out_of_plane = std::max(out_of_plane, std::abs(fine[1] - half_pi));
    largest_mu = std::max(largest_mu, std::abs(mu));
  }
  EXPECT_GT(out_of_plane, 0.4);
  EXPECT_GT(largest_mu, 0.5);  // the extra constraint does push (m2 g = 5.9 N)
  ASSERT_LT(rk4_error, 1e-12);
  // a run at rtol 1e-12 over 5 s, its local errors grown by the flow's sensitivity
  EXPECT_LT(angle_error, 1e-10);
  EXPECT_LT(rate_error, 1e-9);
  EXPECT_LT(mu_error, 1e-9);
  EXPECT_LT(force_error, 1e-9);
  std::printf(
      "Ex. 5.4(e) vs hand RK4 over 5 s (RK4 error %.3g): angles %.3g, rates %.3g rad/s, mu %.3g "
      "(|mu| up to %.3g), F_c1/F_c2 %.3g N; phi2 leaves pi/2 by %.3g\n",
      rk4_error, angle_error, rate_error, mu_error, largest_mu, force_error, out_of_plane);
}

// Exercise 5.4(d): without the fourth constraint (μ = 0), the equations above are (d)'s
// d/dt(∂T̃/∂q̇) − ∂T̃/∂q = −∂Ũ/∂q in θ1, φ2, θ2. double-pendulum-constrained.yaml as it is, but
// started out of the plane (φ̇2 = 0.4: m2 swings on its sphere about m1, which the plane holds),
// against them by RK4 (h = 0.1 ms, error estimated against h = 0.2 ms).
TEST(DoublePendulum, ThreeConstraintsOfExercise54dAgainstHandEquationsByRk4) {
  const Pendulum54 hand{1.0, 1.0, 1.0, 1.0, 9.81, 0.0, false};
  const test::ModelRun run = test::run_model("double-pendulum-constrained", {{"der(phi2)", 0.4}},
                                             [](SimulationOptions& o) { o.t_end = 5.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (const char* name : {"m1", "m2", "L1", "L0"}) ASSERT_EQ(run.parameter(name), 1.0) << name;
  ASSERT_EQ(run.parameter("g"), hand.g);
  Pendulum54State fine{run.at(0, "theta1"),      run.at(0, "phi2"),      run.at(0, "theta2"),
                       run.at(0, "der(theta1)"), run.at(0, "der(phi2)"), run.at(0, "der(theta2)")};
  Pendulum54State coarse = fine;
  double rk4_error = 0, error = 0, out_of_plane = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    ASSERT_NEAR(run.at(k, "t"), 0.01 * static_cast<double>(k), 1e-12);
    if (k > 0) {
      fine = hand.rk4(fine, 1e-4, 100);
      coarse = hand.rk4(coarse, 2e-4, 50);
    }
    std::size_t j = 0;
    for (const char* column :
         {"theta1", "phi2", "theta2", "der(theta1)", "der(phi2)", "der(theta2)"}) {
      rk4_error = std::max(rk4_error, std::abs(fine[j] - coarse[j]) / 15.0);
      error = std::max(error, std::abs(run.at(k, column) - fine[j]));
      ++j;
    }
    out_of_plane = std::max(out_of_plane, std::abs(fine[1] - std::acos(0.0)));
  }
  EXPECT_GT(out_of_plane, 0.1);
  ASSERT_LT(rk4_error, 1e-12);
  EXPECT_LT(error, 1e-10);  // a run at rtol 1e-12 over 5 s: ~3e-11
  std::printf(
      "Ex. 5.4(d) vs hand RK4 over 5 s (RK4 error %.3g): angles and rates %.3g; phi2 leaves "
      "pi/2 by %.3g\n",
      rk4_error, error, out_of_plane);
}

}  // namespace
}  // namespace unidyn
