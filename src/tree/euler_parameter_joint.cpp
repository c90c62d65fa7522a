// Ball and floating joints: Euler parameters and the link's twist
// (include/unidyn/tree/euler_parameter_joint.hpp).
#include "unidyn/tree/euler_parameter_joint.hpp"

#include <cmath>

#include "unidyn/rotation/euler_parameters.hpp"

namespace unidyn::tree {

namespace {

// The first of the Euler parameters among the link's coordinates (after x, y, z when floating).
Eigen::Index first_parameter(const TreeLink& link) {
  return link.coordinate + (link.kind == JointKind::floating ? 3 : 0);
}

// The quaternion product ê ⊗ (0, w): (−ε · w, e0 w + ε × w).
Eigen::Vector4d times_pure(const Eigen::Vector4d& e, const Eigen::Vector3d& w) {
  Eigen::Vector4d out;
  out[0] = -e.tail<3>().dot(w);
  out.tail<3>() = e[0] * w + e.tail<3>().cross(w);
  return out;
}

}  // namespace

FramePlacement euler_joint_placement(const TreeLink& link, TreeVector q, EulerJointData& joint) {
  const Eigen::Vector4d e = q.segment<4>(first_parameter(link));
  joint.norm = e.norm();
  joint.unit = e / joint.norm;
  joint.rotation = rotation_tensor(EulerParameters{joint.unit[0], joint.unit.tail<3>()});  // (6.36)
  FramePlacement X{link.fixed_rotation * joint.rotation, link.origin};
  if (link.kind == JointKind::floating)
    X.offset += link.fixed_rotation * q.segment<3>(link.coordinate);
  return X;
}

FramePlacement euler_joint_kinematics(const TreeLink& link, TreeVector q, TreeVector qdot,
                                      EulerJointData& joint) {
  const FramePlacement X = euler_joint_placement(link, q, joint);
  // ė = ṡ ê + s ê̇ with ê · ê̇ = 0
  const Eigen::Vector4d edot = qdot.segment<4>(first_parameter(link));
  joint.norm_rate = joint.unit.dot(edot);
  joint.unit_rate = (edot - joint.norm_rate * joint.unit) / joint.norm;
  // ω = 2 (ê0 ε̂̇ − ê̇0 ε̂ − ε̂ × ε̂̇), on the link's basis
  const Eigen::Vector4d& e = joint.unit;
  const Eigen::Vector4d& r = joint.unit_rate;
  joint.rate.head<3>() =
      2 * (e[0] * r.tail<3>() - r[0] * e.tail<3>() - e.tail<3>().cross(r.tail<3>()));
  // v = Rᵀ ḋ
  joint.rate.tail<3>() =
      link.kind == JointKind::floating
          ? Eigen::Vector3d(joint.rotation.transpose() * qdot.segment<3>(link.coordinate))
          : Eigen::Vector3d::Zero();
  return X;
}

void euler_joint_accelerations(const TreeLink& link, const EulerJointData& joint,
                               const Vector6d& rate_of_twist, Eigen::VectorXd& qddot) {
  const Eigen::Vector3d w = joint.rate.head<3>();
  // ê̈ = ½ ê ⊗ (0, ω̇) − ¼ |ω|² ê;  ë = s̈ ê + 2 ṡ ê̇ + s ê̈, s̈ = −ṡ² / s
  const Eigen::Vector4d unit_acceleration =
      0.5 * times_pure(joint.unit, rate_of_twist.head<3>()) - 0.25 * w.squaredNorm() * joint.unit;
  const double s = joint.norm, sdot = joint.norm_rate;
  qddot.segment<4>(first_parameter(link)) =
      (-sdot * sdot / s) * joint.unit + 2 * sdot * joint.unit_rate + s * unit_acceleration;
  // d̈ = R (v̇ + ω × v)
  if (link.kind == JointKind::floating) {
    qddot.segment<3>(link.coordinate) =
        joint.rotation * (rate_of_twist.tail<3>() + w.cross(joint.rate.tail<3>()));
  }
}

}  // namespace unidyn::tree
