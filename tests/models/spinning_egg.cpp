// The spinning egg, named in book §9.9: models/spinning-egg.yaml, a prolate spheroid on a rough
// table with the tippe top's friction law. Spun fast on its side it rises onto its end — its axis
// from 80° to vertical, its centre of mass from a to c above the table — paying for the height with
// kinetic energy, E falling all the while; spun slowly it falls onto its side.
#include <gtest/gtest.h>

#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

test::ModelRun spin(double rate) {
  return test::run_model(
      "spinning-egg", {{"spin", rate}}, [](SimulationOptions& o) { o.t_end = 3; }, true);
}

TEST(SpinningEgg, RisesOntoItsEndWhenSpunFast) {
  const double a = 0.02, c = 0.03;
  const test::ModelRun fast = spin(150);
  ASSERT_TRUE(fast.summary.ok) << fast.summary.message;
  EXPECT_NEAR(fast.at(0, "upright"), std::cos(1.4), 1e-12);
  EXPECT_GT(fast.rows.back()[fast.index("upright")], 0.999);
  EXPECT_NEAR(fast.rows.back()[fast.index("x3")], c, 1e-4);
  for (std::size_t i = 1; i < fast.rows.size(); ++i) {
    EXPECT_LE(fast.at(i, "energy"), fast.at(i - 1, "energy") + 1e-12) << fast.at(i, "t");
  }
  const test::ModelRun slow = spin(20);
  ASSERT_TRUE(slow.summary.ok) << slow.summary.message;
  EXPECT_LT(slow.rows.back()[slow.index("upright")], 0.05);
  EXPECT_NEAR(slow.rows.back()[slow.index("x3")], a, 1e-4);
}

}  // namespace
}  // namespace unidyn
