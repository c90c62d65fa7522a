// The heavy top two ways: three Euler angles about the fixed point (heavy-top), and seven
// coordinates — the centre and Euler parameters — held by a ball joint (heavy-top-socket). One
// motion, one support force: m ā − F from Euler's first law in the first, Σ μ_k E_k (8.23) from the
// joint's multipliers in the second.
#include <cmath>

#include "support/joint_loads.hpp"
#include "support/model_run.hpp"

namespace unidyn {
namespace {

TEST(HeavyTopSocket, SameMotionAndSupportForceAsTheEulerAngleTop) {
  const test::ModelRun angles = test::run_model("heavy-top");
  const test::ModelRun socket = test::run_model("heavy-top-socket");
  ASSERT_TRUE(angles.summary.ok) << angles.summary.message;
  ASSERT_TRUE(socket.summary.ok) << socket.summary.message;
  EXPECT_NEAR(angles.summary.energy_initial, socket.summary.energy_initial, 1e-13);
  ASSERT_EQ(angles.rows.size(), socket.rows.size());
  for (std::size_t i = 0; i < angles.rows.size(); i += 10) {
    EXPECT_NEAR(angles.at(i, "cos_theta"), socket.at(i, "cos_theta"), 1e-9) << "row " << i;
    for (const char* R : {"R1", "R2", "R3"}) {
      EXPECT_NEAR(angles.at(i, R), socket.at(i, R), 1e-7) << R << " row " << i;
    }
    EXPECT_LT(socket.at(i, "newton_euler"), 1e-10);
  }
  for (const auto& c : socket.summary.conserved_drift) EXPECT_LT(c.max_change, 1e-11) << c.name;
}

// With Euler parameters the unit norm's row closes the system for the joint's loads.
TEST(HeavyTopSocket, JointLoadsMatchTheirRowsWithEulerParameters) {
  test::expect_joint_loads_match_rows(load_model(test::model_path("heavy-top-socket")));
}

}  // namespace
}  // namespace unidyn
