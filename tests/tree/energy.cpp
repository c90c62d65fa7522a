// A tree's energies (src/tree/tree_energy.cpp): T against ½ q̇ᵀ M q̇ and U against −Σ m g · x̄ with
// M and the centres written out from the bodies' Jacobians and poses (support/tree_oracle.hpp).
#include <gtest/gtest.h>

#include "support/tree_oracle.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {
namespace {

using test::Random;

TEST(Energy, KineticAgainstTheMassMatrix) {
  Random random(13);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    const Eigen::VectorXd qdot = test::random_values(random, t.model.coordinates, 2);
    const double T = tree_kinetic_energy(t.model, q, qdot, data);
    const double reference = 0.5 * qdot.dot(test::oracle_mass_matrix(t, q) * qdot);
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(Eigen::MatrixXd::Constant(1, 1, T),
                                                       Eigen::MatrixXd::Constant(1, 1, reference));
  };
  EXPECT_LT(test::worst_over_random_trees(random, 10, 3, compare), 1e-13);
}

TEST(Energy, GravityAgainstTheCentresOfMass) {
  Random random(17);
  const auto compare = [&](const test::OracleTree& t, TreeData& data) {
    const Eigen::VectorXd q = test::random_values(random, t.model.coordinates, 3);
    const double U = tree_gravity_potential(t.model, q, data);
    const std::vector<test::OraclePose> poses = test::oracle_poses(t, q);
    double reference = 0;
    for (std::size_t b = 0; b < t.bodies.size(); ++b) {
      const Eigen::Vector3d center = poses[b].o + poses[b].Q * t.bodies[b].center;
      reference -= t.bodies[b].mass * t.model.gravity.dot(center);
    }
    return std::pair<Eigen::MatrixXd, Eigen::MatrixXd>(Eigen::MatrixXd::Constant(1, 1, U),
                                                       Eigen::MatrixXd::Constant(1, 1, reference));
  };
  EXPECT_LT(test::worst_over_random_trees(random, 10, 3, compare), 1e-13);
}

}  // namespace
}  // namespace unidyn::tree
