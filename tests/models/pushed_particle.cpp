// Problem 2.4: a particle on a table pushed by a moving plane.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The plane x1 = f(t) = t²/2 + 0.1 sin 2t pushes with λ2 = m f̈ = m (1 − 0.4 sin 2t) along E1, the
// table holds the weight, λ1 = m g; x2 moves uniformly; F_c = λ1 E3 + λ2 E1.
TEST(PushedParticle, TheMovingPlanesForceIsMassTimesItsAcceleration) {
  const double m = 2.0, g = 9.81;
  const test::ModelRun run = test::run_model("pushed-particle");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), f2 = 1 - 0.4 * std::sin(2 * t);
    EXPECT_NEAR(run.at(i, "lambda(table)"), m * g, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "lambda(plane)"), m * f2, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "Fc.x"), m * f2, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "Fc.z"), m * g, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "x1"), t * t / 2 + 0.1 * std::sin(2 * t), 1e-10) << t;
    EXPECT_NEAR(run.at(i, "x2"), 0.7 * t, 1e-10) << t;
  }
}

}  // namespace
}  // namespace unidyn
