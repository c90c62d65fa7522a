// Pass 1 of the recursive algorithms over any scalar: placements, twists and velocity-product
// accelerations (declared in tree_model.hpp; double's compiled in src/tree/tree_kinematics.cpp).
#pragma once

#include "unidyn/tree/euler_parameter_joint.hpp"
#include "unidyn/tree/tree_model.hpp"

namespace unidyn::tree {

namespace kinematics_detail {

// (6.8) Euler's representation of a rotation: L(θ, a) = cos θ 1 + sin θ a× + (1 − cos θ) a aᵀ.
template <class S>
Matrix3<S> axis_angle(const Eigen::Vector3d& a, const S& angle) {
  using std::cos, std::sin;
  const S c = cos(angle), s = sin(angle);
  const Vector3<S> a_S = a.cast<S>();
  const Vector3<S> scaled = a_S * (S(1) - c);
  return Matrix3<S>::Identity() * c + cross_matrix(a_S) * s + scaled * a_S.transpose();
}

// E_i and r_i of the link at its coordinate's value.
template <class S>
BasicFramePlacement<S> placement(const TreeLink& link, const S& q) {
  BasicFramePlacement<S> X{link.fixed_rotation.cast<S>(), link.origin.cast<S>()};
  if (link.kind == JointKind::revolute) {
    X.rotation = link.fixed_rotation.cast<S>() * axis_angle(link.axis, q);
  }
  if (link.kind == JointKind::prismatic) {
    X.offset += link.fixed_rotation.cast<S>() * Vector3<S>(link.axis.cast<S>() * q);
  }
  return X;
}

// The twist S q̇ of a one-coordinate joint.
template <class S>
Vector6<S> joint_twist(const TreeLink& link, const S& qdot) {
  return joint_axis(link).cast<S>() * qdot;
}

}  // namespace kinematics_detail

template <class S>
void tree_placements(const TreeModel& model, std::type_identity_t<BasicTreeVector<S>> q,
                     BasicTreeData<S>& data) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    data.links[i].placement = has_euler_parameters(link)
                                  ? euler_joint_placement<S>(link, q, data.euler[i])
                                  : kinematics_detail::placement(
                                        link, link.coordinate < 0 ? S(0) : S(q[link.coordinate]));
  }
}

template <class S>
void tree_kinematics(const TreeModel& model, std::type_identity_t<BasicTreeVector<S>> q,
                     std::type_identity_t<BasicTreeVector<S>> qdot, BasicTreeData<S>& data) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    BasicLinkData<S>& d = data.links[i];
    // V_i = X_i V_parent + S q̇ (the ground is at rest), c_i = V_i × S q̇
    Vector6<S> joint_twist;
    if (has_euler_parameters(link)) {
      d.placement = euler_joint_kinematics<S>(link, q, qdot, data.euler[i]);
      joint_twist = data.euler[i].rate;
    } else {
      const bool moves = link.coordinate >= 0;
      d.placement = kinematics_detail::placement(link, moves ? S(q[link.coordinate]) : S(0));
      joint_twist = kinematics_detail::joint_twist(link, moves ? S(qdot[link.coordinate]) : S(0));
    }
    d.velocity = joint_twist;
    if (link.parent >= 0) {
      d.velocity +=
          twist_to_child(d.placement, data.links[static_cast<std::size_t>(link.parent)].velocity);
    }
    d.bias = twist_cross(d.velocity, joint_twist);
  }
}

}  // namespace unidyn::tree
