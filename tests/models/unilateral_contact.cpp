// Unilateral constraints and events (§2.6, §2.10, Problem 2.7(i)): a particle leaves a smooth
// sphere where its normal force reaches 0, then flies free, and leaves a rough one later; a ball
// bounces on a table with restitution e; stop_when ends a run where its expression reaches 0.
#include <algorithm>
#include <cmath>
#include <cstdio>

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

// Simpson's rule for ∫ f over [a, b], n (even) intervals.
template <class F>
double simpson(const F& f, double a, double b, int n) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return sum * h / 3;
}

// The run from x = R0 sin φ0, z = R0 cos φ0 (θ0 = 0) with the rates φ̇0, θ̇0 on the smooth sphere:
// v0 = R0 (φ̇0 e_φ + sin φ0 θ̇0 e_θ), e_φ = (cos φ0, 0, −sin φ0), e_θ = E2.
test::ModelRun run_from(double phi0_, double phi_rate, double theta_rate) {
  const double sp = std::sin(phi0_), cp = std::cos(phi0_);
  return test::run_model("particle-leaving-sphere", {{"x", R0 * sp},
                                                     {"z", R0 * cp},
                                                     {"der(x)", R0 * phi_rate * cp},
                                                     {"der(y)", R0 * sp * theta_rate},
                                                     {"der(z)", -R0 * phi_rate * sp}});
}

// Problem 2.7(i), the corollary: at the top N = m g − m v0²/R0 (the criterion with φ = φ0 = 0),
// so with v0 = 1.01 √(g R0) the particle leaves at once: the contact is free from the start, the
// sphere never pushes (λ = 0 on every row) and the particle is the projectile x = v0 t,
// z = R0 − g t²/2, which stays outside the sphere (x² + z² − R0² = (v0² − g R0) t² + g² t⁴/4 > 0).
// With v0 = 0.99 √(g R0) it stays on with N(0) = m g − m v0²/R0 > 0 for a finite time and leaves
// where cos φ1 = (2 + v0²/(g R0))/3, at t1 = ∫_0^φ1 dφ/φ̇ with φ̇² = v0²/R0² + (2g/R0)(1 − cos φ)
// (Simpson).
TEST(UnilateralContact, LeavesTheTopAtOnceOnlyAboveRootGR0) {
  const double v_crit = std::sqrt(g * R0);
  {
    const double v0 = 1.01 * v_crit;
    const test::ModelRun run = run_from(0, v0 / R0, 0);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    EXPECT_EQ(run.summary.phases[0].what, "'surface' free");
    EXPECT_EQ(run.summary.phases[0].t, 0.0);
    for (const auto& phase : run.summary.phases) {
      EXPECT_FALSE(phase.what.starts_with("contact 'surface' made")) << phase.t;
    }
    // apart, the rough contact neither sticks nor slides: the start says only that it is free
    ASSERT_EQ(run.summary.phases.size(), 2u);
    EXPECT_EQ(run.summary.phases.back().what, "stop_when 'z + R0' reached 0");
    double projectile_error = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t");
      EXPECT_EQ(run.at(i, "lambda(surface)"), 0.0) << t;
      projectile_error = std::max({projectile_error, std::abs(run.at(i, "x") - v0 * t),
                                   std::abs(run.at(i, "z") - (R0 - g * t * t / 2))});
      if (t > 0) {
        EXPECT_GT(run.at(i, "x") * run.at(i, "x") + run.at(i, "z") * run.at(i, "z"), R0 * R0);
      }
    }
    EXPECT_LT(projectile_error, 1e-10);
    std::printf("2.7(i) v0 = 1.01 √(gR0): free from t = 0, projectile to %.3g m over %zu rows\n",
                projectile_error, run.rows.size());
  }
  {
    const double v0 = 0.99 * v_crit, w0_ = v0 / R0;
    const test::ModelRun run = run_from(0, w0_, 0);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    ASSERT_GE(run.summary.phases.size(), 3u);
    EXPECT_EQ(run.summary.phases[0].what, "'surface' in contact");
    EXPECT_EQ(run.summary.phases[2].what, "contact 'surface' lost (its force reached 0)");
    const double m = run.parameter("m");
    EXPECT_NEAR(run.at(0, "normal_force"), m * g - m * v0 * v0 / R0, 1e-12);
    EXPECT_GT(run.at(0, "normal_force"), 0.19);
    const double cos_phi1 = (2 + v0 * v0 / (g * R0)) / 3, phi1 = std::acos(cos_phi1);
    const double t1 = simpson(
        [&](double phi) { return 1 / std::sqrt(w0_ * w0_ + 2 * g / R0 * (1 - std::cos(phi))); }, 0,
        phi1, 20000);
    const double t_lost = run.summary.phases[2].t;
    EXPECT_GT(t_lost, 0.03);
    EXPECT_NEAR(t_lost, t1, 1e-10);
    const auto lost = std::find_if(run.rows.begin(), run.rows.end(),
                                   [&](const std::vector<double>& r) { return r[0] == t_lost; });
    ASSERT_NE(lost, run.rows.end());
    const double cos_at_loss = (*lost)[run.index("cos_phi")];
    EXPECT_NEAR(cos_at_loss, cos_phi1, 1e-10);
    std::printf(
        "2.7(i) v0 = 0.99 √(gR0): leaves at t = %.6f, %.3g s from Simpson's; cos φ %.3g "
        "from the book's\n",
        t_lost, std::abs(t_lost - t1), std::abs(cos_at_loss - cos_phi1));
  }
}

// Problem 2.7(i), the criterion with both rates: from φ0 = 0.3 with φ̇0 = 0.4, θ̇0 = 1.5 the
// motion is not planar; N = m g (3 cos φ − 2 cos φ0) − m R0 (φ̇0² + sin²φ0 θ̇0²) vanishes at
// cos φ1 = (2 cos φ0 + R0 (φ̇0² + sin²φ0 θ̇0²)/g)/3, reached at t1 = ∫ dφ/φ̇ with (energy and
// H_O·E3 = m R0² sin²φ θ̇ = m R0² k conserved) φ̇² = φ̇0² + sin²φ0 θ̇0² − k²/sin²φ
// + (2g/R0)(cos φ0 − cos φ), φ̇ > 0 on [φ0, φ1] (Simpson).
TEST(UnilateralContact, LeavesWhereTheBooksCriterionFailsWithBothRates) {
  const double phi_0 = 0.3, phi_rate = 0.4, theta_rate = 1.5;
  const test::ModelRun run = run_from(phi_0, phi_rate, theta_rate);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_GE(run.summary.phases.size(), 3u);
  EXPECT_EQ(run.summary.phases[0].what, "'surface' in contact");
  EXPECT_EQ(run.summary.phases[2].what, "contact 'surface' lost (its force reached 0)");
  const double sp0 = std::sin(phi_0), c = phi_rate * phi_rate + sp0 * sp0 * theta_rate * theta_rate;
  const double k = sp0 * sp0 * theta_rate;
  const double cos_phi1 = (2 * std::cos(phi_0) + R0 * c / g) / 3, phi1 = std::acos(cos_phi1);
  const double t1 = simpson(
      [&](double phi) {
        const double s = std::sin(phi);
        return 1 / std::sqrt(c - k * k / (s * s) + 2 * g / R0 * (std::cos(phi_0) - std::cos(phi)));
      },
      phi_0, phi1, 20000);
  const double t_lost = run.summary.phases[2].t;
  EXPECT_NEAR(t_lost, t1, 1e-10);
  const auto lost = std::find_if(run.rows.begin(), run.rows.end(),
                                 [&](const std::vector<double>& r) { return r[0] == t_lost; });
  ASSERT_NE(lost, run.rows.end());
  const double cos_at_loss = (*lost)[run.index("cos_phi")];
  EXPECT_NEAR(cos_at_loss, cos_phi1, 1e-10);
  EXPECT_GT(std::abs((*lost)[run.index("y")]), 0.05);  // it has gone round, off the plane y = 0
  // before the loss the sphere pushes with the criterion's value of N
  double normal_error = 0;
  for (std::size_t i = 0; i < run.rows.size() && run.at(i, "t") < t_lost; ++i) {
    const double m = run.parameter("m"), cos_phi = run.at(i, "cos_phi");
    const double N = m * g * (3 * cos_phi - 2 * std::cos(phi_0)) - m * R0 * c;
    normal_error = std::max(normal_error, std::abs(run.at(i, "normal_force") - N));
    EXPECT_GT(run.at(i, "normal_force"), 0.0);
  }
  EXPECT_LT(normal_error, 1e-9);
  std::printf(
      "2.7(i) φ0 = 0.3, φ̇0 = 0.4, θ̇0 = 1.5: leaves at t = %.6f, %.3g s from Simpson's; "
      "cos φ %.3g from the book's; N vs the criterion %.3g N\n",
      t_lost, std::abs(t_lost - t1), std::abs(cos_at_loss - cos_phi1), normal_error);
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
