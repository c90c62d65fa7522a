// Exercise 11.1: a plate pinned to a rod spinning at a prescribed Ω (models/plate-on-spinning-rod
// .yaml). (d) The constraints' power is not zero when Ω ≠ 0 — E changes by its integral — and is
// zero when Ω = 0 (E conserved); (e) H_A ≠ J^A ω when Ω ≠ 0: the difference is m π̄ × v_A with
// π̄ = x̄ − x_A = a e2 and v_A = −L Ω e1′ (e1′ = cos ψ E1 + sin ψ E2), zero when Ω = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

using V = Eigen::Vector3d;

test::ModelRun run_plate(double omega) {
  // rows 2.5 ms apart, for Simpson's rule on the power (error ~1e-10)
  return test::run_model(
      "plate-on-spinning-rod", {{"Omega", omega}},
      [](SimulationOptions& o) { o.output_step = 0.0025; }, true);
}

TEST(PlateOnSpinningRod, ConstraintPowerAndAngularMomentumAboutThePin) {
  const double m = 1.5, L = 0.6, a = 0.25;
  for (const double Omega : {2.0, 0.0}) {
    const test::ModelRun run = run_plate(Omega);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const std::vector<double> work = test::running_integral(run, "power");
    double largest_power = 0, largest_difference = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t"), psi = run.at(i, "psi"), theta = run.at(i, "theta");
      if (i % 2 == 0) {
        EXPECT_NEAR(run.at(i, "energy") - run.at(0, "energy"), work[i], 1e-8) << t;
      }
      largest_power = std::max(largest_power, std::abs(run.at(i, "power")));
      const V e2(-std::sin(psi) * std::cos(theta), std::cos(psi) * std::cos(theta),
                 std::sin(theta));
      const V vA = -L * Omega * V(std::cos(psi), std::sin(psi), 0);
      const V HA(run.at(i, "H_A.x"), run.at(i, "H_A.y"), run.at(i, "H_A.z"));
      const V JAw(run.at(i, "JA_omega.x"), run.at(i, "JA_omega.y"), run.at(i, "JA_omega.z"));
      EXPECT_LT((HA - JAw - m * (a * e2).cross(vA)).norm(), 1e-10) << t;
      largest_difference = std::max(largest_difference, (HA - JAw).norm());
    }
    if (Omega != 0) {
      EXPECT_GT(largest_power, 0.1) << "a rheonomic constraint does work";
      EXPECT_GT(largest_difference, 0.05);
    } else {
      EXPECT_LT(largest_power, 1e-9);
      EXPECT_LT(largest_difference, 1e-12);
      EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
    }
  }
}

// (d), the power's value: the rod turns at Ω about E3 through O, so the constraints' power is Ω
// times the axial moment they exert about O, and gravity has none: P = Ω d(H_O·E3)/dt with
// H_O = x̄ × m v̄ + Σ λ_i (ω·e_i) e_i from the rows' state (3-1-3 basis and ω typed here, the rate
// by fourth-order differences) — against the run's F_c·v̄ + M_c·ω from the multipliers.
TEST(PlateOnSpinningRod, ConstraintPowerIsOmegaTimesTheAxialMoment) {
  const double m = 1.5, Omega = 2.0, lambda[3] = {0.04, 0.02, 0.05};
  const test::ModelRun run = run_plate(Omega);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto axial_momentum = [&](std::size_t i) {
    const double psi = run.at(i, "psi"), theta = run.at(i, "theta"), phi = run.at(i, "phi");
    const Eigen::Matrix3d Q =
        (Eigen::AngleAxisd(psi, V::UnitZ()) * Eigen::AngleAxisd(theta, V::UnitX()) *
         Eigen::AngleAxisd(phi, V::UnitZ()))
            .toRotationMatrix();
    const V e1_prime = Eigen::AngleAxisd(psi, V::UnitZ()) * V::UnitX();
    const V omega = run.at(i, "der(psi)") * V::UnitZ() + run.at(i, "der(theta)") * e1_prime +
                    run.at(i, "der(phi)") * Q.col(2);
    V H = V::Zero();
    for (int k = 0; k < 3; ++k) H += lambda[k] * omega.dot(Q.col(k)) * Q.col(k);
    const V x(run.at(i, "x1"), run.at(i, "x2"), run.at(i, "x3"));
    const V v(run.at(i, "der(x1)"), run.at(i, "der(x2)"), run.at(i, "der(x3)"));
    return (x.cross(m * v) + H).z();
  };
  const double h = run.at(1, "t") - run.at(0, "t");
  double error = 0, largest = 0;
  for (std::size_t i = 2; i + 2 < run.rows.size(); ++i) {
    const double rate = (8 * (axial_momentum(i + 1) - axial_momentum(i - 1)) -
                         (axial_momentum(i + 2) - axial_momentum(i - 2))) /
                        (12 * h);
    error = std::max(error, std::abs(run.at(i, "power") - Omega * rate));
    largest = std::max(largest, std::abs(run.at(i, "power")));
  }
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(error, 1e-6 * largest);  // the differences' O(h⁴), h = 2.5 ms
  std::printf("constraint power up to %.4g W, |P - Omega dH_O3/dt| %.3g\n", largest, error);
}

}  // namespace
}  // namespace unidyn
