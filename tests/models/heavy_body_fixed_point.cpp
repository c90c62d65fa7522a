// A heavy asymmetric body about a fixed point (§9.7 (9.22)–(9.25), §10.8's general offsets).
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// E and H_O·E3 are conserved (gravity's moment about O is horizontal), and the kinetic energy is
// T = ½ ω·J_O ω with J_O = J + m (|c|² I − c⊗c), c = L1 e1 + L2 e2 + L3 e3 (7.25) — the cross
// terms −m L_i L_j ω_i ω_j included, which §10.8's printed T leaves out.
TEST(HeavyBodyFixedPoint, IntegralsAndKineticEnergyAboutTheFixedPoint) {
  const double m = 1.0, A = 0.004, B = 0.006, C = 0.008;
  const double c[3] = {0.01, -0.02, 0.05}, J[3] = {A, B, C};
  const test::ModelRun run = test::run_model("heavy-body-fixed-point");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_LT(run.summary.conserved_drift[0].max_change,
            1e-10 * std::abs(run.summary.conserved_drift[0].initial));
  const double c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double w[3] = {run.at(i, "w1"), run.at(i, "w2"), run.at(i, "w3")};
    double T = 0;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b) {
        const double JO = (a == b ? J[a] + m * c2 : 0.0) - m * c[a] * c[b];
        T += 0.5 * w[a] * JO * w[b];
      }
    }
    EXPECT_NEAR(run.at(i, "T"), T, 1e-11 * (1 + T)) << run.at(i, "t");
  }
}

}  // namespace
}  // namespace unidyn
