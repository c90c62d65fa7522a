// Exercise 11.3: a robot arm moved along a prescribed motion (models/robot-arm.yaml): six
// rheonomic constraints whose multipliers are the actuators' loads. Against the book's H (c) and
// F_act (e), the power balance Ė = F_act · u̇ + M_act · ω (g), and M_act (f): the exact one,
// Ḣ + (L/2) e3 × F_act, exceeds the book's expression for constant rates by
// ψ̇θ̇ (λ2 cos θ e2 − λ3 sin θ e3) — ω = ψ̇ E3 + θ̇ e1 is not constant, as the book says it is.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include <Eigen/Dense>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

using V = Eigen::Vector3d;

TEST(RobotArm, ActuatorLoadsOfExercise113) {
  const test::ModelRun run = test::run_model("robot-arm", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 2.0, g = 9.81, L = 1.2, l1 = 0.3, l2 = 0.25, l3 = 0.05, A = 0.2, w = 1.5;
  const double dpsi = 0.8, dtheta = 0.5;
  const auto vec = [&](std::size_t i, const std::string& name) {
    return V(run.at(i, name + ".x"), run.at(i, name + ".y"), run.at(i, name + ".z"));
  };
  double worst_exact = 0;
  for (std::size_t i = 1; i + 1 < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), psi = run.at(i, "psi"), theta = run.at(i, "theta");
    const V e1(std::cos(psi), std::sin(psi), 0);
    const V e2(-std::sin(psi) * std::cos(theta), std::cos(psi) * std::cos(theta), std::sin(theta));
    const V e3(std::sin(theta) * std::sin(psi), -std::sin(theta) * std::cos(psi), std::cos(theta));
    const V H = vec(i, "H"), F = vec(i, "F_act"), M = vec(i, "M_act");
    // (c)
    const V book_H =
        l1 * dtheta * e1 + l2 * dpsi * std::sin(theta) * e2 + l3 * dpsi * std::cos(theta) * e3;
    EXPECT_LT((H - book_H).norm(), 1e-10) << t;
    // (e), with ü = −A w² (sin wt, 0, cos wt) and ψ̈ = θ̈ = 0
    const V uddot = -A * w * w * V(std::sin(w * t), 0, std::cos(w * t));
    const V book_F =
        m * g * V::UnitZ() + m * uddot + m * L / 2 * (2 * dpsi * dtheta * std::cos(theta)) * e1 +
        m * L / 2 * (dpsi * dpsi * std::sin(theta) * std::cos(theta)) * e2 -
        m * L / 2 * (dtheta * dtheta + dpsi * dpsi * std::pow(std::sin(theta), 2)) * e3;
    EXPECT_LT((F - book_F).norm(), 1e-9) << t;
    // (f): exactly Ḣ + (L/2) e3 × F (Ḣ by central differences of the rows)
    const double h = run.at(i + 1, "t") - t;
    const V Hdot = (vec(i + 1, "H") - vec(i - 1, "H")) / (2 * h);
    worst_exact = std::max(worst_exact, (M - Hdot - L / 2 * e3.cross(F)).norm());
    const V omega = dpsi * V::UnitZ() + dtheta * e1;
    const V printed = m * L / 2 * e3.cross(g * V::UnitZ() + uddot) +
                      m * L * L / 2 * dpsi * dtheta * std::cos(theta) * e2 -
                      m * L * L / 4 * dpsi * dpsi * std::sin(theta) * std::cos(theta) * e1 +
                      omega.cross(H);
    const V missing = dpsi * dtheta * (l2 * std::cos(theta) * e2 - l3 * std::sin(theta) * e3);
    EXPECT_LT((M - printed - missing).norm(), 1e-9) << t;
    EXPECT_GT(missing.norm(), 0.015) << "⚠ the printed M_act differs";
  }
  EXPECT_LT(worst_exact, 1e-4) << "central differences 0.01 s apart";
  // (g): E(t) − E(0) = ∫ (F_act · v̄ + M_act · ω) dt (about the centre of mass)
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 0; i < run.rows.size(); i += 2) {
    EXPECT_NEAR(run.at(i, "energy") - run.at(0, "energy"), work[i], 1e-7) << run.at(i, "t");
  }
}

// The angles are left to the constraints: θ = θ0 is computed, and checked for gimbal lock only
// then — refused when θ0 = 0 puts the 3-1-3 set at its lock, accepted otherwise (above).
TEST(RobotArm, ComputedAnglesAreCheckedForGimbalLock) {
  try {
    test::run_model("robot-arm", {{"theta0", 0.0}}, {}, true);
    ADD_FAILURE() << "a start at the gimbal lock must be refused";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gimbal lock"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unidyn
