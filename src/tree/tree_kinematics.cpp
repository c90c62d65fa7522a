// Pass 1 of the recursive algorithms: placements, twists and velocity-product accelerations
// (include/unidyn/tree/tree_model.hpp).
#include <cmath>

#include "unidyn/tree/euler_parameter_joint.hpp"
#include "unidyn/tree/tree_model.hpp"

namespace unidyn::tree {

namespace {

// (6.8) Euler's representation of a rotation: L(θ, a) = cos θ 1 + sin θ a× + (1 − cos θ) a aᵀ.
Eigen::Matrix3d axis_angle(const Eigen::Vector3d& a, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * Eigen::Matrix3d::Identity() + s * cross_matrix(a) + (1 - c) * a * a.transpose();
}

// E_i and r_i of the link at its coordinate's value.
FramePlacement placement(const TreeLink& link, double q) {
  FramePlacement X{link.fixed_rotation, link.origin};
  if (link.kind == JointKind::revolute) X.rotation = link.fixed_rotation * axis_angle(link.axis, q);
  if (link.kind == JointKind::prismatic) X.offset += link.fixed_rotation * (q * link.axis);
  return X;
}

}  // namespace

void tree_placements(const TreeModel& model, TreeVector q, TreeData& data) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    data.links[i].placement = has_euler_parameters(link)
                                  ? euler_joint_placement(link, q, data.euler[i])
                                  : placement(link, link.coordinate < 0 ? 0.0 : q[link.coordinate]);
  }
}

void tree_kinematics(const TreeModel& model, TreeVector q, TreeVector qdot, TreeData& data) {
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    LinkData& d = data.links[i];
    // V_i = X_i V_parent + S q̇ (the ground is at rest), c_i = V_i × S q̇
    Vector6d joint_twist;
    if (has_euler_parameters(link)) {
      d.placement = euler_joint_kinematics(link, q, qdot, data.euler[i]);
      joint_twist = data.euler[i].rate;
    } else {
      const bool moves = link.coordinate >= 0;
      d.placement = placement(link, moves ? q[link.coordinate] : 0.0);
      joint_twist = joint_axis(link) * (moves ? qdot[link.coordinate] : 0.0);
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
