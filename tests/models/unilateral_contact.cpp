// Unilateral constraints and events (§2.6, §2.10, Problem 2.7(i)): a particle leaves a smooth
// sphere where its normal force reaches 0, then flies free, and leaves a rough one later; a ball
// bounces on a table with restitution e; stop_when ends a run where its expression reaches 0.
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/driver.hpp"

namespace unidyn {
namespace {

constexpr double g = 9.81, R0 = 1.0, phi0 = 0.2, w0 = 0.5;

// Problem 2.7(i): N = m g (3 cos φ − 2 cos φ0) − m R0 φ̇0² vanishes at cos φ1 = (2 cos φ0 +
// R0 φ̇0²/g)/3, reached at t1 = ∫ dφ/φ̇ with φ̇² = φ̇0² + (2g/R0)(cos φ0 − cos φ) (energy).
TEST(UnilateralContact, ParticleLeavesTheSphereWhereItsForceVanishes) {
  const test::ModelRun run = test::run_model("particle-leaving-sphere");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 4u);
  EXPECT_EQ(run.summary.phases[0].what, "'surface' in contact");
  EXPECT_EQ(run.summary.phases[1].what, "'surface' slides");  // with μ_d = 0
  EXPECT_EQ(run.summary.phases[2].what, "contact 'surface' lost (its force reached 0)");
  const double cos_phi1 = (2 * std::cos(phi0) + R0 * w0 * w0 / g) / 3, phi1 = std::acos(cos_phi1);
  // t1 by Simpson's rule (the integrand is smooth: φ̇ ≥ w0 on [φ0, φ1])
  const int intervals = 20000;
  const double h = (phi1 - phi0) / intervals;
  const auto inverse_rate = [&](double phi) {
    return 1 / std::sqrt(w0 * w0 + 2 * g / R0 * (std::cos(phi0) - std::cos(phi)));
  };
  double t1 = inverse_rate(phi0) + inverse_rate(phi1);
  for (int i = 1; i < intervals; ++i) t1 += (i % 2 ? 4 : 2) * inverse_rate(phi0 + i * h);
  t1 *= h / 3;
  EXPECT_NEAR(run.summary.phases[2].t, t1, 1e-10);
  // on the sphere the force pushes; off it (from the event's own row on) λ = 0 and the particle
  // is a projectile
  const double t_lost = run.summary.phases[2].t;
  std::size_t first_free = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (t < t_lost) {
      EXPECT_GT(run.at(i, "normal_force"), 0.0) << t;
      continue;
    }
    if (!first_free) first_free = i;
    EXPECT_EQ(run.at(i, "lambda(surface)"), 0.0) << t;
    EXPECT_NEAR(run.at(i, "der(x)"), run.at(first_free, "der(x)"), 1e-11) << t;
    EXPECT_NEAR(run.at(i, "der(z)"),
                run.at(first_free, "der(z)") - g * (t - run.at(first_free, "t")), 1e-10)
        << t;
  }
  EXPECT_NEAR(run.at(first_free - 1, "cos_phi"), cos_phi1, 1e-3);  // the row just before
  // stop_when: z + R0 reaches 0, the run ends there (before t_end = 1.5)
  EXPECT_TRUE(run.summary.stopped);
  EXPECT_EQ(run.summary.phases[3].what, "stop_when 'z + R0' reached 0");
  EXPECT_LT(run.rows.back()[0], 1.5);
  EXPECT_LE(run.rows.back()[0], run.summary.phases[3].t);
}

// Friction and a unilateral contact on one constraint: on the rough sphere (μ_d = 0.3) the
// particle slides with m R0 φ̈ = m g sin φ − μ_d N, N = m g cos φ − m R0 φ̇² (the normal force of
// the current multiplier), and leaves where N = 0 — located here on the hand-written φ equation
// with the driver's events, independently of the model's equations. Off the sphere no friction.
TEST(UnilateralContact, ParticleLeavesARoughSphere) {
  const double mu = 0.3;
  const test::ModelRun run = test::run_model("particle-leaving-sphere", {{"mu_d", mu}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 4u);
  EXPECT_EQ(run.summary.phases[2].what, "contact 'surface' lost (its force reached 0)");
  const double t_lost = run.summary.phases[2].t;
  // (φ, φ̇) by hand, with the event N = 0
  DormandPrinceOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  DormandPrince54 hand(
      [mu](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        const double normal = g * std::cos(y[0]) - R0 * y[1] * y[1];  // per unit mass
        dydt << y[1], (g * std::sin(y[0]) - mu * normal) / R0;
      },
      options);
  std::vector<std::pair<double, Eigen::VectorXd>> rows;
  double t1 = 0;
  IntegrationCallbacks callbacks;
  callbacks.output = [&rows](double t, const Eigen::VectorXd& y) { rows.push_back({t, y}); };
  callbacks.events = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& normal) {
    normal.resize(1);
    normal[0] = g * std::cos(y[0]) - R0 * y[1] * y[1];
  };
  callbacks.on_event = [&t1](double t, Eigen::VectorXd&, std::size_t) {
    t1 = t;
    return AfterEvent::stop;
  };
  Eigen::VectorXd y0(2);
  y0 << phi0, w0 / R0;
  const IntegrationResult result = integrate(hand, 0, y0, 1.5, 0.001, callbacks);
  ASSERT_TRUE(result.stopped);
  EXPECT_NEAR(t_lost, t1, 1e-9);
  EXPECT_GT(t1, 0.9);  // friction holds it on much longer than the smooth sphere's 0.498
  for (std::size_t i = 0; i < rows.size() && rows[i].first < t1; i += 10) {
    const double phi = std::acos(run.at(i, "cos_phi"));
    EXPECT_NEAR(phi, rows[i].second[0], 1e-8) << rows[i].first;
    const double normal = g * std::cos(phi) - R0 * rows[i].second[1] * rows[i].second[1];
    EXPECT_NEAR(run.at(i, "normal_force"), normal, 1e-7) << rows[i].first;
  }
  // off the sphere a projectile: der(x) constant
  std::size_t free = 0;
  while (run.at(free, "t") <= t_lost) ++free;
  for (std::size_t i = free; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "der(x)"), run.at(free, "der(x)"), 1e-10);
  }
}

// §2.10: impacts at t1 = √(2h/g), then every 2 e^k v1/g; the bounces accumulate at
// t∞ = t1 (1 + e)/(1 − e), after which the table holds the ball with λ = m g. The smooth table
// leaves ẋ alone.
TEST(UnilateralContact, BouncingBallComesToRest) {
  const test::ModelRun run = test::run_model("bouncing-ball");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 0.5, h = 1.0, e = 0.8, t1 = std::sqrt(2 * h / g);
  const auto& phases = run.summary.phases;
  ASSERT_GT(phases.size(), 20u);
  EXPECT_EQ(phases[0].what, "'table' free");
  double expected = t1, speed = g * t1;
  for (std::size_t k = 1; k <= 20; ++k) {
    EXPECT_TRUE(phases[k].what.starts_with("impact on 'table'")) << phases[k].what;
    EXPECT_NEAR(phases[k].t, expected, 1e-9) << "impact " << k;
    speed *= e;
    expected += 2 * speed / g;
  }
  EXPECT_TRUE(phases.back().what.starts_with("contact 'table' made")) << phases.back().what;
  EXPECT_NEAR(phases.back().t, t1 * (1 + e) / (1 - e), 1e-5);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x"), 0.3 * t, 1e-12) << t;
    EXPECT_GE(run.at(i, "z"), -1e-12) << t;
    if (t >= phases.back().t) {  // from the contact's own row on
      EXPECT_NEAR(run.at(i, "z"), 0.0, 1e-12) << t;
      EXPECT_NEAR(run.at(i, "lambda(table)"), m * g, 1e-9) << t;
    } else {
      EXPECT_EQ(run.at(i, "lambda(table)"), 0.0) << t;
    }
  }
}

}  // namespace
}  // namespace unidyn
