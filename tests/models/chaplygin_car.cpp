// The car with a Chaplygin (knife-edge) constraint (Problem 10.2, (10.49)–(10.50)).
#include <array>
#include <cmath>
#include <cstdio>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/kinematics/integrability.hpp"

namespace unidyn {
namespace {

// (10.50): Euler's laws with the constraint's load, m ẍ1 = −μ4 sin φ, m ẍ2 = μ4 cos φ,
// λ3 φ̈ = −μ4 L1 — here m ā and Ḣ from the run against the multiplier; E conserved; (b) the
// constraint is not integrable.
TEST(ChaplyginCar, EquationsEnergyAndNonIntegrability) {
  const test::ModelRun run = test::run_model("chaplygin-car");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-12);
  const double L1 = 1.2;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double mu = run.at(i, "lambda(chaplygin)"), phi = run.at(i, "phi");
    const double scale = 1e-9 * (1 + std::abs(mu));
    EXPECT_NEAR(run.at(i, "F1"), -mu * std::sin(phi), scale);
    EXPECT_NEAR(run.at(i, "F2"), mu * std::cos(phi), scale);
    EXPECT_NEAR(run.at(i, "M3"), -mu * L1, scale);
    largest = std::max(largest, std::abs(mu));
  }
  EXPECT_GT(largest, 100.0);  // the constraint does act
  const System system = load_model(test::model_path("chaplygin-car"));
  EXPECT_FALSE(constraint_integrability(system, 0).integrable);
}

// (e) Straight-line motion without rotation is a motion of the car: moving along e1 at φ̇ = 0 it
// needs no constraint force.
TEST(ChaplyginCar, StraightLineMotion) {
  const test::ModelRun run =
      test::run_model("chaplygin-car", {{"der(phi)", 0.0}, {"der(x2)", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); i += 10) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), 10 * t, 1e-9) << t;
    EXPECT_EQ(run.at(i, "x2"), 0.0) << t;
    EXPECT_EQ(run.at(i, "lambda(chaplygin)"), 0.0) << t;
  }
}

// The sled's reduced equations, derived by hand from (10.50): with the body-frame velocity
// v̄ = u e1 + v e2 and ω = φ̇, the constraint (10.49) is v = L1 ω; m ā = μ4 e2 gives
// m (u̇ − v ω) = 0 and m (v̇ + u ω) = μ4, and λ3 ω̇ = −μ4 L1; eliminating μ4 (v̇ = L1 ω̇):
//   u̇ = L1 ω²,   ω̇ = −m L1 u ω / (λ3 + m L1²),   μ4 = m u ω λ3 / (λ3 + m L1²),
// and the centre follows ẋ1 = u cos φ − L1 ω sin φ, ẋ2 = u sin φ + L1 ω cos φ, φ̇ = ω.
// State (x1, x2, φ, u, ω).
using SledState = std::array<double, 5>;

struct Sled {
  double m, lambda3, L1;
  double multiplier(const SledState& s) const {
    return m * s[3] * s[4] * lambda3 / (lambda3 + m * L1 * L1);
  }
  SledState rates(const SledState& s) const {
    const double c = std::cos(s[2]), sn = std::sin(s[2]), u = s[3], w = s[4];
    return {u * c - L1 * w * sn, u * sn + L1 * w * c, w, L1 * w * w,
            -m * L1 * u * w / (lambda3 + m * L1 * L1)};
  }
};

// (10.50) as a motion: x1, x2, φ and the multiplier μ4 of the run against the sled's reduced
// equations above, integrated here by RK4 (h = 0.5 ms) from the model's initial state; and u, ω
// against the closed form of those equations: with K = (λ3 + m L1²)/m, u² + K ω² = C is constant
// (the energy of (e)), so u̇ = L1 (C − u²)/K gives u = √C tanh τ, τ = L1 √C t/K + artanh(u0/√C),
// and ω = ±√(C/K) sech τ with ω0's sign. The car turns by ~0.12 rad (√K/L1 (π/2 − asin(u0/√C)))
// as u grows towards √C and ω decays: the constraint steers it.
TEST(ChaplyginCar, MotionAndMultiplierAgreeWithTheSledsReducedEquations) {
  const test::ModelRun run = test::run_model("chaplygin-car");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Sled sled{run.parameter("m"), run.parameter("lambda3"), run.parameter("L1")};
  const double phi0 = run.at(0, "phi");
  const double u0 = run.at(0, "der(x1)") * std::cos(phi0) + run.at(0, "der(x2)") * std::sin(phi0);
  const double w0 = run.at(0, "der(phi)");
  SledState s{run.at(0, "x1"), run.at(0, "x2"), phi0, u0, w0};
  const double K = (sled.lambda3 + sled.m * sled.L1 * sled.L1) / sled.m, C = u0 * u0 + K * w0 * w0;
  double position_error = 0, angle_error = 0, mu_error = 0, closed_form_error = 0, largest_mu = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    if (k > 0) {  // the rows are 0.01 s apart: 20 steps of 0.5 ms
      s = test::rk4(s, 0.0, 0.01, 20,
                    [&sled](double, const SledState& q) { return sled.rates(q); });
    }
    const double t = run.at(k, "t");
    ASSERT_NEAR(t, 0.01 * static_cast<double>(k), 1e-12);
    position_error = std::max(
        {position_error, std::abs(run.at(k, "x1") - s[0]), std::abs(run.at(k, "x2") - s[1])});
    angle_error = std::max(angle_error, std::abs(run.at(k, "phi") - s[2]));
    const double mu = sled.multiplier(s);
    mu_error = std::max(mu_error, std::abs(run.at(k, "lambda(chaplygin)") - mu));
    largest_mu = std::max(largest_mu, std::abs(mu));
    // the closed form against the run's body-frame velocity
    const double phi = run.at(k, "phi");
    const double u = run.at(k, "der(x1)") * std::cos(phi) + run.at(k, "der(x2)") * std::sin(phi);
    const double tau = sled.L1 * std::sqrt(C) * t / K + std::atanh(u0 / std::sqrt(C));
    const double u_exact = std::sqrt(C) * std::tanh(tau);
    const double w_exact = std::copysign(std::sqrt(C / K) / std::cosh(tau), w0);
    closed_form_error = std::max(
        {closed_form_error, std::abs(u - u_exact), std::abs(run.at(k, "der(phi)") - w_exact)});
  }
  // RK4 at h = 0.5 ms (the fastest rate, L1 √C/K ≈ 4 /s, makes its error ~1e-14) against a run
  // at rtol 1e-12: ~1e-11 of the ~100 m travelled and of μ4's ~2500 N
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(angle_error, 1e-11);
  EXPECT_LT(mu_error, 1e-8);
  EXPECT_LT(closed_form_error, 1e-10);
  EXPECT_GT(std::abs(run.rows.back()[run.index("phi")] - phi0), 0.1);
  EXPECT_GT(largest_mu, 1000.0);
  std::printf(
      "sled RK4 vs model over %.0f s: x %.3g m, phi %.3g rad, mu4 %.3g N (of %.0f N); "
      "closed-form u, omega %.3g\n",
      run.rows.back()[0], position_error, angle_error, mu_error, largest_mu, closed_form_error);
}

}  // namespace
}  // namespace unidyn
