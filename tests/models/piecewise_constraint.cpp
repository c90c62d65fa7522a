// §2.10, (2.23)–(2.26): the velocity constraint x ẏ = 0 on its smooth branch x ≠ 0.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// With P = 0.5 E1 − 2 E2, m = 1, from x = 1, y = 0.3, ẋ = 0.4: y stays 0.3, x = 1 + 0.4 t + t²/4
// (m ẍ = P1), and the constraint force λ ∂(x ẏ)/∂ẏ E2 = λ x E2 cancels P2: λ = −P2/x (the book's
// (2.25) prints F_y/x); the particle's constraint force m a − P is 2 E2.
TEST(PiecewiseConstraint, SmoothBranchHoldsYWithLambdaMinusP2OverX) {
  const test::ModelRun run = test::run_model("piecewise-constraint");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), x = 1 + 0.4 * t + 0.25 * t * t;
    EXPECT_NEAR(run.at(i, "x"), x, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "y"), 0.3, 1e-14) << t;
    EXPECT_NEAR(run.at(i, "lambda(xy)"), 2.0 / x, 1e-13) << t;
    EXPECT_NEAR(run.at(i, "Fc.x"), 0.0, 1e-13) << t;
    EXPECT_NEAR(run.at(i, "Fc.y"), 2.0, 1e-13) << t;
  }
}

}  // namespace
}  // namespace unidyn
