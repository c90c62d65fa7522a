// The rattleback (celt), named in book §9.9: models/rattleback.yaml, an ellipsoidal body whose
// principal axes of inertia are turned by δ from its shape's, rolling without slip. Spun about the
// vertical it rocks, stops and spins the other way — with E conserved (rolling does no work); with
// δ = 0 it keeps its spin; and δ → −δ mirrors the motion (ω3 → −ω3 from the mirrored start).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

test::ModelRun spin(double rate, double delta, double t_end) {
  return test::run_model(
      "rattleback", {{"spin", rate}, {"delta", delta}},
      [&](SimulationOptions& o) { o.t_end = t_end; }, true);
}

TEST(Rattleback, SpinReversesOnlyWithMisalignedAxes) {
  const test::ModelRun turned = spin(5, 0.05, 6.5);
  ASSERT_TRUE(turned.summary.ok) << turned.summary.message;
  EXPECT_LT(turned.summary.energy_relative_drift, 1e-8);
  const std::vector<double> w3 = turned.column("w3");
  EXPECT_NEAR(w3.front(), 5, 1e-12);
  EXPECT_LT(*std::min_element(w3.begin(), w3.end()), -4) << "spins the other way";
  const test::ModelRun aligned = spin(5, 0, 4);
  ASSERT_TRUE(aligned.summary.ok) << aligned.summary.message;
  for (const double w : aligned.column("w3")) EXPECT_NEAR(w, 5, 1e-3);
  const test::ModelRun mirrored = spin(-5, -0.05, 6.5);
  ASSERT_TRUE(mirrored.summary.ok) << mirrored.summary.message;
  ASSERT_EQ(mirrored.rows.size(), turned.rows.size());
  for (std::size_t i = 0; i < turned.rows.size(); ++i) {
    EXPECT_NEAR(mirrored.at(i, "w3"), -turned.at(i, "w3"), 1e-6) << turned.at(i, "t");
  }
}

}  // namespace
}  // namespace unidyn
