// Spatial vectors of a body frame {o; e1, e2, e3} (Featherstone, Rigid Body Dynamics Algorithms,
// 2008, ch. 2), angular part first:
//
//   a twist (motion)  V = (ω, v_o)  — the angular velocity and the velocity of the point at o;
//   a wrench (force)  W = (n_o, f)  — the moment about o and the resultant;
//   a spatial inertia I with I V = (H_o, p), the angular momentum about o and the momentum.
//
// A child frame sits on its parent's frame at r (its origin from the parent's, parent basis) with
// the basis turned by E (child basis components of a vector u: Eᵀ u). With r× the cross-product
// matrix of r, the book's transport of velocities (v_o' = v_o + ω × r) and of moments
// (n_o = n_o' + r × f, (8.x)) give the transforms
//
//   V_child = Eᵀ (ω, v + ω × r),   W_parent = (E n + r × E f, E f),   I_parent = Xᵀ I_child X,
//
// X the twist transform. A rigid body of mass m, centre of mass c from o and inertia J0 about its
// centre (all on the body basis) has, with h = m c,   (7.x) H_o = (J0 + m (|c|² 1 − c cᵀ)) ω + h ×
// v, p = m v + ω × h:
//
//   I = [ Ī_o   h× ]      a symmetric 6 × 6 matrix; an articulated-body inertia is one too, of
//       [ −h×   m1 ]      the general form [A B; Bᵀ C].
#pragma once

#include <Eigen/Dense>

namespace unidyn::tree {

using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

// The cross-product matrix u× (u× w = u × w).
inline Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& u) {
  Eigen::Matrix3d m;
  m << 0, -u.z(), u.y(), u.z(), 0, -u.x(), -u.y(), u.x(), 0;
  return m;
}

// Where a child frame sits on its parent's: E and r as above.
struct FramePlacement {
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  // E
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();        // r, on the parent's basis
};

// A twist of the parent frame as a twist of the child frame: Eᵀ (ω, v + ω × r).
inline Vector6d twist_to_child(const FramePlacement& X, const Vector6d& V) {
  Vector6d out;
  const Eigen::Vector3d w = V.head<3>();
  out.head<3>() = X.rotation.transpose() * w;
  out.tail<3>() = X.rotation.transpose() * (V.tail<3>() + w.cross(X.offset));
  return out;
}

// A wrench on the child frame as one on the parent frame: (E n + r × E f, E f).
inline Vector6d wrench_to_parent(const FramePlacement& X, const Vector6d& W) {
  Vector6d out;
  out.tail<3>() = X.rotation * W.tail<3>();
  out.head<3>() = X.rotation * W.head<3>() + X.offset.cross(out.tail<3>());
  return out;
}

// A spatial inertia about the child's origin on its basis, about the parent's origin on the
// parent's basis: the blocks turned by E, then moved by r (Steiner's theorem for a general
// [A B; Bᵀ C]: A' = A + r× Bᵀ + (r× Bᵀ)ᵀ − r× C r×, B' = B + r× C, C' = C).
Matrix6d inertia_to_parent(const FramePlacement& X, const Matrix6d& I);

// Twist cross twist, V ×  U = (ω × u_ω, ω × u_v + v × u_ω): the rate of a twist U carried by V.
inline Vector6d twist_cross(const Vector6d& V, const Vector6d& U) {
  Vector6d out;
  const Eigen::Vector3d w = V.head<3>();
  out.head<3>() = w.cross(U.head<3>());
  out.tail<3>() = w.cross(U.tail<3>()) + V.tail<3>().cross(U.head<3>());
  return out;
}

// Twist cross wrench, V ×* W = (ω × n + v × f, ω × f): the rate of a momentum W carried by V.
inline Vector6d wrench_cross(const Vector6d& V, const Vector6d& W) {
  Vector6d out;
  const Eigen::Vector3d w = V.head<3>();
  out.head<3>() = w.cross(W.head<3>()) + V.tail<3>().cross(W.tail<3>());
  out.tail<3>() = w.cross(W.tail<3>());
  return out;
}

// The spatial inertia of a rigid body about its frame's origin (the header's I).
Matrix6d rigid_body_inertia(double mass, const Eigen::Vector3d& center,
                            const Eigen::Matrix3d& central_inertia);

}  // namespace unidyn::tree
