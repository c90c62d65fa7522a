// The articulated-body algorithm (Featherstone 2008, §7.3) over any scalar: q̈ of a tree in three
// passes (declared in tree_dynamics.hpp; double's compiled in src/tree/articulated_body.cpp).
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
//
// Every pivot D (and each of a k × k D's Cholesky pivots) goes through require_positive_pivot:
// in doubles it throws std::domain_error at one that is not positive; a recording scalar keeps
// them, to be checked where its trace is evaluated.
#pragma once

#include <stdexcept>
#include <string>

#include "unidyn/tree/euler_parameter_joint.hpp"
#include "unidyn/tree/tree_kinematics.hpp"

namespace unidyn::tree {

// D_i of the joint of `coordinate` (−1: a ball or floating joint's D, by its Cholesky factor).
inline void require_positive_pivot(double pivot, int coordinate) {
  if (pivot > 0) return;
  if (coordinate < 0) {
    throw std::domain_error("the inertia beyond a ball or floating joint is not positive definite");
  }
  throw std::domain_error("the inertia beyond the joint of coordinate " +
                          std::to_string(coordinate) + " about its axis is not positive");
}

namespace articulated_detail {

// D⁻¹ of a k × k D by its Cholesky factor D = L Lᵀ, each pivot L_jj² required positive.
template <class S, int k>
Eigen::Matrix<S, k, k> inverse_pivot(const Eigen::Matrix<S, k, k>& D) {
  using std::sqrt;
  Eigen::Matrix<S, k, k> L = Eigen::Matrix<S, k, k>::Zero();
  for (int j = 0; j < k; ++j) {
    S pivot = D(j, j);
    for (int m = 0; m < j; ++m) pivot -= L(j, m) * L(j, m);
    require_positive_pivot(pivot, -1);
    L(j, j) = sqrt(pivot);
    for (int i = j + 1; i < k; ++i) {
      S sum = D(i, j);
      for (int m = 0; m < j; ++m) sum -= L(i, m) * L(j, m);
      L(i, j) = sum / L(j, j);
    }
  }
  // D⁻¹ = L⁻ᵀ L⁻¹: the columns of L⁻¹ by forward substitution, then the product
  Eigen::Matrix<S, k, k> L_inverse = Eigen::Matrix<S, k, k>::Zero();
  for (int c = 0; c < k; ++c) {
    for (int i = c; i < k; ++i) {
      S sum = i == c ? S(1) : S(0);
      for (int m = c; m < i; ++m) sum -= L(i, m) * L_inverse(m, c);
      L_inverse(i, c) = sum / L(i, i);
    }
  }
  return L_inverse.transpose() * L_inverse;
}

// In doubles, Eigen's Cholesky factorisation.
template <int k>
Eigen::Matrix<double, k, k> inverse_pivot(const Eigen::Matrix<double, k, k>& D) {
  const Eigen::LLT<Eigen::Matrix<double, k, k>> factor(D);
  require_positive_pivot(factor.info() == Eigen::Success ? 1.0 : 0.0, -1);
  return factor.solve(Eigen::Matrix<double, k, k>::Identity());
}

// I S and Sᵀ w for S = (a, 0) or (0, a): half the products of the 6 × 6 forms.
template <class S>
Vector6<S> inertia_along_joint(const TreeLink& link, const Matrix6<S>& I) {
  const Vector3<S> a = link.axis.cast<S>();
  return link.kind == JointKind::revolute ? Vector6<S>(I.template leftCols<3>() * a)
                                          : Vector6<S>(I.template rightCols<3>() * a);
}
template <class S>
S along_joint(const TreeLink& link, const Vector6<S>& w) {
  const Vector3<S> a = link.axis.cast<S>();
  return link.kind == JointKind::revolute ? a.dot(w.template head<3>())
                                          : a.dot(w.template tail<3>());
}

// Pass 2 at a ball (k = 3) or floating (k = 6) joint: U, D⁻¹, u, and I^a, p^a in place.
template <int k, class S>
void euler_joint_articulated(const BasicLinkData<S>& d, BasicEulerJointData<S>& joint,
                             Matrix6<S>& Ia, Vector6<S>& pa) {
  const Eigen::Matrix<S, 6, k> U = Ia.template leftCols<k>();
  const Eigen::Matrix<S, k, k> D_inverse =
      inverse_pivot(Eigen::Matrix<S, k, k>(Ia.template topLeftCorner<k, k>()));
  joint.inertia_axes.template leftCols<k>() = U;
  joint.inverse_pivot.template topLeftCorner<k, k>() = D_inverse;
  joint.torque.template head<k>() = -pa.template head<k>();
  const Eigen::Matrix<S, k, 1> u = joint.torque.template head<k>();
  Ia -= U * D_inverse * U.transpose();
  mirror_upper(Ia);
  pa += Ia * d.bias + U * Eigen::Matrix<S, k, 1>(D_inverse * u);
}

// Pass 3 at a ball or floating joint: ν̇ = D⁻¹ (u − Uᵀ A), A += S ν̇.
template <int k, class S>
Vector6<S> euler_joint_rate_of_twist(const BasicEulerJointData<S>& joint, Vector6<S>& A) {
  Vector6<S> rate = Vector6<S>::Zero();
  const Eigen::Matrix<S, k, 1> u = joint.torque.template head<k>();
  const Eigen::Matrix<S, 6, k> U = joint.inertia_axes.template leftCols<k>();
  rate.template head<k>() = joint.inverse_pivot.template topLeftCorner<k, k>() *
                            Eigen::Matrix<S, k, 1>(u - U.transpose() * A);
  A.template head<k>() += rate.template head<k>();
  return rate;
}

// Pass 2, inward: I^A_i, p^A_i, U_i, D_i, u_i.
template <class S>
void articulated_inertias(const TreeModel& model, std::type_identity_t<BasicTreeVector<S>> tau,
                          BasicTreeData<S>& data) {
  for (std::size_t k = model.links.size(); k-- > 0;) {
    const TreeLink& link = model.links[k];
    BasicLinkData<S>& d = data.links[k];
    Matrix6<S> Ia = d.articulated;
    Vector6<S> pa = d.force;
    if (link.kind == JointKind::ball) euler_joint_articulated<3>(d, data.euler[k], Ia, pa);
    if (link.kind == JointKind::floating) euler_joint_articulated<6>(d, data.euler[k], Ia, pa);
    if (link.coordinate >= 0 && !has_euler_parameters(link)) {
      d.inertia_axis = inertia_along_joint(link, Ia);
      d.pivot = along_joint(link, d.inertia_axis);
      d.torque = S(tau[link.coordinate]) - along_joint(link, pa);
      require_positive_pivot(d.pivot, link.coordinate);
      // one division, by D (eight multiplications by 1/D instead)
      const S inverse = S(1) / d.pivot;
      Ia -= Vector6<S>(d.inertia_axis * inverse) * d.inertia_axis.transpose();
      mirror_upper(Ia);
      pa += Ia * d.bias + d.inertia_axis * S(d.torque * inverse);
    }
    if (link.parent < 0) continue;
    BasicLinkData<S>& parent = data.links[static_cast<std::size_t>(link.parent)];
    parent.articulated += inertia_to_parent(d.placement, Ia);
    parent.force += wrench_to_parent(d.placement, pa);
  }
}

}  // namespace articulated_detail

template <class S>
void articulated_body_accelerations(const TreeModel& model,
                                    std::type_identity_t<BasicTreeVector<S>> q,
                                    std::type_identity_t<BasicTreeVector<S>> qdot,
                                    std::type_identity_t<BasicTreeVector<S>> tau,
                                    Eigen::Matrix<S, Eigen::Dynamic, 1>& qddot,
                                    BasicTreeData<S>& data) {
  // pass 1: twists and biases; each link's own I and the bias wrench V ×* I V
  tree_kinematics<S>(model, q, qdot, data);
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    BasicLinkData<S>& d = data.links[i];
    d.articulated = model.links[i].inertia.template cast<S>();
    d.force = wrench_cross(d.velocity, Vector6<S>(d.articulated * d.velocity));
  }
  articulated_detail::articulated_inertias<S>(model, tau, data);
  // pass 3, outward: A_i = X_i A_parent + c_i, q̈_i = (u_i − U_iᵀ A_i) / D_i, then + S q̈_i
  qddot.resize(static_cast<Eigen::Index>(model.coordinates));
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    BasicLinkData<S>& d = data.links[i];
    d.acceleration = carried_acceleration(model, data, i);
    if (has_euler_parameters(link)) {
      const Vector6<S> rate =
          link.kind == JointKind::ball
              ? articulated_detail::euler_joint_rate_of_twist<3>(data.euler[i], d.acceleration)
              : articulated_detail::euler_joint_rate_of_twist<6>(data.euler[i], d.acceleration);
      euler_joint_accelerations(link, data.euler[i], rate, qddot);
      continue;
    }
    if (link.coordinate < 0) continue;
    const S acceleration = (d.torque - d.inertia_axis.dot(d.acceleration)) * (S(1) / d.pivot);
    qddot[link.coordinate] = acceleration;
    const Vector3<S> change = link.axis.cast<S>() * acceleration;
    if (link.kind == JointKind::revolute) d.acceleration.template head<3>() += change;
    if (link.kind == JointKind::prismatic) d.acceleration.template tail<3>() += change;
  }
}

}  // namespace unidyn::tree
