// The unbalanced rotor (§9.4, (9.8)) turning at Ω about the fixed axis E3, with its centre of mass
// at ε e1 off the axis and products of inertia J13, J23: the bearings must supply
//   F_c = m ā − F = −m ε Ω² e1 + m g E3,   M_c = Ḣ = Ω² (J13 e2 − J23 e1)   (about x̄)
// since H = J ω = Ω (J13 e1 + J23 e2 + J33 e3) turns with the rotor. Checked on the one-coordinate
// model (Newton–Euler resultants) and on the six-coordinate model held by a pin (the pin's
// multipliers through (8.22)–(8.23)).
#include <cmath>

#include "support/joint_loads.hpp"
#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double m = 2.0, g = 9.81, eps = 0.01, J13 = 0.003, J23 = -0.002, Omega = 50.0;

TEST(UnbalancedRotor, BearingLoadsFromNewtonEuler) {
  const test::ModelRun run = test::run_model("unbalanced-rotor");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); i += 50) {
    EXPECT_NEAR(run.at(i, "der(theta)"), Omega, 1e-10);
    EXPECT_NEAR(run.at(i, "bearing_force"), -m * eps * Omega * Omega, 1e-9);
    EXPECT_NEAR(run.at(i, "bearing_moment_1"), -Omega * Omega * J23, 1e-9);
    EXPECT_NEAR(run.at(i, "bearing_moment_2"), Omega * Omega * J13, 1e-9);
  }
}

TEST(UnbalancedRotor, PinMultipliersGiveTheBearingLoads) {
  const test::ModelRun run = test::run_model("unbalanced-rotor-pinned");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size(), 1001u);
  for (std::size_t i = 0; i < run.rows.size(); i += 50) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "psi"), Omega * t, 1e-8);
    EXPECT_NEAR(run.at(i, "bearing_force_1"), -m * eps * Omega * Omega, 1e-8);
    EXPECT_NEAR(run.at(i, "bearing_force_3"), m * g, 1e-8);
    EXPECT_NEAR(run.at(i, "bearing_moment_1"), -Omega * Omega * J23, 1e-8);
    EXPECT_NEAR(run.at(i, "bearing_moment_2"), Omega * Omega * J13, 1e-8);
    // the multipliers (from the saddle-point solve) and m ā − F, Ḣ − M (from the solved q̈) agree
    EXPECT_LT(run.at(i, "newton_euler_force"), 1e-11 * m * eps * Omega * Omega);
    EXPECT_LT(run.at(i, "newton_euler_moment"), 1e-11 * Omega * Omega * J13);
  }
}

// The pin's closed-form f and h (8.23) against f and h solved from each row ∂Ψ/∂q alone.
TEST(UnbalancedRotor, PinLoadsMatchTheirRowsInTheCoordinates) {
  const System system = load_model(test::model_path("unbalanced-rotor-pinned"));
  ASSERT_EQ(system.constraints.size(), 5u);
  test::expect_joint_loads_match_rows(system);
}

}  // namespace
}  // namespace unidyn
