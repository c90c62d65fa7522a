// A particle on a smooth cone with a spring (§2.9, (2.22), dimensionless): h = R² cos²α θ̇ is
// conserved and R follows the one-degree-of-freedom equation (2.22) with the normal force from the
// e_φ component of (2.20).
#include <cmath>
#include <numbers>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// Released at R0 = 1.8 with h = 5 (α = 20°, ω² = 10): along the motion
//   R'' = h²/(R³ cos²α) − ω² (R − 1) − sin α                                 (2.22)
//   |N| = cos α + h² tan α/(R³ cos²α)   (the notes' correction of the printed n)
// and R oscillates about the circular orbit w0 = 1.6252669 (between 1.8 and its turning point).
TEST(SmoothCone, RadialEquationAndNormalForceAlongTheMotion) {
  const double alpha = std::numbers::pi / 9, h = 5, omega2 = 10, c2 = std::pow(std::cos(alpha), 2);
  const test::ModelRun run = test::run_model("smooth-cone");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double least = 1e9, most = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double R = run.at(i, "R");
    least = std::min(least, R);
    most = std::max(most, R);
    EXPECT_NEAR(run.at(i, "h"), h, 1e-10);
    EXPECT_NEAR(run.at(i, "Rdd"), h * h / (R * R * R * c2) - omega2 * (R - 1) - std::sin(alpha),
                1e-9);
    EXPECT_NEAR(run.at(i, "normal"), std::cos(alpha) + h * h * std::tan(alpha) / (R * R * R * c2),
                1e-9);
  }
  EXPECT_NEAR(most, 1.8, 1e-9);
  EXPECT_LT(least, 1.6252669);
}

}  // namespace
}  // namespace unidyn
