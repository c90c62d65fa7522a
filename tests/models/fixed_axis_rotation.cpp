// Exercise 8.1: ω·g³ = 0 and ω·g² = 0 leave a rotation about the fixed first Euler axis.
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/rotation/euler_angles.hpp"

namespace unidyn {
namespace {

// With 3-1-3 angles held at θ = 0.7, φ = 0.4: ω = ψ̇ E3 with ψ̇ constant (no moment, and E3·J E3
// fixed), ω·g³ = ω·g² = 0 for the dual Euler basis (6.44) computed here from the angles, and
// T_rot = ½ ψ̇² (λ1 sin²φ sin²θ + λ2 cos²φ sin²θ + λ3 cos²θ) from (10.5); H = J ω is not along E3.
TEST(FixedAxisRotation, AboutTheFirstEulerAxisOfExercise81) {
  const double l1 = 2.0, l2 = 3.0, l3 = 4.0, theta = 0.7, phi = 0.4, rate = 1.3;
  const test::ModelRun run = test::run_model("fixed-axis-rotation");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double T =
      0.5 * rate * rate *
      (l1 * std::pow(std::sin(phi) * std::sin(theta), 2) +
       l2 * std::pow(std::cos(phi) * std::sin(theta), 2) + l3 * std::pow(std::cos(theta), 2));
  const EulerSet set{3, 1, 3};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Vec3 omega(run.at(i, "omega.x"), run.at(i, "omega.y"), run.at(i, "omega.z"));
    EXPECT_LT((omega - rate * Vec3(0, 0, 1)).norm(), 1e-12) << run.at(i, "t");
    const Tensor dual = dual_euler_basis(set, Vec3(run.at(i, "psi"), theta, phi));
    EXPECT_NEAR(omega.dot(dual.col(1)), 0.0, 1e-12);
    EXPECT_NEAR(omega.dot(dual.col(2)), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "T_rot"), T, 1e-12);
    EXPECT_GT(std::hypot(run.at(i, "H.x"), run.at(i, "H.y")), 0.1);
  }
}

}  // namespace
}  // namespace unidyn
