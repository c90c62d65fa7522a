// The recursive Newton–Euler bias (src/tree/inverse_dynamics.cpp) against Lagrange's equations
// written out from the bodies' Jacobians (support/tree_oracle.hpp), and a pendulum's closed form.
#include <gtest/gtest.h>

#include "support/tree_oracle.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {
namespace {

using test::Random;

// At rest the bias is gravity's alone, ∂U/∂q = −Σ m J_vᵀ g: exact in the oracle too.
TEST(InverseDynamics, GravityAtRestAgainstThePotential) {
  Random random(7);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    Eigen::VectorXd bias;
    inverse_dynamics_bias(t.model, q, Eigen::VectorXd::Zero(q.size()), bias, data);
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(bias, test::oracle_gravity_forces(t, q));
  };
  EXPECT_LT(test::worst_over_random_trees(random, 10, 4, compare), 1e-13);
}

// Moving: the Coriolis and centripetal forces of Lagrange's equations (3.7) from ∂M/∂q (central
// differences of the oracle's M, ~1e-10).
TEST(InverseDynamics, MovingAgainstLagrangesEquations) {
  Random random(11);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    const Eigen::VectorXd qdot = test::random_values(random, t.model.coordinates, 2);
    Eigen::VectorXd bias;
    inverse_dynamics_bias(t.model, q, qdot, bias, data);
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(bias, test::oracle_bias(t, q, qdot));
  };
  EXPECT_LT(test::worst_over_random_trees(random, 6, 3, compare), 1e-8);
}

// A body on a hinge about E3 with its centre at distance c along e1 and g = −g E2:
// b = m g c cos θ (U = m g c sin θ), whatever θ̇ (no velocity forces on one hinge).
TEST(InverseDynamics, PendulumClosedForm) {
  const double m = 2.5, c = 0.4, g = 9.81, theta = 0.7;
  const TreeModel model = test::hinge_pendulum(m, c, 0.1, g);
  TreeData data(model);
  Eigen::VectorXd bias;
  inverse_dynamics_bias(model, Eigen::VectorXd::Constant(1, theta),
                        Eigen::VectorXd::Constant(1, 3.0), bias, data);
  EXPECT_NEAR(bias[0], m * g * c * std::cos(theta), 1e-13);
}

}  // namespace
}  // namespace unidyn::tree
