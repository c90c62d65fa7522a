// Particles on prescribed paths (rheonomic constraints that leave no freedom): the areal
// velocities of Examples 1.1 and 1.2 and the work of §2.3.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// Ex. 1.1: r = c E2 + 10 t E1 sweeps A = ½ r × v = −5 c E3; Ex. 1.2: r = 10 e_r with θ = ω t
// sweeps A = 50 ω E3; both constant.
TEST(PrescribedMotions, ArealVelocitiesOfExamples11And12) {
  const double c = 2.0, w = 1.5;
  const test::ModelRun run = test::run_model("prescribed-motions");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "A1.x"), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "A1.y"), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "A1.z"), -5 * c, 1e-10) << run.at(i, "t");
    EXPECT_NEAR(run.at(i, "A2.z"), 50 * w, 1e-9) << run.at(i, "t");
  }
}

// §2.3: the force P e_θ along the spiral r = L e^{αt}(cos ωt E1 + sin ωt E2) does the work
// W = (ω P L/α)(e^{α t_B} − e^{α t_A}); here its power's integral by Simpson's rule from t_A = 0.
TEST(PrescribedMotions, WorkAlongTheSpiralOfSection23) {
  const double w = 1.5, L = 0.5, alpha = 0.3, F = 2.0;
  const test::ModelRun run = test::run_model("prescribed-motions");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 2; i < run.rows.size(); i += 2) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(work[i], w * F * L / alpha * (std::exp(alpha * t) - 1), 1e-9) << t;
  }
}

}  // namespace
}  // namespace unidyn
