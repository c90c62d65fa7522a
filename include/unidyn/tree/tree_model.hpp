// A kinematic tree in numbers, for the recursive algorithms (Featherstone 2008, ch. 4–7): an
// immutable TreeModel — the links, each a body on a joint, parents before children — and a
// mutable TreeData of one evaluation (as Pinocchio separates Model from Data).
//
// Link i's frame sits on its parent's frame (the ground's {O; E1, E2, E3} for a root) as the model
// language's tree joints place it (model/tree_joint.hpp): the joint frame at the origin p and
// turned by R0, then the joint's motion,
//   E_i = R0 L(q, a)  (revolute, (6.8)) or R0 (prismatic, fixed);   r_i = p + R0 q a (prismatic) or
//   p,
// and the joint's twist is S q̇ with S = (a, 0) (revolute) or (0, a) (prismatic), a on the link's
// basis (L(q, a) a = a). Gravity g enters as the ground's acceleration −g (the bodies then feel
// m g at their centres).
//
// A ball joint turns the link by the Euler parameters e = (e0, e1, e2, e3) of its four
// coordinates, E_i = R0 R(e) ((6.36)), and a floating joint also moves it by d = (x, y, z) on the
// joint frame (seven coordinates x, y, z, e0..e3), r_i = p + R0 d. Their twists are the link's own
// angular velocity ω and (floating) the velocity v of its origin, on its basis: S selects the
// first three or all six components of (ω, v) (euler_parameter_joint.hpp maps q̇ to them).
#pragma once

#include <Eigen/Dense>
#include <type_traits>
#include <vector>

#include "unidyn/tree/spatial.hpp"

namespace unidyn::tree {

enum class JointKind { fixed, revolute, prismatic, ball, floating };

struct TreeLink {
  int parent = -1;  // an earlier link; −1: the ground
  JointKind kind = JointKind::fixed;
  int coordinate = -1;  // the index of its (first) q; −1 for a fixed joint
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();               // a, unit
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();              // p, on the parent's basis
  Eigen::Matrix3d fixed_rotation = Eigen::Matrix3d::Identity();  // R0
  Matrix6d inertia = Matrix6d::Zero();  // the body's, about the link's origin (rigid_body_inertia)
};

struct TreeModel {
  std::vector<TreeLink> links;
  std::size_t coordinates = 0;                        // n: every coordinate is one joint's
  Eigen::Vector3d gravity = Eigen::Vector3d::Zero();  // g, on the ground's basis
};

// One link's numbers during an evaluation (S: double, or a recording scalar).
template <class S>
struct BasicLinkData {
  BasicFramePlacement<S> placement;         // E_i, r_i from the parent
  Vector6<S> velocity, bias, acceleration;  // V_i; c_i = V_i × S q̇; the twist rate
  Matrix6<S> articulated;                   // I^A_i (ABA) or the composite inertia I^c_i (CRBA)
  Vector6<S> force;               // p^A_i (ABA) or the wrench of the inverse dynamics (RNEA)
  Vector6<S> inertia_axis;        // U_i = I^A_i S (ABA)
  S pivot = S(0), torque = S(0);  // D_i = Sᵀ U_i, u_i = τ_i − Sᵀ p^A_i (ABA)
};
using LinkData = BasicLinkData<double>;

// q, q̇, τ: a vector or a segment of one, taken without a copy.
template <class S>
using BasicTreeVector = Eigen::Ref<const Eigen::Matrix<S, Eigen::Dynamic, 1>>;
using TreeVector = BasicTreeVector<double>;

// A ball or floating joint's numbers during an evaluation (euler_parameter_joint.hpp).
template <class S>
struct BasicEulerJointData {
  // the Euler parameters as the unit ê = e / s, s = |e|, and the rates ṡ, ê̇
  Eigen::Matrix<S, 4, 1> unit = Eigen::Matrix<S, 4, 1>::UnitX(),
                         unit_rate = Eigen::Matrix<S, 4, 1>::Zero();
  S norm = S(1), norm_rate = S(0);
  Matrix3<S> rotation = Matrix3<S>::Identity();  // R(ê)
  Vector6<S> rate = Vector6<S>::Zero();  // the joint's twist ν = (ω, v) on the link's basis
  // ABA: U = I^A S, D⁻¹ = (Sᵀ I^A S)⁻¹ and u = −Sᵀ p^A (k = 3 or 6 of the 6 rows)
  Matrix6<S> inertia_axes = Matrix6<S>::Zero(), inverse_pivot = Matrix6<S>::Zero();
  Vector6<S> torque = Vector6<S>::Zero();
};
using EulerJointData = BasicEulerJointData<double>;

template <class S>
struct BasicTreeData {
  std::vector<BasicLinkData<S>> links;
  std::vector<BasicEulerJointData<S>> euler;  // per link; empty when no link has one
  BasicTreeData() = default;
  explicit BasicTreeData(const TreeModel& model) : links(model.links.size()) {
    for (const TreeLink& link : model.links) {
      if (link.kind == JointKind::ball || link.kind == JointKind::floating) {
        euler.resize(model.links.size());
      }
    }
  }
};
using TreeData = BasicTreeData<double>;

// Whether the link's joint is a ball or floating joint (several twist components).
inline bool has_euler_parameters(const TreeLink& link) {
  return link.kind == JointKind::ball || link.kind == JointKind::floating;
}

// Whether any link has a ball or floating joint.
inline bool has_euler_parameters(const TreeModel& model) {
  for (const TreeLink& link : model.links) {
    if (has_euler_parameters(link)) return true;
  }
  return false;
}

// The twist S of a link's one-coordinate joint (zero for a fixed joint).
inline Vector6d joint_axis(const TreeLink& link) {
  Vector6d S = Vector6d::Zero();
  if (link.kind == JointKind::revolute) S.head<3>() = link.axis;
  if (link.kind == JointKind::prismatic) S.tail<3>() = link.axis;
  return S;
}

// Each link's placement E_i, r_i at q. (The passes are templates over the scalar, defined in
// tree_kinematics.hpp; double's are compiled once, in src/tree/.)
template <class S>
void tree_placements(const TreeModel& model, std::type_identity_t<BasicTreeVector<S>> q,
                     BasicTreeData<S>& data);
extern template void tree_placements<double>(const TreeModel&, TreeVector, TreeData&);

// The ground's acceleration, (0, −g): gravity as a fictitious lift of the whole tree.
inline Vector6d ground_acceleration(const TreeModel& model) {
  Vector6d a = Vector6d::Zero();
  a.tail<3>() = -model.gravity;
  return a;
}

// A_i = X_i A_parent + c_i (the ground's (0, −g) for a root): link i's acceleration while its own
// joint does not accelerate.
template <class S>
Vector6<S> carried_acceleration(const TreeModel& model, const BasicTreeData<S>& data,
                                std::size_t i) {
  const int parent = model.links[i].parent;
  const BasicLinkData<S>& d = data.links[i];
  const Vector6<S> A_parent = parent < 0
                                  ? Vector6<S>(ground_acceleration(model).template cast<S>())
                                  : data.links[static_cast<std::size_t>(parent)].acceleration;
  return twist_to_child(d.placement, A_parent) + d.bias;
}

// Pass 1 of every algorithm: each link's placement, twist V_i = X_i V_parent + S q̇ and bias
// c_i = V_i × S q̇ at (q, q̇).
template <class S>
void tree_kinematics(const TreeModel& model, std::type_identity_t<BasicTreeVector<S>> q,
                     std::type_identity_t<BasicTreeVector<S>> qdot, BasicTreeData<S>& data);
extern template void tree_kinematics<double>(const TreeModel&, TreeVector, TreeVector, TreeData&);

}  // namespace unidyn::tree
