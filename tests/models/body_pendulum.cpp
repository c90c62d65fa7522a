// Exercises 8.5 and 10.1: an axisymmetric body on a pivot, its spin stopped (1-3-1 angles).
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// With φ̇ = 0: T = ½ (λ1 ψ̇² cos²θ + λ (θ̇² + ψ̇² sin²θ)) and U = −m g L0 cos θ (10.47); ψ is
// cyclic, so p_ψ = (λ1 cos²θ + λ sin²θ) ψ̇ is conserved (10.48), and so is E.
TEST(BodyPendulum, KineticAndPotentialEnergyOf1047) {
  const double m = 1.0, g = 9.81, L0 = 0.5, l1 = 0.01, lam = 0.3;
  const test::ModelRun run = test::run_model("body-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double th = run.at(i, "theta"), psd = run.at(i, "der(psi)"),
                 thd = run.at(i, "der(theta)");
    const double T = 0.5 * (l1 * psd * psd * std::pow(std::cos(th), 2) +
                            lam * (thd * thd + psd * psd * std::pow(std::sin(th), 2)));
    EXPECT_NEAR(run.at(i, "T"), T, 1e-13) << run.at(i, "t");
    EXPECT_NEAR(run.at(i, "U"), -m * g * L0 * std::cos(th), 1e-13);
    EXPECT_EQ(run.at(i, "der(phi)"), 0.0);
  }
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-11);
}

}  // namespace
}  // namespace unidyn
