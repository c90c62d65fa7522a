// The articulated-body algorithm (src/tree/articulated_body.cpp): q̈ against M q̈ = τ − b solved
// with the oracle's M and b (support/tree_oracle.hpp), and a compound pendulum's closed form.
#include <gtest/gtest.h>

#include "support/tree_oracle.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {
namespace {

using test::Random;

// At rest under joint forces: q̈ = M⁻¹ (τ − ∂U/∂q), every term exact in the oracle.
TEST(ArticulatedBody, AtRestAgainstTheOraclesEquations) {
  Random random(3);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    const Eigen::VectorXd tau = test::random_values(random, t.model.coordinates, 5);
    Eigen::VectorXd qddot;
    articulated_body_accelerations(t.model, q, Eigen::VectorXd::Zero(q.size()), tau, qddot, data);
    const Eigen::VectorXd reference =
        test::oracle_mass_matrix(t, q).ldlt().solve(tau - test::oracle_gravity_forces(t, q));
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(qddot, reference);
  };
  EXPECT_LT(test::worst_over_random_trees(random, 10, 3, compare), 1e-11);
}

// Moving: q̈ = M⁻¹ (τ − b) with Lagrange's b (∂M/∂q by central differences).
TEST(ArticulatedBody, MovingAgainstLagrangesEquations) {
  Random random(5);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    const Eigen::VectorXd qdot = test::random_values(random, t.model.coordinates, 2);
    const Eigen::VectorXd tau = test::random_values(random, t.model.coordinates, 5);
    Eigen::VectorXd qddot;
    articulated_body_accelerations(t.model, q, qdot, tau, qddot, data);
    const Eigen::VectorXd reference =
        test::oracle_mass_matrix(t, q).ldlt().solve(tau - test::oracle_bias(t, q, qdot));
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(qddot, reference);
  };
  EXPECT_LT(test::worst_over_random_trees(random, 6, 4, compare), 1e-8);
}

// A compound pendulum (hinge about E3, centre at c on e1, I_o = J + m c² about the hinge, g = −g
// E2) with a joint torque τ: θ̈ = (τ − m g c cos θ) / I_o.
TEST(ArticulatedBody, CompoundPendulumClosedForm) {
  const double m = 1.7, c = 0.35, J = 0.08, g = 9.81, theta = -1.1, tau = 0.6;
  const TreeModel model = test::hinge_pendulum(m, c, J, g);
  TreeData data(model);
  Eigen::VectorXd qddot;
  articulated_body_accelerations(model, Eigen::VectorXd::Constant(1, theta),
                                 Eigen::VectorXd::Constant(1, 2.0),
                                 Eigen::VectorXd::Constant(1, tau), qddot, data);
  EXPECT_NEAR(qddot[0], (tau - m * g * c * std::cos(theta)) / (J + m * c * c), 1e-13);
}

// A leaf without mass on a joint cannot be accelerated: refused, not a division by zero.
TEST(ArticulatedBody, MasslessLeafRefused) {
  TreeModel model;
  model.coordinates = 1;
  TreeLink link;
  link.kind = JointKind::revolute;
  link.coordinate = 0;
  model.links.push_back(link);
  TreeData data(model);
  Eigen::VectorXd qddot;
  EXPECT_THROW(
      articulated_body_accelerations(model, Eigen::VectorXd::Zero(1), Eigen::VectorXd::Zero(1),
                                     Eigen::VectorXd::Zero(1), qddot, data),
      std::domain_error);
}

}  // namespace
}  // namespace unidyn::tree
