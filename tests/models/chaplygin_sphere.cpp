// Chaplygin's sphere, named in book §9.9: models/chaplygin-sphere.yaml, a balanced ball with
// unequal principal moments rolling without slip. Gravity and the normal force have no moment
// about the contact point, which moves with the centre, so H_P = Jω + m R² (ω − (ω·E3) E3) is
// constant — and E — while the angular momentum about the centre, turned by the friction at the
// contact, is not.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

TEST(ChaplyginSphere, AngularMomentumAboutTheContactPointIsConstant) {
  const test::ModelRun run = test::run_model("chaplygin-sphere", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  ASSERT_EQ(run.summary.conserved_drift.size(), 3u);
  for (const auto& d : run.summary.conserved_drift) {
    EXPECT_LT(d.max_change, 1e-10) << d.name << " (initial " << d.initial << ")";
  }
  const auto H = [&](std::size_t i) {
    return Eigen::Vector3d(run.at(i, "H.x"), run.at(i, "H.y"), run.at(i, "H.z"));
  };
  double change = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) change = std::max(change, (H(i) - H(0)).norm());
  EXPECT_GT(change, 1e-2) << "about the centre it must change for the test to mean anything";
}

}  // namespace
}  // namespace unidyn
