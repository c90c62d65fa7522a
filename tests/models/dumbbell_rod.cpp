// Two particles joined by a rigid rod orbiting a planet (§5.3 with a rod, §4.3–4.5).
#include <cmath>
#include <string>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// (4.3): the rod's forces on its ends are equal and opposite and along the rod (F_c1 = −F_c2 =
// −μ t), so they do no net work and no net moment: E and H_O are conserved; the rod keeps its
// length.
TEST(DumbbellRod, RodForcesEqualOppositeAlongTheRod) {
  const test::ModelRun run = test::run_model("dumbbell-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "length"), 0.012, 1e-12);
    for (const char* c : {".x", ".y", ".z"}) {
      const double F1 = run.at(i, std::string("F1") + c), F2 = run.at(i, std::string("F2") + c);
      EXPECT_NEAR(F1 + F2, 0.0, 1e-18);
      largest = std::max(largest, std::abs(F1));
    }
    EXPECT_NEAR(run.at(i, "F1_across"), 0.0, 1e-18);
  }
  EXPECT_GT(largest, 1e-6);  // the rod does pull
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  ASSERT_EQ(run.summary.conserved_drift.size(), 3u);
  for (const auto& c : run.summary.conserved_drift) {
    EXPECT_LT(c.max_change, 1e-10 * std::abs(run.summary.conserved_drift[2].initial)) << c.name;
  }
}

}  // namespace
}  // namespace unidyn
