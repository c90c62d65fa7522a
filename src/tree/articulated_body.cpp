// The articulated-body algorithm (Featherstone 2008, §7.3): q̈ of a tree in three passes.
//
// Cut the tree at joint i: the links beyond it, free to move in their own joints, resist an
// acceleration A of link i with the wrench I^A_i A + p^A_i — the articulated inertia and bias
// force. Working inward from the leaves, a child passes on what its joint cannot transmit: with
// U = I^A S, D = Sᵀ U and u = τ − Sᵀ p^A, its joint's q̈ = (u − Uᵀ A_parent') / D, so
//   I^a = I^A − U Uᵀ / D,   p^a = p^A + I^a c + U u / D
// are added, moved to the parent's frame, to the parent's I^A and p^A (which start as the body's
// own I and V ×* I V). Working outward, each A_i = X_i A_parent + c_i gives q̈_i, and the link's
// acceleration A_i + S q̈_i its children's. Gravity is the ground's acceleration (0, −g).
//
// A ball or floating joint (S: the first 3 or all 6 components of the link's twist) does the same
// with U = I^A S (6 × k), D = Sᵀ U (k × k), u = −Sᵀ p^A: ν̇ = D⁻¹ (u − Uᵀ A), I^a = I^A − U D⁻¹ Uᵀ,
// p^a = p^A + I^a c + U D⁻¹ u (a floating joint passes nothing on: I^a = 0, p^a = 0).
#include <stdexcept>
#include <string>

#include "unidyn/tree/euler_parameter_joint.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {

namespace {

// I S and Sᵀ w for S = (a, 0) or (0, a): half the products of the 6 × 6 forms.
Vector6d inertia_along_joint(const TreeLink& link, const Matrix6d& I) {
  return link.kind == JointKind::revolute ? Vector6d(I.leftCols<3>() * link.axis)
                                          : Vector6d(I.rightCols<3>() * link.axis);
}
double along_joint(const TreeLink& link, const Vector6d& w) {
  return link.kind == JointKind::revolute ? link.axis.dot(w.head<3>()) : link.axis.dot(w.tail<3>());
}

// Pass 2 at a ball (k = 3) or floating (k = 6) joint: U, D⁻¹, u, and I^a, p^a in place.
template <int k>
void euler_joint_articulated(const LinkData& d, EulerJointData& joint, Matrix6d& Ia, Vector6d& pa) {
  const Eigen::Matrix<double, 6, k> U = Ia.template leftCols<k>();
  const Eigen::LLT<Eigen::Matrix<double, k, k>> D(Ia.template topLeftCorner<k, k>());
  if (D.info() != Eigen::Success) {
    throw std::domain_error("the inertia beyond a ball or floating joint is not positive definite");
  }
  const Eigen::Matrix<double, k, k> D_inverse = D.solve(Eigen::Matrix<double, k, k>::Identity());
  joint.inertia_axes.template leftCols<k>() = U;
  joint.inverse_pivot.template topLeftCorner<k, k>() = D_inverse;
  joint.torque.template head<k>() = -pa.template head<k>();
  Ia.noalias() -= U * D_inverse * U.transpose();
  pa += Ia * d.bias + U * (D_inverse * joint.torque.template head<k>());
}

// Pass 3 at a ball or floating joint: ν̇ = D⁻¹ (u − Uᵀ A), A += S ν̇.
template <int k>
Vector6d euler_joint_rate_of_twist(const EulerJointData& joint, Vector6d& A) {
  Vector6d rate = Vector6d::Zero();
  rate.head<k>() =
      joint.inverse_pivot.template topLeftCorner<k, k>() *
      (joint.torque.template head<k>() - joint.inertia_axes.template leftCols<k>().transpose() * A);
  A.head<k>() += rate.head<k>();
  return rate;
}

// Pass 2, inward: I^A_i, p^A_i, U_i, D_i, u_i.
void articulated_inertias(const TreeModel& model, TreeVector tau, TreeData& data) {
  for (std::size_t k = model.links.size(); k-- > 0;) {
    const TreeLink& link = model.links[k];
    LinkData& d = data.links[k];
    Matrix6d Ia = d.articulated;
    Vector6d pa = d.force;
    if (link.kind == JointKind::ball) euler_joint_articulated<3>(d, data.euler[k], Ia, pa);
    if (link.kind == JointKind::floating) euler_joint_articulated<6>(d, data.euler[k], Ia, pa);
    if (link.coordinate >= 0 && !has_euler_parameters(link)) {
      d.inertia_axis = inertia_along_joint(link, Ia);
      d.pivot = along_joint(link, d.inertia_axis);
      d.torque = tau[link.coordinate] - along_joint(link, pa);
      if (!(d.pivot > 0)) {
        throw std::domain_error("the inertia beyond the joint of coordinate " +
                                std::to_string(link.coordinate) +
                                " about its axis is not positive");
      }
      Ia.noalias() -= (d.inertia_axis / d.pivot) * d.inertia_axis.transpose();
      pa += Ia * d.bias + d.inertia_axis * (d.torque / d.pivot);
    }
    if (link.parent < 0) continue;
    LinkData& parent = data.links[static_cast<std::size_t>(link.parent)];
    parent.articulated += inertia_to_parent(d.placement, Ia);
    parent.force += wrench_to_parent(d.placement, pa);
  }
}

}  // namespace

void articulated_body_accelerations(const TreeModel& model, TreeVector q, TreeVector qdot,
                                    TreeVector tau, Eigen::VectorXd& qddot, TreeData& data) {
  // pass 1: twists and biases; each link's own I and the bias wrench V ×* I V
  tree_kinematics(model, q, qdot, data);
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    LinkData& d = data.links[i];
    d.articulated = model.links[i].inertia;
    d.force = wrench_cross(d.velocity, d.articulated * d.velocity);
  }
  articulated_inertias(model, tau, data);
  // pass 3, outward: A_i = X_i A_parent + c_i, q̈_i = (u_i − U_iᵀ A_i) / D_i, then + S q̈_i
  qddot.resize(static_cast<Eigen::Index>(model.coordinates));
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    LinkData& d = data.links[i];
    d.acceleration = carried_acceleration(model, data, i);
    if (has_euler_parameters(link)) {
      const Vector6d rate = link.kind == JointKind::ball
                                ? euler_joint_rate_of_twist<3>(data.euler[i], d.acceleration)
                                : euler_joint_rate_of_twist<6>(data.euler[i], d.acceleration);
      euler_joint_accelerations(link, data.euler[i], rate, qddot);
      continue;
    }
    if (link.coordinate < 0) continue;
    const double acceleration = (d.torque - d.inertia_axis.dot(d.acceleration)) / d.pivot;
    qddot[link.coordinate] = acceleration;
    (link.kind == JointKind::revolute ? d.acceleration.head<3>() : d.acceleration.tail<3>()) +=
        link.axis * acceleration;
  }
}

}  // namespace unidyn::tree
