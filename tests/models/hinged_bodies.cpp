// Two bodies joined by a cylindrical hinge (§8.6.4, §11.3), derived two independent ways: with
// seven coordinates and no multipliers (hinged-bodies, Lagrange's approach II (11.5)), and with
// twelve coordinates and the pin's five multipliers (hinged-bodies-pinned, (11.6)). The two runs
// must give one motion, and the hinge force on A from the seven-coordinate run's m ā − F must be
// the pin's Σ μ_k f_k (8.23) from the twelve-coordinate run.
#include <cmath>

#include "support/joint_loads.hpp"
#include "support/model_run.hpp"

namespace unidyn {
namespace {

TEST(HingedBodies, SevenAndTwelveCoordinatesGiveOneMotionAndOneHingeForce) {
  const test::ModelRun reduced = test::run_model("hinged-bodies");
  const test::ModelRun pinned = test::run_model("hinged-bodies-pinned");
  ASSERT_TRUE(reduced.summary.ok) << reduced.summary.message;
  ASSERT_TRUE(pinned.summary.ok) << pinned.summary.message;
  ASSERT_EQ(reduced.rows.size(), pinned.rows.size());
  for (std::size_t i = 0; i < reduced.rows.size(); ++i) {
    for (const char* column : {"x", "y", "z", "xB", "yB", "zB", "a3_1", "a3_2", "a1_3"}) {
      EXPECT_NEAR(reduced.at(i, column), pinned.at(i, column), 1e-9) << column << " row " << i;
    }
    for (const char* column : {"hinge_force_1", "hinge_force_2", "hinge_force_3"}) {
      EXPECT_NEAR(reduced.at(i, column), pinned.at(i, column), 1e-8) << column << " row " << i;
    }
  }
}

// (8.24): F_cA = −F_cB, the reaction moments M_r = M_c − π_P × F_c are equal and opposite and
// perpendicular to the axis, and the pin's loads are m ā − F and Ḣ − M of each body (Euler's laws
// with the multipliers the saddle-point solve returned).
TEST(HingedBodies, PinObeysTheGeneralisedThirdLaw) {
  const test::ModelRun run = test::run_model("hinged-bodies-pinned");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    largest = std::max(largest, std::abs(run.at(i, "hinge_force_1")));
    EXPECT_LT(run.at(i, "force_sum"), 1e-14);
    EXPECT_LT(run.at(i, "reaction_sum"), 1e-14);
    EXPECT_LT(std::abs(run.at(i, "reaction_along_axis")), 1e-14);
    EXPECT_LT(run.at(i, "newton_euler"), 1e-12);
  }
  EXPECT_GT(largest, 0.5);  // the hinge does carry a load
}

// Without external loads E, G and H_O are constants of both descriptions.
TEST(HingedBodies, MomentaAndEnergyConserved) {
  for (const char* model : {"hinged-bodies", "hinged-bodies-pinned"}) {
    const test::ModelRun run = test::run_model(model);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    EXPECT_LT(run.summary.energy_relative_drift, 1e-11) << model;
    for (const auto& c : run.summary.conserved_drift) {
      EXPECT_LT(c.max_change, 1e-11) << model << " " << c.name;
    }
  }
}

TEST(HingedBodies, PinLoadsMatchTheirRowsInTheCoordinates) {
  test::expect_joint_loads_match_rows(load_model(test::model_path("hinged-bodies-pinned")));
}

}  // namespace
}  // namespace unidyn
