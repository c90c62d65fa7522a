// The composite-rigid-body algorithm (src/tree/composite_inertia.cpp) against M written out from
// the bodies' Jacobians (support/tree_oracle.hpp) and against a double pendulum's closed form.
#include <gtest/gtest.h>

#include "support/tree_oracle.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {
namespace {

using test::Random;

// Branching trees of revolute, prismatic and fixed joints with random geometry: M agrees with
// Σ m J_vᵀ J_v + J_ωᵀ J J_ω to rounding, at random configurations.
TEST(CompositeInertia, RandomTreesAgainstTheBodiesJacobians) {
  Random random;
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    Eigen::MatrixXd M;
    composite_inertia_mass_matrix(t.model, q, M, data);
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(M, test::oracle_mass_matrix(t, q));
  };
  EXPECT_LT(test::worst_over_random_trees(random, 20, 3, compare), 1e-13);
}

// Two uniform rods of lengths l1, l2 hinged about E3, the second at the first's end, θ2 measured
// from the first: M11 = I1 + I2 + m1 c1² + m2 (l1² + c2² + 2 l1 c2 cos θ2),
// M12 = I2 + m2 (c2² + l1 c2 cos θ2), M22 = I2 + m2 c2², c = l/2, I = m l²/12.
TEST(CompositeInertia, DoublePendulumClosedForm) {
  const double m1 = 1.3, l1 = 0.7, m2 = 0.9, l2 = 1.1, theta2 = 0.83;
  TreeModel model;
  model.coordinates = 2;
  for (int i = 0; i < 2; ++i) {
    TreeLink link;
    link.parent = i - 1;
    link.kind = JointKind::revolute;
    link.coordinate = i;
    link.axis = Eigen::Vector3d::UnitZ();
    link.origin = i == 0 ? Eigen::Vector3d::Zero() : Eigen::Vector3d(l1, 0, 0);
    const double m = i == 0 ? m1 : m2, l = i == 0 ? l1 : l2;
    link.inertia =
        rigid_body_inertia(m, Eigen::Vector3d(l / 2, 0, 0),
                           Eigen::Vector3d(0, m * l * l / 12, m * l * l / 12).asDiagonal());
    model.links.push_back(link);
  }
  TreeData data(model);
  Eigen::MatrixXd M;
  composite_inertia_mass_matrix(model, Eigen::Vector2d(-0.4, theta2), M, data);
  const double I1 = m1 * l1 * l1 / 12, I2 = m2 * l2 * l2 / 12, c1 = l1 / 2, c2 = l2 / 2;
  EXPECT_NEAR(M(0, 0),
              I1 + I2 + m1 * c1 * c1 + m2 * (l1 * l1 + c2 * c2 + 2 * l1 * c2 * std::cos(theta2)),
              1e-14);
  EXPECT_NEAR(M(0, 1), I2 + m2 * (c2 * c2 + l1 * c2 * std::cos(theta2)), 1e-14);
  EXPECT_NEAR(M(1, 0), M(0, 1), 0);
  EXPECT_NEAR(M(1, 1), I2 + m2 * c2 * c2, 1e-14);
}

}  // namespace
}  // namespace unidyn::tree
