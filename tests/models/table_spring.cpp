// Problem 2.5: a particle on a smooth table tied to a fixed point by a spring.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The spring's force is central: A = ½ r² θ̇ E3 stays at its initial value (2.5(a), (e)); and r
// follows (2.32), in dimensional form r̈ = h²/r³ − (K/m)(r − L0) with h = r² θ̇ = 2|A|.
TEST(TableSpring, ArealVelocityAndEquation232) {
  const double m = 0.5, K = 8.0, L0 = 1.0, h = 1.3 * 1.3 * 2.0;
  const test::ModelRun run = test::run_model("table-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double least = 1e9, most = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double r = run.at(i, "r");
    least = std::min(least, r);
    most = std::max(most, r);
    EXPECT_NEAR(run.at(i, "A.z"), h / 2, 1e-11) << run.at(i, "t");
    EXPECT_NEAR(run.at(i, "A.x"), 0.0, 1e-15);
    EXPECT_NEAR(run.at(i, "rdd"), h * h / (r * r * r) - K / m * (r - L0), 1e-9) << run.at(i, "t");
  }
  EXPECT_GT(most - least, 0.1);  // not the circular orbit
}

}  // namespace
}  // namespace unidyn
