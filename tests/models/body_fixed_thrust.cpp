// Exercise 9.2: a free body with a body-fixed thrust F_a e3 at its centre of mass.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// No moment: the rotation is the torque-free one — from ω(0) = 0.5 E2 + 5 E3 with λ = (2, 4, 5) it
// reaches the book's ω(10) ≈ (0.2800, 0.3638, 5.0063) of Fig. 9.2 — and m x̄̈ = F_a e3, so the
// centre's velocity is (F_a/m) ∫ e3 dt (Simpson's rule on the 1 ms grid).
TEST(BodyFixedThrust, TorqueFreeRotationAndThrustAlongE3) {
  const double m = 2.0, F = 3.0;
  const test::ModelRun run = test::run_model("body-fixed-thrust");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_NEAR(run.at(last, "t"), 10.0, 1e-12);
  EXPECT_NEAR(run.at(last, "w1"), 0.2800, 5e-5);
  EXPECT_NEAR(run.at(last, "w2"), 0.3638, 5e-5);
  EXPECT_NEAR(run.at(last, "w3"), 5.0063, 5e-5);
  ASSERT_EQ(last % 2, 0u);
  const char* e3[3] = {"e3_.x", "e3_.y", "e3_.z"};
  const char* rate[3] = {"der(x)", "der(y)", "der(z)"};
  for (int k = 0; k < 3; ++k) {
    const std::vector<double> e3_integral = test::running_integral(run, e3[k]);
    for (std::size_t i = 2; i <= last; i += 2) {
      EXPECT_NEAR(run.at(i, rate[k]), F / m * e3_integral[i], 1e-9) << run.at(i, "t");
    }
  }
}

}  // namespace
}  // namespace unidyn
