// Exercise 3.8(b): a particle on a smooth parabola, in the non-orthogonal coordinates (1.6).
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// With q² = x − y² = −4 and z = 0 held, T = (m/2)(1 + 4y²) ẏ²: m (1 + 4y²) ÿ + 4 m y ẏ² = −m g; the
// constraint force is normal to the wire's tangent a₁ = 2y E1 + E2.
TEST(ParabolaWire, EquationOfMotionAndNormalConstraintForce) {
  const double g = 9.81;
  const test::ModelRun run = test::run_model("parabola-wire");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double y = run.at(i, "q1"), v = run.at(i, "der(q1)");
    EXPECT_NEAR(run.at(i, "ydd"), (-g - 4 * y * v * v) / (1 + 4 * y * y), 1e-11) << run.at(i, "t");
    EXPECT_NEAR(2 * y * run.at(i, "Fc.x") + run.at(i, "Fc.y"), 0.0, 1e-11);
    EXPECT_NEAR(run.at(i, "q2"), -4.0, 1e-12);
  }
}

}  // namespace
}  // namespace unidyn
