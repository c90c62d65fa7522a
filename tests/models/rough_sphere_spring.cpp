// Problem 2.7(a)–(g): a particle sliding inside a rough sphere, tied by a spring.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// While it slides, the constraint force's power is the friction's, −μ_d |N| |v| (the normal force
// does no work on the fixed sphere), so E = T + U (gravity and spring) decreases (2.7(g)).
TEST(RoughSphereSpring, FrictionTakesEnergyAtMuNv) {
  const double mu_d = 0.15;
  const test::ModelRun run = test::run_model("rough-sphere-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);  // it slides throughout
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double N = run.at(i, "N"), v = run.at(i, "speed");
    EXPECT_NEAR(run.at(i, "power"), -mu_d * N * v, 1e-11) << run.at(i, "t");
    EXPECT_GT(v, 0.1);
    if (i > 0) {
      EXPECT_LT(run.at(i, "E"), run.at(i - 1, "E")) << run.at(i, "t");
    }
  }
}

}  // namespace
}  // namespace unidyn
