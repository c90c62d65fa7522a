// The single-axis rate gyroscope (§11.4): the rotor's spin (11.7), the gimbal's steady deflection
// under a steady platform rate (11.10, with the editor's correction) and its rest when the
// platform does not turn.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double lam1 = 1e-4, lam2 = 2e-4, rho2 = 6e-5, rho3 = 7e-5, KA = 50 * 0.01, w30 = 0.5;

// (11.7) h = λ2 (β̇ + ω_p · e2) is constant: the rotor's moment has no e2 component.
TEST(RateGyroscope, SpinIsConserved) {
  const test::ModelRun run = test::run_model("rate-gyroscope");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_NEAR(run.summary.conserved_drift[0].initial, lam2 * 1000, 1e-15);
  EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-12 * lam2 * 1000);
}

// With the platform turning at Ω = ω30 about t3 the gimbal settles where the e1 component of
// Ḣ = M for gimbal + rotor balances the spring. In the steady state e2, e3 turn at Ω t3 and
// H = h e2 + λ1 Ω cos α e3 + J_g Ω t3, so (derived by hand from Ḣ = Ω t3 × H):
//   K A α0 = Ω h cos α0 − Ω² sin α0 cos α0 (ρ3 − ρ2 + λ1)
// and to first order α0 = λ2 β̇ Ω/(K A) (11.10).
TEST(RateGyroscope, SteadyRateGivesSteadyDeflection) {
  const test::ModelRun run = test::run_model("rate-gyroscope");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  const double alpha0 = run.at(last, "alpha"), h = lam2 * 1000;
  EXPECT_LT(std::abs(run.at(last, "der(alpha)")), 1e-5);  // the transient has died out
  const double balance = w30 * h * std::cos(alpha0) -
                         w30 * w30 * std::sin(alpha0) * std::cos(alpha0) * (rho3 - rho2 + lam1) -
                         KA * alpha0;
  EXPECT_LT(std::abs(balance), 1e-8 * KA * alpha0);
  // (11.10) neglects 1 − cos α0 ≈ α0²/2 ≈ 2 % here
  const double approximate = run.at(last, "alpha_11_10");
  EXPECT_NEAR(alpha0, approximate, 0.03 * approximate);
  EXPECT_GT(std::abs(alpha0 - approximate), 0.01 * approximate);
}

// (11.10): with α = 0 and ω3 = 0 the gimbal stays at α = 0 and the rotor spins on.
TEST(RateGyroscope, NoPlatformRateNoDeflection) {
  const test::ModelRun run = test::run_model("rate-gyroscope", {{"w30", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); i += 100) {
    EXPECT_EQ(run.at(i, "alpha"), 0.0);
    EXPECT_NEAR(run.at(i, "der(beta)"), 1000.0, 1e-9);
  }
}

}  // namespace
}  // namespace unidyn
