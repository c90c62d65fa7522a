// Ball and floating joints of a tree (tree_model.hpp): their Euler parameters e = (e0, ε) and
// rates ė as the twist ν = (ω, v) of the link on its own basis, and back from ν̇ to ë (and d̈).
//
// (6.36) R(e) = ((e0² − ε · ε) 1 + 2 ε εᵀ + 2 e0 ε×) / |e|² is a rotation for every e ≠ 0, as the
// model language writes it: it sees only the unit ê = e / s (s = |e|), and the norm s is free —
// the constraint e · e = 1 fixes it, and its multiplier is 0 (no force depends on s). With ê as
// a unit quaternion, ê̇ = ½ ê ⊗ (0, ω) for ω on the link's basis, so
//
//   ω = 2 (ê0 ε̂̇ − ê̇0 ε̂ − ε̂ × ε̂̇),    ê̈ = ½ ê ⊗ (0, ω̇) − ¼ |ω|² ê,
//
// and e = s ê gives ë = s̈ ê + 2 ṡ ê̇ + s ê̈ with s̈ = −ṡ² / s, the s that keeps e · ë + ė · ė = 0
// (the constraint's second derivative) whatever the state. A floating joint's d on the joint
// frame has ḋ = R v and d̈ = R (v̇ + ω × v).
#pragma once

#include "unidyn/tree/tree_model.hpp"

namespace unidyn::tree {

namespace euler_detail {

// The first of the Euler parameters among the link's coordinates (after x, y, z when floating).
inline Eigen::Index first_parameter(const TreeLink& link) {
  return link.coordinate + (link.kind == JointKind::floating ? 3 : 0);
}

// The quaternion product ê ⊗ (0, w): (−ε · w, e0 w + ε × w).
template <class S>
Eigen::Matrix<S, 4, 1> times_pure(const Eigen::Matrix<S, 4, 1>& e, const Vector3<S>& w) {
  Eigen::Matrix<S, 4, 1> out;
  const Vector3<S> epsilon = e.template tail<3>();
  out[0] = -epsilon.dot(w);
  out.template tail<3>() = e[0] * w + epsilon.cross(w);
  return out;
}

// (6.36) R(ê) of a unit ê = (e0, ε): (e0² − ε · ε) 1 + 2 ε εᵀ + 2 e0 ε×.
template <class S>
Matrix3<S> unit_rotation(const Eigen::Matrix<S, 4, 1>& e) {
  const Vector3<S> epsilon = e.template tail<3>();
  const S e0 = e[0];
  return Matrix3<S>::Identity() * (e0 * e0 - epsilon.dot(epsilon)) +
         (S(2) * epsilon) * epsilon.transpose() + cross_matrix(Vector3<S>(S(2) * e0 * epsilon));
}

}  // namespace euler_detail

// The link's placement E_i = R0 R(ê), r_i = p (+ R0 d) at q; fills ê, s and R(ê).
template <class S>
BasicFramePlacement<S> euler_joint_placement(const TreeLink& link,
                                             std::type_identity_t<BasicTreeVector<S>> q,
                                             BasicEulerJointData<S>& joint) {
  using std::sqrt;
  const Eigen::Matrix<S, 4, 1> e = q.template segment<4>(euler_detail::first_parameter(link));
  joint.norm = sqrt(e.dot(e));
  joint.unit = e / joint.norm;
  joint.rotation = euler_detail::unit_rotation(joint.unit);
  const Matrix3<S> R0 = link.fixed_rotation.cast<S>();
  BasicFramePlacement<S> X{R0 * joint.rotation, link.origin.cast<S>()};
  if (link.kind == JointKind::floating) {
    X.offset += R0 * Vector3<S>(q.template segment<3>(link.coordinate));
  }
  return X;
}

// The placement and the joint's twist ν at (q, q̇); fills ṡ and ê̇ too.
template <class S>
BasicFramePlacement<S> euler_joint_kinematics(const TreeLink& link,
                                              std::type_identity_t<BasicTreeVector<S>> q,
                                              std::type_identity_t<BasicTreeVector<S>> qdot,
                                              BasicEulerJointData<S>& joint) {
  const BasicFramePlacement<S> X = euler_joint_placement<S>(link, q, joint);
  // ė = ṡ ê + s ê̇ with ê · ê̇ = 0
  const Eigen::Matrix<S, 4, 1> edot = qdot.template segment<4>(euler_detail::first_parameter(link));
  joint.norm_rate = joint.unit.dot(edot);
  joint.unit_rate = (edot - joint.unit * joint.norm_rate) / joint.norm;
  // ω = 2 (ê0 ε̂̇ − ê̇0 ε̂ − ε̂ × ε̂̇), on the link's basis
  const Eigen::Matrix<S, 4, 1>& e = joint.unit;
  const Eigen::Matrix<S, 4, 1>& r = joint.unit_rate;
  const Vector3<S> epsilon = e.template tail<3>(), epsilon_rate = r.template tail<3>();
  joint.rate.template head<3>() =
      (epsilon_rate * e[0] - epsilon * r[0] - epsilon.cross(epsilon_rate)) * S(2);
  // v = Rᵀ ḋ
  joint.rate.template tail<3>() =
      link.kind == JointKind::floating
          ? Vector3<S>(joint.rotation.transpose() *
                       Vector3<S>(qdot.template segment<3>(link.coordinate)))
          : Vector3<S>::Zero();
  return X;
}

// ë (and d̈) of the link's coordinates from the joint's twist rate ν̇ (its first 3 or 6
// components), written into qddot.
template <class S>
void euler_joint_accelerations(const TreeLink& link, const BasicEulerJointData<S>& joint,
                               const Vector6<S>& rate_of_twist,
                               Eigen::Matrix<S, Eigen::Dynamic, 1>& qddot) {
  const Vector3<S> w = joint.rate.template head<3>();
  // ê̈ = ½ ê ⊗ (0, ω̇) − ¼ |ω|² ê;  ë = s̈ ê + 2 ṡ ê̇ + s ê̈, s̈ = −ṡ² / s
  const Eigen::Matrix<S, 4, 1> unit_acceleration =
      euler_detail::times_pure(joint.unit, Vector3<S>(rate_of_twist.template head<3>())) * S(0.5) -
      joint.unit * (S(0.25) * w.dot(w));
  const S s = joint.norm, sdot = joint.norm_rate;
  qddot.template segment<4>(euler_detail::first_parameter(link)) =
      joint.unit * (-sdot * sdot / s) + joint.unit_rate * (S(2) * sdot) + unit_acceleration * s;
  // d̈ = R (v̇ + ω × v)
  if (link.kind == JointKind::floating) {
    const Vector3<S> v = joint.rate.template tail<3>();
    qddot.template segment<3>(link.coordinate) =
        joint.rotation * Vector3<S>(rate_of_twist.template tail<3>() + w.cross(v));
  }
}

extern template FramePlacement euler_joint_placement<double>(const TreeLink&, TreeVector,
                                                             EulerJointData&);
extern template FramePlacement euler_joint_kinematics<double>(const TreeLink&, TreeVector,
                                                              TreeVector, EulerJointData&);
extern template void euler_joint_accelerations<double>(const TreeLink&, const EulerJointData&,
                                                       const Vector6d&, Eigen::VectorXd&);

}  // namespace unidyn::tree
