// Exercise 3.6: a particle inside a smooth sphere, until it leaves the wall.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// While on the wall the force along e_R is N = 3 m g cos φ − 2 E0/R0 (cos φ = z/R0), never
// positive (the wall pushes inwards); the particle leaves where it reaches 0, cos φ = 2 E0/(3 m g
// R0) (3.6(e)); H_O·E3 is conserved throughout.
TEST(InsideSphere, WallForceAndWhereTheParticleLeaves) {
  const double m = 1.0, g = 9.81, R0 = 1.0;
  const test::ModelRun run = test::run_model("inside-sphere");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double v2 = std::pow(run.at(0, "der(x)"), 2) + std::pow(run.at(0, "der(y)"), 2) +
                    std::pow(run.at(0, "der(z)"), 2);
  const double E0 = m * v2 / 2 + m * g * run.at(0, "z");
  ASSERT_GE(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what, "contact 'wall' lost (its force reached 0)");
  const double t_lost = run.summary.phases[1].t;
  for (std::size_t i = 0; i < run.rows.size() && run.at(i, "t") < t_lost; ++i) {
    const double N = 3 * m * g * run.at(i, "z") / R0 - 2 * E0 / R0;
    EXPECT_NEAR(run.at(i, "N_R"), N, 1e-9) << run.at(i, "t");
    EXPECT_LE(N, 1e-9);
  }
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    if (std::abs(run.at(i, "t") - t_lost) > 1e-12) continue;
    EXPECT_NEAR(run.at(i, "z") / R0, 2 * E0 / (3 * m * g * R0), 1e-9);
  }
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-10);
}

}  // namespace
}  // namespace unidyn
