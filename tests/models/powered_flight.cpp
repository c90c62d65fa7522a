// Exercise 9.8 (and §9.6 with drag): a spinning body under thrust, drag and the Magnus force.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The Magnus force m B ω × v̄ is normal to v̄: no power; E changes by the work of the thrust and
// the drag, E(t) − E(0) = ∫ (thrust + drag)·v̄ dt (Simpson's rule on the 1 ms grid).
TEST(PoweredFlight, MagnusDoesNoWorkThrustAndDragDo) {
  const test::ModelRun run = test::run_model("powered-flight");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "magnus_power"), 0.0, 1e-13);
    if (i % 2 == 1) continue;
    EXPECT_NEAR(run.at(i, "E") - run.at(0, "E"), work[i], 1e-8) << run.at(i, "t");
  }
  EXPECT_GT(std::abs(work.back()), 1.0);
}

}  // namespace
}  // namespace unidyn
