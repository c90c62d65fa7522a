// Exercise 11.2(c), (11.13)–(11.15): a rod strikes a smooth floor with one end.
#include <cmath>
#include <string>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// Before the impact the rod flies freely: z = 1 − g t²/2, θ = 0.5 + t, ẋ = 0.3. Its lower end
// A = x̄ − (L/2) e3 reaches the floor when z − (L/2) cos θ = 0 (found here by bisection). The
// floor's impulse I E3 at A jumps the momenta (11.15): [[m ż]] = I, [[J θ̇]] = (L/2) sin θ I,
// [[m ẋ]] = 0, with J = m L²/12, and the end rebounds, ż_A⁺ = −e ż_A⁻ with ż_A = ż + (L/2) sin θ θ̇,
// so I = −(1 + e) ż_A⁻ / (1/m + (L/2)² sin²θ / J).
TEST(RodImpact, ImpulseAndJumpsOfElevenFifteen) {
  const double m = 1.0, g = 9.81, L = 1.0, e = 0.5, J = m * L * L / 12;
  const auto gap = [&](double t) { return 1 - g * t * t / 2 - L / 2 * std::cos(0.5 + t); };
  double lo = 0.0, hi = 0.5;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (gap(lo) * gap(mid) <= 0 ? hi : lo) = mid;
  }
  const double t_hit = 0.5 * (lo + hi), theta = 0.5 + t_hit, arm = L / 2 * std::sin(theta);
  const double zA_rate = -g * t_hit + arm * 1.0;
  const double impulse = -(1 + e) * zA_rate / (1 / m + arm * arm / J);

  const test::ModelRun run = test::run_model("rod-impact");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_NEAR(run.summary.phases[1].t, t_hit, 1e-12);
  // "impact on 'floor': rate … -> … (restitution 0.5), impulse I"
  const std::string& what = run.summary.phases[1].what;
  ASSERT_TRUE(what.starts_with("impact on 'floor'")) << what;
  EXPECT_NEAR(std::stod(what.substr(what.rfind(' ') + 1)), impulse, 1e-12) << what;
  // the event's row holds the state just after the impact
  bool found = false;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    if (std::abs(run.at(i, "t") - t_hit) > 1e-12) continue;
    found = true;
    EXPECT_NEAR(run.at(i, "der(x)"), 0.3, 1e-12);
    EXPECT_NEAR(run.at(i, "der(z)"), -g * t_hit + impulse / m, 1e-10);
    EXPECT_NEAR(run.at(i, "der(theta)"), 1.0 + arm * impulse / J, 1e-10);
    EXPECT_NEAR(run.at(i, "der(z)") + arm * run.at(i, "der(theta)"), -e * zA_rate, 1e-10);
  }
  EXPECT_TRUE(found);
}

}  // namespace
}  // namespace unidyn
