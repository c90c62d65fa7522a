// Exercise 3.4: a particle held at rest on a rough moving surface q3 = d(t) by static friction
// (models/rough-moving-surface.yaml), in coordinates whose bases a_1 = E1 + (q1 + q2) E3,
// a_2 = E2 + q1 E3, a_3 = E3 are not orthogonal. (b) F_c = F_f^1 a_1 + F_f^2 a_2 + N a^3 with N
// the constraint's multiplier, and its covariant components λ_i = F_c · a_i are
// [[a11, a12, 0], [a12, a22, 0], [a13, a23, 1]] [F_f^1, F_f^2, N]; (c) E is not conserved: it
// changes by the work of F_c, the surface's.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

using V = Eigen::Vector3d;

TEST(RoughMovingSurface, AtRestOnItFrictionNormalForceAndWork) {
  const test::ModelRun run = test::run_model("rough-moving-surface", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what, "contact 'surface' sticks");
  const std::vector<double> work = test::running_integral(run, "power");
  double largest_friction = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), q1 = run.at(i, "q1"), q2 = run.at(i, "q2");
    // at rest on the surface
    EXPECT_NEAR(q1, 0.3, 1e-10) << t;
    EXPECT_NEAR(q2, -0.2, 1e-10) << t;
    const V a1(1, 0, q1 + q2), a2(0, 1, q1), a3(0, 0, 1);
    // a^3 = grad q3 = −(q1 + q2) E1 − q1 E2 + E3, with a^3 · a_1 = a^3 · a_2 = 0, a^3 · a_3 = 1
    const V upper3(-(q1 + q2), -q1, 1);
    const V F(run.at(i, "Fc.x"), run.at(i, "Fc.y"), run.at(i, "Fc.z"));
    Eigen::Matrix3d basis;
    basis << a1, a2, upper3;
    const V parts = basis.fullPivLu().solve(F);  // F_f^1, F_f^2, N
    EXPECT_NEAR(parts[2], run.at(i, "lambda(surface)"), 1e-9) << t;
    Eigen::Matrix3d metric;
    metric << a1.dot(a1), a1.dot(a2), 0, a1.dot(a2), a2.dot(a2), 0, a1.dot(a3), a2.dot(a3), 1;
    const V covariant(F.dot(a1), F.dot(a2), F.dot(a3));
    EXPECT_LT((covariant - metric * parts).norm(), 1e-12 * (1 + F.norm())) << t;
    largest_friction = std::max(largest_friction, std::hypot(parts[0], parts[1]));
    if (i % 2 == 0) {
      EXPECT_NEAR(run.at(i, "energy") - run.at(0, "energy"), work[i], 1e-9) << t;
    }
  }
  EXPECT_GT(largest_friction, 0.1) << "friction must hold it for the test to mean anything";
  EXPECT_GT(std::abs(run.summary.energy_final - run.summary.energy_initial), 0.05);
}

}  // namespace
}  // namespace unidyn
