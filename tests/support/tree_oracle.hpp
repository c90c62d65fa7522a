// Oracles for the recursive algorithms of kinematic trees (tests/tree): a tree with random
// geometry, and its M, gravity forces and Lagrange's bias written out here in the ground's frame,
// body by body, from the bodies' geometric Jacobians — no spatial algebra, no recursion:
//
//   Q_B = Q_P R0 L(q, a),  o_B = o_P + Q_P (p + R0 q a)          the composition (6.49), (6.8)
//   ∂ω_B/∂q̇_k = w_k,  ∂v̄_B/∂q̇_k = w_k × (x̄_B − o_k)   (joint k revolute, an ancestor of B or B's)
//   ∂v̄_B/∂q̇_k = w_k                                             (joint k prismatic)
//   M = Σ_B m J_vᵀ J_v + J_ωᵀ (Q J0 Qᵀ) J_ω                      (T = ½ q̇ᵀ M q̇, (7.x) Koenig)
//   U = −Σ_B m g · x̄_B,   ∂U/∂q_i = −Σ_B m g · J_v,i
//   b_i = Σ_jk ∂M_ij/∂q_k q̇_k q̇_j − ½ q̇ᵀ ∂M/∂q_i q̇ + ∂U/∂q_i     Lagrange's equations (3.7)
//
// with w_k = Q_k a_k, the joint's axis on the ground's basis, and ∂M/∂q by fourth-order central
// differences (the one approximation: ~1e-10 relative).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::test {

// A body of the tree as the oracle sees it: mass, centre of mass from its frame's origin and
// central inertia (both on its basis).
struct OracleBody {
  double mass = 1;
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();
};

struct OracleTree {
  tree::TreeModel model;
  std::vector<OracleBody> bodies;
};

// A random tree of `links` links (each on a random earlier link or the ground), revolute,
// prismatic and fixed joints in turn, random axes, origins, rotations and bodies (each inertia a
// cloud of point masses', so physically realisable), gravity g.
inline OracleTree random_tree(Random& random, std::size_t links) {
  OracleTree t;
  t.model.gravity = Eigen::Vector3d(0.4, -1.3, -9.81);
  for (std::size_t i = 0; i < links; ++i) {
    tree::TreeLink link;
    link.parent = static_cast<int>(std::floor(random.uniform(-1.0, static_cast<double>(i))));
    link.kind = i % 4 == 3   ? tree::JointKind::fixed
                : i % 4 == 2 ? tree::JointKind::prismatic
                             : tree::JointKind::revolute;
    if (link.kind != tree::JointKind::fixed)
      link.coordinate = static_cast<int>(t.model.coordinates++);
    link.axis = random.unit_vector();
    link.origin = random.vector(0.8);
    link.fixed_rotation = random.rotation();
    OracleBody body;
    body.mass = random.uniform(0.5, 3.0);
    body.center = random.vector(0.5);
    body.inertia.setZero();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector3d x = random.vector(0.4);
      body.inertia +=
          body.mass / 4 * (x.squaredNorm() * Eigen::Matrix3d::Identity() - x * x.transpose());
    }
    link.inertia = tree::rigid_body_inertia(body.mass, body.center, body.inertia);
    t.model.links.push_back(link);
    t.bodies.push_back(body);
  }
  return t;
}

// A compound pendulum: one body on a hinge about E3 at O, its centre at c e1, central inertia J 1,
// under g = −g E2.
inline tree::TreeModel hinge_pendulum(double m, double c, double J, double g) {
  tree::TreeModel model;
  model.coordinates = 1;
  model.gravity = Eigen::Vector3d(0, -g, 0);
  tree::TreeLink link;
  link.kind = tree::JointKind::revolute;
  link.coordinate = 0;
  link.inertia =
      tree::rigid_body_inertia(m, Eigen::Vector3d(c, 0, 0), Eigen::Matrix3d::Identity() * J);
  model.links.push_back(link);
  return model;
}

// n values uniform in [−scale, scale]: a state or joint forces.
inline Eigen::VectorXd random_values(Random& random, std::size_t n, double scale) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(n));
  for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = random.uniform(-scale, scale);
  return v;
}

// Each body's frame on the ground's basis: Q_B and o_B.
struct OraclePose {
  Eigen::Matrix3d Q;
  Eigen::Vector3d o;
};

inline std::vector<OraclePose> oracle_poses(const OracleTree& t, const Eigen::VectorXd& q) {
  std::vector<OraclePose> poses;
  for (const tree::TreeLink& link : t.model.links) {
    OraclePose parent{Eigen::Matrix3d::Identity(), Eigen::Vector3d::Zero()};
    if (link.parent >= 0) parent = poses[static_cast<std::size_t>(link.parent)];
    const double qi = link.coordinate >= 0 ? q[link.coordinate] : 0.0;
    Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
    Eigen::Vector3d d = Eigen::Vector3d::Zero();
    if (link.kind == tree::JointKind::revolute) R = book_L(qi, link.axis);
    if (link.kind == tree::JointKind::prismatic) d = qi * link.axis;
    poses.push_back({parent.Q * link.fixed_rotation * R,
                     parent.o + parent.Q * (link.origin + link.fixed_rotation * d)});
  }
  return poses;
}

// The Jacobians of body b's centre (3 × n) and rotation (3 × n) on the ground's basis.
inline void oracle_jacobians(const OracleTree& t, const std::vector<OraclePose>& poses,
                             std::size_t b, Eigen::MatrixXd& Jv, Eigen::MatrixXd& Jw) {
  const auto n = static_cast<Eigen::Index>(t.model.coordinates);
  Jv.setZero(3, n);
  Jw.setZero(3, n);
  const Eigen::Vector3d center = poses[b].o + poses[b].Q * t.bodies[b].center;
  for (int k = static_cast<int>(b); k >= 0; k = t.model.links[static_cast<std::size_t>(k)].parent) {
    const tree::TreeLink& joint = t.model.links[static_cast<std::size_t>(k)];
    if (joint.coordinate < 0) continue;
    const Eigen::Vector3d w = poses[static_cast<std::size_t>(k)].Q * joint.axis;
    if (joint.kind == tree::JointKind::revolute) {
      Jw.col(joint.coordinate) = w;
      Jv.col(joint.coordinate) = w.cross(center - poses[static_cast<std::size_t>(k)].o);
    } else {
      Jv.col(joint.coordinate) = w;
    }
  }
}

inline Eigen::MatrixXd oracle_mass_matrix(const OracleTree& t, const Eigen::VectorXd& q) {
  const std::vector<OraclePose> poses = oracle_poses(t, q);
  const auto n = static_cast<Eigen::Index>(t.model.coordinates);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(n, n), Jv, Jw;
  for (std::size_t b = 0; b < t.bodies.size(); ++b) {
    oracle_jacobians(t, poses, b, Jv, Jw);
    const Eigen::Matrix3d J = poses[b].Q * t.bodies[b].inertia * poses[b].Q.transpose();
    M += t.bodies[b].mass * Jv.transpose() * Jv + Jw.transpose() * J * Jw;
  }
  return M;
}

// ∂U/∂q = −Σ m J_vᵀ g.
inline Eigen::VectorXd oracle_gravity_forces(const OracleTree& t, const Eigen::VectorXd& q) {
  const std::vector<OraclePose> poses = oracle_poses(t, q);
  Eigen::VectorXd dU = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(t.model.coordinates));
  Eigen::MatrixXd Jv, Jw;
  for (std::size_t b = 0; b < t.bodies.size(); ++b) {
    oracle_jacobians(t, poses, b, Jv, Jw);
    dU -= t.bodies[b].mass * Jv.transpose() * t.model.gravity;
  }
  return dU;
}

// b of Lagrange's equations (3.7), with ∂M/∂q_k by fourth-order central differences.
inline Eigen::VectorXd oracle_bias(const OracleTree& t, const Eigen::VectorXd& q,
                                   const Eigen::VectorXd& qdot) {
  const auto n = static_cast<Eigen::Index>(t.model.coordinates);
  const double h = 1e-3;
  std::vector<Eigen::MatrixXd> dM;
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto M_at = [&](double s) {
      Eigen::VectorXd moved = q;
      moved[k] += s;
      return oracle_mass_matrix(t, moved);
    };
    dM.push_back((8.0 * (M_at(h) - M_at(-h)) - (M_at(2 * h) - M_at(-2 * h))) / (12.0 * h));
  }
  Eigen::VectorXd b = oracle_gravity_forces(t, q);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index k = 0; k < n; ++k)
      b[i] += dM[static_cast<std::size_t>(k)].row(i).dot(qdot) * qdot[k];
    b[i] -= 0.5 * qdot.dot(dM[static_cast<std::size_t>(i)] * qdot);
  }
  return b;
}

// The largest relative error ‖value − reference‖ / ‖reference‖ of `compare`, which returns the
// pair for a tree, over `trials` random trees of first, first + 2, … links (recorded).
template <class Compare>
double worst_over_random_trees(Random& random, int trials, std::size_t first, Compare compare) {
  double worst = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const OracleTree t = random_tree(random, first + 2 * static_cast<std::size_t>(trial));
    tree::TreeData data(t.model);
    const std::pair<Eigen::MatrixXd, Eigen::MatrixXd> both = compare(t, data);
    worst = std::max(worst, (both.first - both.second).norm() / both.second.norm());
  }
  record("relative_error", worst);
  return worst;
}

}  // namespace unidyn::test
