// The car with a Chaplygin (knife-edge) constraint (Problem 10.2, (10.49)–(10.50)).
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/kinematics/integrability.hpp"

namespace unidyn {
namespace {

// (10.50): Euler's laws with the constraint's load, m ẍ1 = −μ4 sin φ, m ẍ2 = μ4 cos φ,
// λ3 φ̈ = −μ4 L1 — here m ā and Ḣ from the run against the multiplier; E conserved; (b) the
// constraint is not integrable.
TEST(ChaplyginCar, EquationsEnergyAndNonIntegrability) {
  const test::ModelRun run = test::run_model("chaplygin-car");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-12);
  const double L1 = 1.2;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double mu = run.at(i, "lambda(chaplygin)"), phi = run.at(i, "phi");
    const double scale = 1e-9 * (1 + std::abs(mu));
    EXPECT_NEAR(run.at(i, "F1"), -mu * std::sin(phi), scale);
    EXPECT_NEAR(run.at(i, "F2"), mu * std::cos(phi), scale);
    EXPECT_NEAR(run.at(i, "M3"), -mu * L1, scale);
    largest = std::max(largest, std::abs(mu));
  }
  EXPECT_GT(largest, 100.0);  // the constraint does act
  const System system = load_model(test::model_path("chaplygin-car"));
  EXPECT_FALSE(constraint_integrability(system, 0).integrable);
}

// (e) Straight-line motion without rotation is a motion of the car: moving along e1 at φ̇ = 0 it
// needs no constraint force.
TEST(ChaplyginCar, StraightLineMotion) {
  const test::ModelRun run =
      test::run_model("chaplygin-car", {{"der(phi)", 0.0}, {"der(x2)", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); i += 10) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), 10 * t, 1e-9) << t;
    EXPECT_EQ(run.at(i, "x2"), 0.0) << t;
    EXPECT_EQ(run.at(i, "lambda(chaplygin)"), 0.0) << t;
  }
}

}  // namespace
}  // namespace unidyn
