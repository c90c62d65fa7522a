// A particle on a rotating rough cone with a spring (§2.9, (2.20)): friction acts against the
// velocity relative to the turning surface (surface_velocity = Ω0 E3 × r).
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double m = 1.0, g = 9.81, alpha = 0.35, K = 40.0, L0 = 0.5, Omega0 = 3.0, mu_d = 0.2,
                 mu_s = 0.3;

// Stuck at R0 = 0.6 the particle turns with the cone, held by (§2.9)
// F_f = (K (R0 − L0) + m g sin α − m R0 cos²α Ω0²) e_R inside the static cone.
TEST(RotatingCone, StuckParticleTurnsWithTheCone) {
  const double R0 = 0.6, c = std::cos(alpha), s = std::sin(alpha);
  const double friction = K * (R0 - L0) + m * g * s - m * R0 * c * c * Omega0 * Omega0;
  const double normal = m * g * c + m * R0 * Omega0 * Omega0 * s * c;
  ASSERT_LE(std::abs(friction), mu_s * normal);  // the book's stick condition holds here
  const test::ModelRun run = test::run_model("rotating-cone");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what, "contact 'cone' sticks");
  for (std::size_t i = 0; i < run.rows.size(); i += 10) {
    EXPECT_NEAR(run.at(i, "R"), R0, 1e-12);
    EXPECT_NEAR(run.at(i, "thetad"), Omega0, 1e-12);
    EXPECT_NEAR(run.at(i, "contact_radial"), friction, 1e-9);
  }
}

// From R0 = 0.9 the static bound is exceeded: the particle slides, following (2.20)
//   m (R̈ − R cos²α θ̇²) = −K (R − L0) + F_f · e_R − m g sin α,
//   F_f = −μ_d |N| v_rel/|v_rel|, v_rel = Ṙ e_R + R cos α (θ̇ − Ω0) e_θ,
//   |N| = |m R sin α cos α θ̇² + m g cos α|   (the e_φ equation),
// until it sticks again where |F_f| ≤ μ_s |N|.
TEST(RotatingCone, SlidingFollowsEquation220) {
  const test::ModelRun run = test::run_model("rotating-cone", {{"R0", 0.9}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto& phases = run.summary.phases;
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_TRUE(phases[0].what.starts_with("contact 'cone' slides on")) << phases[0].what;
  EXPECT_EQ(phases[1].what, "contact 'cone' sticks");
  const double c = std::cos(alpha), s = std::sin(alpha);
  std::size_t checked = 0;
  for (std::size_t i = 0; i < run.rows.size() && run.at(i, "t") < phases[1].t; ++i) {
    const double R = run.at(i, "R"), Rd = run.at(i, "Rd"), Rdd = run.at(i, "Rdd");
    const double w = run.at(i, "thetad");
    const double slip = std::hypot(Rd, R * c * (w - Omega0));
    if (slip < 1e-3) continue;
    const double normal = std::abs(m * R * s * c * w * w + m * g * c);
    const double radial_friction = -mu_d * normal * Rd / slip;
    EXPECT_NEAR(m * (Rdd - R * c * c * w * w), -K * (R - L0) + radial_friction - m * g * s, 1e-8)
        << "t = " << run.at(i, "t");
    ++checked;
  }
  EXPECT_GT(checked, 50u);
  // where it sticks, the holding force is within the static cone
  const std::size_t last = run.rows.size() - 1;
  const double R = run.at(last, "R");
  const double holding = K * (R - L0) + m * g * s - m * R * c * c * Omega0 * Omega0;
  EXPECT_LE(std::abs(holding), mu_s * (m * g * c + m * R * Omega0 * Omega0 * s * c) + 1e-9);
  EXPECT_NEAR(run.at(last, "thetad"), Omega0, 1e-9);
}

}  // namespace
}  // namespace unidyn
