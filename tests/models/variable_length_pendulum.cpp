// A spherical pendulum whose string is pulled in and let out (§2.7, §1.7 Fig. 1.7b, Ex. 4.2): a
// rheonomic constraint does work.
#include <array>
#include <cmath>

#include "support/model_run.hpp"
#include "support/rk4.hpp"

namespace unidyn {
namespace {

// Ψ = |r| − L0(t): the constraint force's power F_c · v is −λ ∂Ψ/∂t = λ L̇0 (Ex. 4.2), and the
// energy changes by its integral, E(t) − E(0) = ∫ λ L̇0 dt (§2.7), here by Simpson's rule on the
// 1 ms grid; E changes by more than 1 J, so it is not conserved.
TEST(VariableLengthPendulum, EnergyChangesByTheConstraintsWork) {
  const test::ModelRun run = test::run_model("variable-length-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);  // an even number of intervals
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "power"), run.at(i, "lambda_Lrate"), 1e-10) << run.at(i, "t");
  }
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 2; i < run.rows.size(); i += 2) {
    EXPECT_NEAR(run.at(i, "E") - run.at(0, "E"), work[i], 1e-9) << run.at(i, "t");
  }
  EXPECT_GT(std::abs(run.rows.back()[run.index("E")] - run.at(0, "E")), 1.0);
}

// The pendulum in spherical coordinates with R = L0(t) = L + a sin ωt (φ the polar angle from E3,
// θ the azimuth), from (1.9) with gravity −mg E3 = −mg cos φ e_R + mg sin φ e_φ and the string's
// force λ e_R (Ψ = |r| − L0):
//   φ̈ = (g sin φ − 2 L̇0 φ̇ + L0 sin φ cos φ θ̇²) / L0,
//   θ̈ = −2 θ̇ (L̇0 sin φ + L0 cos φ φ̇) / (L0 sin φ),
//   λ = m (L̈0 − L0 φ̇² − L0 sin²φ θ̇²) + m g cos φ   (the e_R component of m a = F + λ e_R).
// State (φ, φ̇, θ, θ̇).
using SphericalState = std::array<double, 4>;

struct String {
  double L, a, w;
  double length(double t) const { return L + a * std::sin(w * t); }
  double rate(double t) const { return a * w * std::cos(w * t); }
  double acceleration(double t) const { return -a * w * w * std::sin(w * t); }
};

SphericalState spherical_rates(double t, const SphericalState& s, const String& string, double g) {
  const double R = string.length(t), Rdot = string.rate(t);
  const double sp = std::sin(s[0]), cp = std::cos(s[0]);
  return {s[1], (g * sp - 2 * Rdot * s[1] + R * sp * cp * s[3] * s[3]) / R, s[3],
          -2 * s[3] * (Rdot * sp + R * cp * s[1]) / (R * sp)};
}

// §2.7, Fig. 1.7b: the motion and the string's multiplier against the spherical equations above,
// integrated here by RK4 from the model's initial state (φ0 = π − 1, θ̇0 = 2/(L sin 1), Ṙ0 = aω).
TEST(VariableLengthPendulum, MotionAndStringForceAgreeWithSphericalEquationsByRk4) {
  const test::ModelRun run = test::run_model("variable-length-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = run.parameter("m"), g = run.parameter("g");
  const String string{run.parameter("L"), run.parameter("a"), run.parameter("w")};
  const double x0 = run.at(0, "x"), z0 = run.at(0, "z");
  ASSERT_EQ(run.at(0, "y"), 0.0);
  SphericalState s{std::atan2(x0, z0), 0.0, 0.0, run.at(0, "der(y)") / x0};
  double t = 0, position_error = 0, lambda_error = 0;
  for (std::size_t k = 250; k < run.rows.size(); k += 250) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, 2000, [&](double tau, const SphericalState& q) {
      return spherical_rates(tau, q, string, g);
    });
    t = t1;
    const double R = string.length(t), sp = std::sin(s[0]), cp = std::cos(s[0]);
    const double x = R * sp * std::cos(s[2]), y = R * sp * std::sin(s[2]), z = R * cp;
    position_error = std::max({position_error, std::abs(run.at(k, "x") - x),
                               std::abs(run.at(k, "y") - y), std::abs(run.at(k, "z") - z)});
    const double lambda =
        m * (string.acceleration(t) - R * s[1] * s[1] - R * sp * sp * s[3] * s[3]) + m * g * cp;
    lambda_error = std::max(lambda_error, std::abs(run.at(k, "lambda(string)") - lambda));
  }
  // RK4 at h = 1.25e-4 s (error ~1e-12) against a run at rtol 1e-12 over 5 s
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(lambda_error, 1e-8);
  std::printf("RK4 vs model over 5 s: position %.3g m, string multiplier %.3g N\n", position_error,
              lambda_error);
}

}  // namespace
}  // namespace unidyn
