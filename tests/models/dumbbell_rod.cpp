// Two particles joined by a rigid rod orbiting a planet (§5.3 with a rod, §4.3–4.5): the rod's
// forces (4.3) against closed forms of the tension, spinning freely and on the orbit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// (4.3): the rod's forces on its ends are equal and opposite and along the rod (F_c1 = −F_c2 =
// −μ t), so they do no net work and no net moment: E and H_O are conserved; the rod keeps its
// length.
TEST(DumbbellRod, RodForcesEqualOppositeAlongTheRod) {
  const test::ModelRun run = test::run_model("dumbbell-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "length"), 0.012, 1e-12);
    for (const char* c : {".x", ".y", ".z"}) {
      const double F1 = run.at(i, std::string("F1") + c), F2 = run.at(i, std::string("F2") + c);
      EXPECT_NEAR(F1 + F2, 0.0, 1e-18);
      largest = std::max(largest, std::abs(F1));
    }
    EXPECT_NEAR(run.at(i, "F1_across"), 0.0, 1e-18);
  }
  EXPECT_GT(largest, 1e-6);  // the rod does pull
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  ASSERT_EQ(run.summary.conserved_drift.size(), 3u);
  for (const auto& c : run.summary.conserved_drift) {
    EXPECT_LT(c.max_change, 1e-10 * std::abs(run.summary.conserved_drift[2].initial)) << c.name;
  }
}

// The rod's force from the state alone, derived here: with x = r2 − r1, |x| = L, the rod's
// forces F_c1 = −μ t, F_c2 = μ t (4.3), t = x/|x|, and the applied forces F1, F2,
//   ẍ = F2/m2 − F1/m1 + μ (1/m1 + 1/m2) t,
// and the rod twice differentiated, x·ẍ + |ẋ|² = 0, give (μ_r = m1m2/(m1 + m2))
//   μ = −μ_r (|ẋ|² + x·(F2/m2 − F1/m1)) / |x|.
// μ < 0 when the rod pulls the particles together (F_c1 = −μ t points from m1 towards m2).
double rod_mu(const Vec3& x, const Vec3& xdot, const Vec3& relative_applied_acceleration, double m1,
              double m2) {
  const double reduced = m1 * m2 / (m1 + m2);
  return -reduced * (xdot.squaredNorm() + x.dot(relative_applied_acceleration)) / x.norm();
}

struct RodRow {
  Vec3 r1, r2, v1, v2, F1;
  double lambda;
};

RodRow rod_row(const test::ModelRun& run, std::size_t i) {
  return {Vec3(run.at(i, "x1"), run.at(i, "y1"), run.at(i, "z1")),
          Vec3(run.at(i, "x2"), run.at(i, "y2"), run.at(i, "z2")),
          Vec3(run.at(i, "der(x1)"), run.at(i, "der(y1)"), run.at(i, "der(z1)")),
          Vec3(run.at(i, "der(x2)"), run.at(i, "der(y2)"), run.at(i, "der(z2)")),
          Vec3(run.at(i, "F1.x"), run.at(i, "F1.y"), run.at(i, "F1.z")),
          run.at(i, "lambda(rod)")};
}

// (4.3)–(4.4) with the tension's value: the dumbbell of models/dumbbell-rod.yaml with the planet
// switched off (G = 0) spins freely at the model's ω = 0.8 rad/s about E3 (relative velocity
// 0.8 L (−sin 0.4, cos 0.4, 0)) while C moves uniformly. Each mass circles C, at m2 L/(m1 + m2)
// and m1 L/(m1 + m2), so the rod pulls each towards the other with
//   |F_c| = (m1m2/(m1 + m2)) L ω²,   F_c1 = −F_c2 = +|F_c| t,
// i.e. μ = −(m1m2/(m1 + m2)) L ω² in (4.3), and the model's multiplier (Ψ = |x|² − L², ∂Ψ/∂r1 =
// −2x = −2L t) is λ = μ/(2L) = −(m1m2/(m1 + m2)) ω²/2. Compared with: the F1, F2 columns and
// lambda(rod), and the positions with the closed-form motion r1,2 = r̄0 + v̄0 t ∓ (m2, m1)/(m1 +
// m2) L (cos(0.4 + ωt), sin(0.4 + ωt), 0).
TEST(DumbbellRod, FreeSpinningRodTensionIsReducedMassTimesLOmegaSquared) {
  const test::ModelRun run = test::run_model("dumbbell-rod", {{"G", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m1 = run.parameter("m1"), m2 = run.parameter("m2"), L = run.parameter("L");
  const double m = m1 + m2, reduced = m1 * m2 / m, omega = 0.8;
  const RodRow start = rod_row(run, 0);
  // the model's start is that spin
  ASSERT_NEAR((start.r2 - start.r1).cross(start.v2 - start.v1).z() / (L * L), omega, 1e-14);
  const Vec3 c0 = (m1 * start.r1 + m2 * start.r2) / m, u0 = (m1 * start.v1 + m2 * start.v2) / m;
  const double tension = reduced * L * omega * omega, lambda = -reduced * omega * omega / 2;
  double force_error = 0, lambda_error = 0, position_error = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const RodRow row = rod_row(run, i);
    const Vec3 e(std::cos(0.4 + omega * t), std::sin(0.4 + omega * t), 0.0);
    const Vec3 c = c0 + u0 * t;
    position_error = std::max({position_error, (row.r1 - (c - m2 / m * L * e)).norm(),
                               (row.r2 - (c + m1 / m * L * e)).norm()});
    const Vec3 F2(run.at(i, "F2.x"), run.at(i, "F2.y"), run.at(i, "F2.z"));
    const Vec3 t_hat = (row.r2 - row.r1).normalized();
    force_error =
        std::max({force_error, (row.F1 - tension * t_hat).norm(), (F2 + tension * t_hat).norm()});
    lambda_error = std::max(lambda_error, std::abs(row.lambda - lambda));
  }
  std::printf(
      "Free dumbbell, |F_c| = (m1m2/(m1 + m2)) L ω² = %.6g: force error %.3g (relative), lambda "
      "%.3g (relative), positions against the uniform spin %.3g m over %g s\n",
      tension, force_error / tension, lambda_error / std::abs(lambda), position_error,
      run.rows.back()[0]);
  // the run's state keeps |x| = L and ω to its rtol 1e-12; μ is evaluated at that state
  EXPECT_LT(force_error / tension, 1e-10);
  EXPECT_LT(lambda_error / std::abs(lambda), 1e-10);
  // the global error at rtol 1e-12 over 20 s, ~2.5 turns
  EXPECT_LT(position_error, 1e-10);
}

// (4.3) on the orbit of models/dumbbell-rod.yaml: the rod's force at every row against μ above,
// computed here from the row's positions and velocities with the planet's pulls
// F_i/m_i = −GM r_i/|r_i|³ (the tidal part x·(F2/m2 − F1/m1) changes along the orbit and is up
// to ~35 times the spin part |ẋ|², so μ is far from the free value): F_c1 = −μ t against the F1
// column, F_c2 = μ t against F2, and the multiplier λ = μ/(2L).
TEST(DumbbellRod, RodForceOnTheOrbitMatchesTheClosedForm) {
  const test::ModelRun run = test::run_model("dumbbell-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m1 = run.parameter("m1"), m2 = run.parameter("m2"),
               GM = run.parameter("G") * run.parameter("M");
  const auto pull = [&](const Vec3& r) -> Vec3 { return -GM * r / std::pow(r.norm(), 3); };
  double force_error = 0, lambda_error = 0, smallest = INFINITY, largest = 0, tidal = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const RodRow row = rod_row(run, i);
    const Vec3 x = row.r2 - row.r1, xdot = row.v2 - row.v1;
    const double mu = rod_mu(x, xdot, pull(row.r2) - pull(row.r1), m1, m2);
    const Vec3 F2(run.at(i, "F2.x"), run.at(i, "F2.y"), run.at(i, "F2.z"));
    const Vec3 t_hat = x.normalized();
    force_error = std::max({force_error, (row.F1 + mu * t_hat).norm() / std::abs(mu),
                            (F2 - mu * t_hat).norm() / std::abs(mu)});
    lambda_error = std::max(
        lambda_error, std::abs(row.lambda - mu / (2 * x.norm())) / std::abs(mu / (2 * x.norm())));
    smallest = std::min(smallest, std::abs(mu));
    largest = std::max(largest, std::abs(mu));
    tidal = std::max(tidal, std::abs(x.dot(pull(row.r2) - pull(row.r1))) / xdot.squaredNorm());
  }
  std::printf(
      "Orbiting dumbbell: |μ| from %.4g to %.4g N (tidal/spin part up to %.3g); force error %.3g, "
      "lambda %.3g (relative)\n",
      smallest, largest, tidal, force_error, lambda_error);
  // μ from the row's state against the solver's at the same state: round-off and the constraint
  // drift of the run (|Ψ| ~ 1e-18)
  EXPECT_LT(force_error, 1e-10);
  EXPECT_LT(lambda_error, 1e-10);
  EXPECT_GT(largest - smallest, 0.1 * largest);  // μ does vary along the orbit
}

}  // namespace
}  // namespace unidyn
