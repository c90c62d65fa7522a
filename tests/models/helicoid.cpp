// Exercise 3.5: a particle on a smooth helicoid z = αθ under gravity.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// (3.24): d/dt(m (r² + α²) θ̇) = −m g α, so p = m (r² + α²) θ̇ falls linearly, p(t) = p(0) − m g α t;
// r̈ = r θ̇²; and H_O·E3 = m r² θ̇ is not conserved (it changes sign here).
TEST(Helicoid, Equations324AndTheAngularMomentumNotConserved) {
  const double m = 1.0, g = 9.81, alpha = 0.3;
  const test::ModelRun run = test::run_model("helicoid");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double least = 1e9, most = -1e9;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "p_theta"), run.at(0, "p_theta") - m * g * alpha * t, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "rdd"), run.at(i, "r") * std::pow(run.at(i, "der(theta)"), 2), 1e-10);
    least = std::min(least, run.at(i, "H3"));
    most = std::max(most, run.at(i, "H3"));
  }
  EXPECT_LT(least, 0.0);
  EXPECT_GT(most, 0.0);
}

}  // namespace
}  // namespace unidyn
