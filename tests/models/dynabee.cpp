// Exercise 11.4, the Dynabee (Powerball): models/dynabee.yaml, a rotor whose axle rolls on a track
// inside a casing the hand moves (ψ = Ωt, θ = θ0, φ = −Ωt). The rolling is the book's vector
// condition of (d): the rotor's material point at the contact P moves with the track's, P − x̄ =
// π_P = R_t e_r1 − R_a e_t3; (11.17) and the axle's staying in the track's plane follow from it.
//
// The rotor's equation, derived here by hand (Lagrange in α alone). With μ = 0 and the casing's
// ω_t = Ω E3 − Ω e_t3, the rotor's ω_r = Ω E3 + (α̇ − Ω) e_t3 + γ̇ e_r1 with γ̇ = −k α̇, k = R_t/R_a.
// E3 · e_t1 = sinθ0 sinφ, E3 · e_t2 = sinθ0 cosφ, E3 · e_t3 = cosθ0 (3-1-3) and e_r1 = cosα e_t1 +
// sinα e_t2 give E3 · e_r1 = s sinδ, s = sinθ0, δ = α − Ωt, so the spin ω1 = ω_r · e_r1 =
// Ω s sinδ − k α̇. The rotor is axisymmetric about e_r1 (moments C_r, A_r) and its centre is fixed:
//   T = ½ (C_r − A_r) ω1² + ½ A_r |ω_r|²,
//   |ω_r|² = Ω² + (α̇ − Ω)² + k² α̇² + 2Ω cosθ0 (α̇ − Ω) − 2Ω k α̇ s sinδ,
//   ∂T/∂α̇ = A_r (α̇ − Ω (1 − cosθ0)) − k C_r ω1,   ∂T/∂α = Ω s cosδ (C_r ω1 − A_r Ω s sinδ),
// and d/dt ∂T/∂α̇ = ∂T/∂α (no applied loads; the contact's force does no work on δα, δγ = −k δα):
//   (A_r + k² C_r) α̈ = Ω² s cosδ ((C_r − A_r) s sinδ − k C_r).                         (*)
// The Euler equation about the axle (f): the moment about x̄ of the contact force λ1 a2 + λ2 π_P ×
// a2 at P (the model's rows roll_1, roll_2; a2 = e_t3 × e_r1) has the e_r1 component R_a λ1, so
//   C_r ω̇1 = C_r (Ω s cosδ (α̇ − Ω) − k α̈) = R_a λ1.                                      (**)
// (g) Steady spin: (*) holds δ at −π/2 (sinδ = −1), i.e. α = Ωt − π/2: α̇ = Ω = ψ̇, and the rotor
// spins at γ̇ = −(R_t/R_a) Ω, ten times the hand's rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/equations/lagrange.hpp"

namespace unidyn {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Rotor {
  double A, C, k, Omega, theta0;
  // (*): α̈ at time t
  double acceleration(double t, double alpha) const {
    const double s = std::sin(theta0), delta = alpha - Omega * t;
    return Omega * Omega * s * std::cos(delta) * ((C - A) * s * std::sin(delta) - k * C) /
           (A + k * k * C);
  }
  // (**): the multiplier of roll_1
  double rolling_multiplier(double t, double alpha, double rate, double R_a) const {
    const double s = std::sin(theta0), delta = alpha - Omega * t;
    return C * (Omega * s * std::cos(delta) * (rate - Omega) - k * acceleration(t, alpha)) / R_a;
  }
};

Rotor rotor_of(const test::ModelRun& run) {
  return {run.parameter("A_r"), run.parameter("C_r"), run.parameter("R_t") / run.parameter("R_a"),
          run.parameter("Omega"), run.parameter("theta0")};
}

using State = std::array<double, 2>;  // (α, α̇)

struct Errors {
  double alpha = 0, rate = 0, lambda = 0, swing = 0;
};

// The run against RK4 of (*) from its initial (α, α̇) on every output row, and λ(roll_1) against
// (**).
Errors compare_with_rk4(const test::ModelRun& run) {
  const Rotor rotor = rotor_of(run);
  const double R_a = run.parameter("R_a");
  // (*) as a first-order system in (α, α̇)
  const auto rates = [&rotor](double t, const State& x) {
    return State{x[1], rotor.acceleration(t, x[0])};
  };
  State s{run.at(0, "alpha"), run.at(0, "der(alpha)")};
  Errors e;
  double t = run.at(0, "t"), lowest = s[1], highest = s[1];
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t1 = run.at(i, "t");
    if (t1 > t)
      s = test::rk4(s, t, t1, std::max(1, static_cast<int>(std::lround((t1 - t) / 1e-4))), rates);
    t = t1;
    e.alpha = std::max(e.alpha, std::abs(run.at(i, "alpha") - s[0]));
    e.rate = std::max(e.rate, std::abs(run.at(i, "der(alpha)") - s[1]));
    e.lambda = std::max(e.lambda, std::abs(run.at(i, "lambda(roll_1)") -
                                           rotor.rolling_multiplier(t, s[0], s[1], R_a)));
    lowest = std::min(lowest, s[1]);
    highest = std::max(highest, s[1]);
  }
  e.swing = highest - lowest;
  return e;
}

// (e) With both centres as coordinates the hand (6), the centres (3) and the two components of the
// rolling (d) are 11 independent rows on 12 coordinates (rank of A), at the start and where the
// rotor has turned by γ = π/2 about its axle. (d) Along the run the rolling's consequences hold:
// μ = 0 (the axle in the track's plane) and (11.17) γ̇ = −(R_t/R_a) α̇, the rotor spinning ten times
// faster than it runs round the track.
TEST(Dynabee, ElevenConstraintsAndTheRollingRelation1117) {
  const System system = load_model(test::model_path("dynabee"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  for (const double gamma : {0.0, kPi / 2}) {
    SimulationStart start = initial_state(system, {{"gamma", gamma}});
    complete_initial_state(system, compiled, start);
    CompiledSystemData data = compiled.make_data();
    compiled.constraints(start.t0, start.q, start.qdot, start.parameters, data);
    EXPECT_EQ(data.constraint_matrix.rows(), 11);
    EXPECT_EQ(data.constraint_matrix.cols(), 12);
    EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(data.constraint_matrix).rank(), 11) << gamma;
  }

  const test::ModelRun run = test::run_system(system, {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double k = run.parameter("R_t") / run.parameter("R_a");
  double relation = 0, plane = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double alpha_rate = run.at(i, "der(alpha)");
    relation = std::max(relation, std::abs(run.at(i, "der(gamma)") + k * alpha_rate) / alpha_rate);
    plane = std::max({plane, std::abs(run.at(i, "mu")), std::abs(run.at(i, "der(mu)"))});
  }
  EXPECT_LT(relation, 1e-9);
  EXPECT_LT(plane, 1e-9);
  EXPECT_GT(run.rows.back()[run.index("alpha")], 10.0) << "the rotor must run round the track";
  std::printf("(11.17): max |gamma' + (R_t/R_a) alpha'| / alpha' = %.3g; max |mu|, |mu'| = %.3g\n",
              relation, plane);
}

// (f) The rotor's motion against RK4 (h = 1e-4 s) of the hand-derived (*), and the rolling force's
// multiplier λ(roll_1) against the Euler equation about the axle (**): the model's run (α̇0 = 20,
// δ̇ = 14 rad/s, δ going round) and a run from δ0 = −π/2 + 1.2, α̇0 = Ω, where δ swings about −π/2
// (its period 2π/0.85 s) and α̇ changes by ~2 rad/s.
TEST(Dynabee, RotorFollowsTheHandDerivedEquationByRk4) {
  const test::ModelRun model = test::run_model("dynabee", {}, {}, true);
  ASSERT_TRUE(model.summary.ok) << model.summary.message;
  const test::ModelRun swinging = test::run_model(
      "dynabee", {{"alpha", -kPi / 2 + 1.2}, {"der(alpha)", 6.0}},
      [](SimulationOptions& o) { o.t_end = 10; }, true);
  ASSERT_TRUE(swinging.summary.ok) << swinging.summary.message;
  for (const test::ModelRun* run : {&model, &swinging}) {
    const Errors e = compare_with_rk4(*run);
    // RK4 at 1e-4 s is exact to ~1e-13 here; the runs are at rtol 1e-10 (α up to 40 rad)
    EXPECT_LT(e.alpha, 1e-7);
    EXPECT_LT(e.rate, 1e-7);
    EXPECT_LT(e.lambda, 1e-7);
    EXPECT_GT(e.swing, 0.05) << "the rotor's rate must change";
    std::printf(
        "RK4 of (*) vs model over %.0f s: alpha %.3g rad, alpha' %.3g rad/s (alpha' swings by "
        "%.3g), "
        "lambda(roll_1) vs (**) %.3g N\n",
        run->rows.back()[0], e.alpha, e.rate, e.swing, e.lambda);
  }
}

// (g) The steady spin: started at α = −π/2, α̇ = Ω = ψ̇ (δ = −π/2), the rotor keeps α̇ = ψ̇ = Ω and
// α = Ωt − π/2 for 10 s (about ten turns of the hand), and spins about its axle at γ̇ = −(R_t/R_a)
// ψ̇, (R_t/R_a) = 10 times the hand's rate.
TEST(Dynabee, SteadySpinFollowsTheHand) {
  const test::ModelRun run = test::run_model(
      "dynabee", {{"alpha", -kPi / 2}, {"der(alpha)", 6.0}},
      [](SimulationOptions& o) { o.t_end = 10; }, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double Omega = run.parameter("Omega"), k = run.parameter("R_t") / run.parameter("R_a");
  double phase = 0, rate = 0, spin = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    phase = std::max(phase, std::abs(run.at(i, "alpha") - (Omega * t - kPi / 2)));
    rate = std::max(rate, std::abs(run.at(i, "der(alpha)") - run.at(i, "der(psi)")));
    spin = std::max(spin, std::abs(run.at(i, "der(gamma)") + k * Omega));
  }
  EXPECT_LT(phase, 1e-8);
  EXPECT_LT(rate, 1e-8);
  EXPECT_LT(spin, 1e-7);
  std::printf(
      "steady spin over 10 s: max |alpha - (Omega t - pi/2)| %.3g, |alpha' - psi'| %.3g, "
      "|gamma' + (R_t/R_a) Omega| %.3g\n",
      phase, rate, spin);
}

}  // namespace
}  // namespace unidyn
