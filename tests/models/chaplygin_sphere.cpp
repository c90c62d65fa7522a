// Chaplygin's sphere, named in book §9.9: models/chaplygin-sphere.yaml, a balanced ball with
// unequal principal moments rolling without slip. Gravity and the normal force have no moment
// about the contact point, which moves with the centre, so H_P = Jω + m R² (ω − (ω·E3) E3) is
// constant — and E — while the angular momentum about the centre, turned by the friction at the
// contact, is not. Its motion and its contact point's path against Chaplygin's equations by RK4.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

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

// Chaplygin's equations, by hand: the ball's centre is its centre of mass and the contact point is
// P = x̄ − R E3, so the angular momentum about P, K = Jω + m R² (ω − (ω·γ) γ) (γ = E3), is
// constant in space. On the body's basis (ω, γ, K their components on e1, e2, e3), K̇ + ω × K = 0
// and γ̇ = γ × ω, and since γ̇·ω = 0,
//   (J + m R² (I − γ γᵀ)) ω̇ = −ω × K + m R² (ω·γ) γ̇.
// The orientation Q = [e1 e2 e3] follows Q̇ = Q [ω]× and the centre rolls at v̄ = ω_s × R E3, ω_s =
// Q ω: its path x1, x2 is the contact point's. State: Q (by columns), ω on the body's basis, x1,
// x2.
using BallState = Eigen::Matrix<double, 14, 1>;

struct ChaplyginBall {
  double m, R;
  Eigen::Matrix3d J;

  BallState rates(const BallState& x) const {
    const Eigen::Map<const Eigen::Matrix3d> Q(x.data());
    const Eigen::Vector3d w = x.segment<3>(9);
    const Eigen::Vector3d up = Q.transpose() * Eigen::Vector3d::UnitZ();
    const Eigen::Vector3d K = J * w + m * R * R * (w - w.dot(up) * up);
    const Eigen::Vector3d up_rate = up.cross(w);
    const Eigen::Matrix3d mass =
        J + m * R * R * (Eigen::Matrix3d::Identity() - up * up.transpose());
    Eigen::Matrix3d wx;
    wx << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
    const Eigen::Vector3d ws = Q * w;
    BallState out;
    Eigen::Map<Eigen::Matrix3d>(out.data()) = Q * wx;
    out.segment<3>(9) = mass.lu().solve(-w.cross(K) + m * R * R * w.dot(up) * up_rate);
    out.segment<2>(12) = R * Eigen::Vector2d(ws.y(), -ws.x());  // ω_s × R E3
    return out;
  }
  // Classical RK4 over dt in n steps.
  BallState rk4(BallState x, double dt, int n) const {
    const double k = dt / n;
    for (int i = 0; i < n; ++i) {
      const BallState k1 = rates(x), k2 = rates(x + k / 2 * k1), k3 = rates(x + k / 2 * k2),
                      k4 = rates(x + k * k3);
      x += k / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return x;
  }
};

// §9.9, Chaplygin's sphere: the run (models/chaplygin-sphere.yaml: I1, I2, I3 = 0.002, 0.004,
// 0.005 kg m², m R² = 0.01 kg m², ω0 = (3, −2, 8) rad/s) against Chaplygin's equations above by
// RK4 (100 steps per 0.01 s row) from the run's first row: the contact point's path x1, x2 (the
// book's "unusual path"), ω on E1, E2, E3 and the body's basis e1, e2, e3 over the 10 s.
TEST(ChaplyginSphere, MotionAndContactPathAgainstChaplyginsEquationsByRk4) {
  std::ifstream file(test::model_path("chaplygin-sphere"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t at = text.find("outputs:\n");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 9, "  w: ball.omega\n  b1: ball.e1\n  b2: ball.e2\n  b3: ball.e3\n");
  const test::ModelRun run =
      test::run_system(parse_model(text, "chaplygin-path.yaml"), {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const ChaplyginBall ball{
      run.parameter("m"), run.parameter("R"),
      Eigen::Vector3d(run.parameter("I1"), run.parameter("I2"), run.parameter("I3")).asDiagonal()};
  const auto vector = [&](std::size_t i, const std::string& name) {
    return Eigen::Vector3d(run.at(i, name + ".x"), run.at(i, name + ".y"), run.at(i, name + ".z"));
  };
  const auto basis = [&](std::size_t i) {
    Eigen::Matrix3d Q;
    Q << vector(i, "b1"), vector(i, "b2"), vector(i, "b3");
    return Q;
  };
  EXPECT_LT((vector(0, "w") - Eigen::Vector3d(3, -2, 8)).norm(), 1e-12);
  BallState x;
  Eigen::Map<Eigen::Matrix3d>(x.data()) = basis(0);
  x.segment<3>(9) = basis(0).transpose() * vector(0, "w");
  x.segment<2>(12) << run.at(0, "x1"), run.at(0, "x2");
  const Eigen::Vector2d start = x.segment<2>(12);
  double path_error = 0, omega_error = 0, basis_error = 0, reach = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    if (i > 0) x = ball.rk4(x, run.at(i, "t") - run.at(i - 1, "t"), 100);
    const Eigen::Map<const Eigen::Matrix3d> Q(x.data());
    const Eigen::Vector2d path(run.at(i, "x1"), run.at(i, "x2"));
    path_error = std::max(path_error, (path - x.segment<2>(12)).norm());
    omega_error = std::max(omega_error, (vector(i, "w") - Q * x.segment<3>(9)).norm());
    basis_error = std::max(basis_error, (basis(i) - Q).norm());
    reach = std::max(reach, (path - start).norm());
  }
  std::printf(
      "10 s: |x - rk4| %.2e m (the path reaches %.3f m from the start), |omega - rk4| "
      "%.2e rad/s, |Q - rk4| %.2e\n",
      path_error, reach, omega_error, basis_error);
  EXPECT_GT(reach, 0.1);
  EXPECT_LT(path_error, 1e-8);
  EXPECT_LT(omega_error, 1e-7);
  EXPECT_LT(basis_error, 1e-8);
}

}  // namespace
}  // namespace unidyn
