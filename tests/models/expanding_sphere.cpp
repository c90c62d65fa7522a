// §3.5, (3.9)–(3.11): a particle on a smooth sphere of radius d(t) with a force D R e_θ.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// (3.10): d/dt(m d² sin²φ θ̇) = D d² sin φ — p_θ(t) − p_θ(0) is the integral of D d² sin φ
// (Simpson's rule on the 1 ms grid); (3.11): the multiplier of R − d(t) = 0 is λ = m d̈ − m d sin²φ
// θ̇² − m d φ̇² + m g cos φ.
TEST(ExpandingSphere, ApproachTwoAndTheMultiplierOfApproachOne) {
  const double m = 1.0, g = 9.81, d0 = 1.0, a = 0.2, w = 2.0;
  const test::ModelRun run = test::run_model("expanding-sphere");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const std::vector<double> impulse = test::running_integral(run, "source");
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), d = d0 + a * std::sin(w * t),
                 d2 = -a * w * w * std::sin(w * t), phi = run.at(i, "phi");
    const double lambda = m * d2 - m * d * std::pow(std::sin(phi) * run.at(i, "der(theta)"), 2) -
                          m * d * std::pow(run.at(i, "der(phi)"), 2) + m * g * std::cos(phi);
    EXPECT_NEAR(run.at(i, "lambda(sphere)"), lambda, 1e-10) << t;
    if (i % 2 == 1) continue;
    EXPECT_NEAR(run.at(i, "p_theta") - run.at(0, "p_theta"), impulse[i], 1e-9) << t;
  }
}

}  // namespace
}  // namespace unidyn
