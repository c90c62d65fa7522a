// Exercise 9.14: a body about a fixed point with a spring and gravity (Fig. 9.7).
#include <cmath>
#include <string>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// H_O = (λ1 + m h²) ω1 e1 + (λ2 + m h²) ω2 e2 + λ3 ω3 e3 (9.14(b), x̄ − x_O = h e3) along the
// motion, and E (spring and gravity) is conserved.
TEST(TopSpring, AngularMomentumAboutTheFixedPoint) {
  const double m = 1.0, h = 0.2, l[3] = {0.02, 0.03, 0.015};
  const test::ModelRun run = test::run_model("top-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  const double coefficient[3] = {l[0] + m * h * h, l[1] + m * h * h, l[2]};
  const char* xyz[3] = {".x", ".y", ".z"};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double w[3] = {run.at(i, "w1"), run.at(i, "w2"), run.at(i, "w3")};
    for (int c = 0; c < 3; ++c) {
      double H = 0;
      for (int k = 0; k < 3; ++k) {
        H += coefficient[k] * w[k] * run.at(i, "b" + std::to_string(k + 1) + xyz[c]);
      }
      EXPECT_NEAR(run.at(i, std::string("H_O") + xyz[c]), H, 1e-13) << run.at(i, "t");
    }
  }
}

}  // namespace
}  // namespace unidyn
