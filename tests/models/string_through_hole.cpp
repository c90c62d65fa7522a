// Two particles joined by a string through a hole (§5.5, (5.13)–(5.14)): a unilateral string and
// a rough table at once.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double m1 = 1.0, m2 = 0.5, g = 9.81, L0 = 1.0, r0 = 0.4;

// μ_d = 0: m1 circling at r0 with θ̇1² = m2 g/(m1 r0) holds m2 still with the tension m2 g; E and
// m1 r1² θ̇1 are conserved.
TEST(StringThroughHole, RelativeEquilibrium) {
  const test::ModelRun run = test::run_model("string-through-hole");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double w = std::sqrt(m2 * g / (m1 * r0));
  for (std::size_t i = 0; i < run.rows.size(); i += 10) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), r0 * std::cos(w * t), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "y1"), r0 * std::sin(w * t), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "z2"), -(L0 - r0), 1e-12) << t;
    EXPECT_NEAR(run.at(i, "tension"), m2 * g, 1e-9) << t;
  }
  EXPECT_LT(run.summary.energy_relative_drift, 1e-12);
}

// Ė = −μ_d m1 g |v1| (§5.5): the string's work cancels (ṙ1 + Ṙ2 = 0) and the table's normal force
// is m1 g. Checked by Simpson's rule over the rows while m1 slides and m2 swings.
TEST(StringThroughHole, FrictionDissipation) {
  const double mu_d = 0.1;
  const test::ModelRun run =
      test::run_model("string-through-hole", {{"mu_d", mu_d}, {"der(x2)", 0.3}},
                      [](SimulationOptions& o) { o.t_end = 1.0; })
          .on_grid(0.01);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size(), 101u);
  double integral = 0;  // ∫ |v1| dt
  for (std::size_t i = 0; i + 2 < run.rows.size(); i += 2) {
    integral +=
        0.01 / 3 * (run.at(i, "speed1") + 4 * run.at(i + 1, "speed1") + run.at(i + 2, "speed1"));
  }
  const double lost = run.at(0, "energy") - run.rows.back()[run.index("energy")];
  EXPECT_NEAR(lost, mu_d * m1 * g * integral, 1e-8);
  EXPECT_GT(lost, 0.5);
  for (std::size_t i = 0; i < run.rows.size(); ++i) EXPECT_GT(run.at(i, "tension"), 0.0);
}

// Thrown up at 3 m/s, m2 slackens the string at once: both fly free (m2 a projectile, m1 on a
// straight line) until |r1| + |r2| = L0, where the string jerks taut (plastic).
TEST(StringThroughHole, SlackThenTaut) {
  const test::ModelRun run = test::run_model("string-through-hole", {{"der(z2)", 3.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_GE(run.summary.phases.size(), 3u);
  EXPECT_EQ(run.summary.phases[0].what, "'string' free");
  EXPECT_TRUE(run.summary.phases[2].what.starts_with("contact 'string' made"))
      << run.summary.phases[2].what;
  // the free flight: |r1| = √(r0² + (v1 t)²), |r2| = −z2(t)
  const double v1 = std::sqrt(m2 * g * r0 / m1);
  const auto slack = [&](double t) {
    return L0 - std::hypot(r0, v1 * t) - std::abs(-(L0 - r0) + 3 * t - g * t * t / 2);
  };
  double lo = 0.1, hi = 1.0;  // slack(lo) > 0 > slack(hi)
  for (int i = 0; i < 200; ++i) (slack((lo + hi) / 2) > 0 ? lo : hi) = (lo + hi) / 2;
  EXPECT_NEAR(run.summary.phases[2].t, hi, 1e-9);
  for (std::size_t i = 0; i < run.rows.size() && run.at(i, "t") < hi; ++i) {
    EXPECT_EQ(run.at(i, "tension"), 0.0);
  }
}

}  // namespace
}  // namespace unidyn
