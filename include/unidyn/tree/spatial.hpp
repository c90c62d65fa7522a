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
//
// Each operation is a template over the scalar S: double, or the recording scalar of
// numeric/tape_recorder.hpp that traces an algorithm once into a tape.
#pragma once

#include <Eigen/Dense>

namespace unidyn::tree {

template <class S>
using Vector3 = Eigen::Matrix<S, 3, 1>;
template <class S>
using Matrix3 = Eigen::Matrix<S, 3, 3>;
template <class S>
using Vector6 = Eigen::Matrix<S, 6, 1>;
template <class S>
using Matrix6 = Eigen::Matrix<S, 6, 6>;
using Vector6d = Vector6<double>;
using Matrix6d = Matrix6<double>;

// The cross-product matrix u× (u× w = u × w).
template <class S>
Matrix3<S> cross_matrix(const Vector3<S>& u) {
  Matrix3<S> m;
  m << S(0), -u.z(), u.y(), u.z(), S(0), -u.x(), -u.y(), u.x(), S(0);
  return m;
}

// A matrix known to be symmetric made exactly so: its upper triangle copied to the lower (a
// recorded algorithm then computes each pair of entries once — the lower ones are dead code).
template <class Derived>
void mirror_upper(Eigen::MatrixBase<Derived>& M) {
  for (Eigen::Index i = 0; i < M.rows(); ++i) {
    for (Eigen::Index j = i + 1; j < M.cols(); ++j) M(j, i) = M(i, j);
  }
}

// Where a child frame sits on its parent's: E and r as above.
template <class S>
struct BasicFramePlacement {
  Matrix3<S> rotation = Matrix3<S>::Identity();  // E
  Vector3<S> offset = Vector3<S>::Zero();        // r, on the parent's basis
};
using FramePlacement = BasicFramePlacement<double>;

// A twist of the parent frame as a twist of the child frame: Eᵀ (ω, v + ω × r).
template <class S>
Vector6<S> twist_to_child(const BasicFramePlacement<S>& X, const Vector6<S>& V) {
  Vector6<S> out;
  const Vector3<S> w = V.template head<3>();
  out.template head<3>() = X.rotation.transpose() * w;
  out.template tail<3>() = X.rotation.transpose() * (V.template tail<3>() + w.cross(X.offset));
  return out;
}

// A wrench on the child frame as one on the parent frame: (E n + r × E f, E f).
template <class S>
Vector6<S> wrench_to_parent(const BasicFramePlacement<S>& X, const Vector6<S>& W) {
  Vector6<S> out;
  out.template tail<3>() = X.rotation * W.template tail<3>();
  const Vector3<S> f = out.template tail<3>();
  out.template head<3>() = X.rotation * W.template head<3>() + X.offset.cross(f);
  return out;
}

// A spatial inertia about the child's origin on its basis, about the parent's origin on the
// parent's basis: the blocks turned by E, then moved by r (Steiner's theorem for a general
// [A B; Bᵀ C]: A' = A + r× Bᵀ + (r× Bᵀ)ᵀ − r× C r×, B' = B + r× C, C' = C).
template <class S>
Matrix6<S> inertia_to_parent(const BasicFramePlacement<S>& X, const Matrix6<S>& I) {
  const Matrix3<S>& E = X.rotation;
  // the blocks on the parent's basis, still about the child's origin (A, C symmetric)
  Matrix3<S> A = E * I.template topLeftCorner<3, 3>() * E.transpose();
  const Matrix3<S> B = E * I.template topRightCorner<3, 3>() * E.transpose();
  Matrix3<S> C = E * I.template bottomRightCorner<3, 3>() * E.transpose();
  mirror_upper(A);
  mirror_upper(C);
  // Steiner: about the parent's origin, r× = R
  const Matrix3<S> R = cross_matrix(X.offset);
  const Matrix3<S> RBt = R * B.transpose();
  const Matrix3<S> RC = R * C;
  Matrix6<S> out;
  Matrix3<S> top_left = A + RBt + RBt.transpose() - RC * R;
  mirror_upper(top_left);
  out.template topLeftCorner<3, 3>() = top_left;
  out.template topRightCorner<3, 3>() = B + RC;
  out.template bottomLeftCorner<3, 3>() = (B + RC).transpose();
  out.template bottomRightCorner<3, 3>() = C;
  return out;
}

// Twist cross twist, V ×  U = (ω × u_ω, ω × u_v + v × u_ω): the rate of a twist U carried by V.
template <class S>
Vector6<S> twist_cross(const Vector6<S>& V, const Vector6<S>& U) {
  Vector6<S> out;
  const Vector3<S> w = V.template head<3>(), v = V.template tail<3>();
  const Vector3<S> u_w = U.template head<3>(), u_v = U.template tail<3>();
  out.template head<3>() = w.cross(u_w);
  out.template tail<3>() = w.cross(u_v) + v.cross(u_w);
  return out;
}

// Twist cross wrench, V ×* W = (ω × n + v × f, ω × f): the rate of a momentum W carried by V.
template <class S>
Vector6<S> wrench_cross(const Vector6<S>& V, const Vector6<S>& W) {
  Vector6<S> out;
  const Vector3<S> w = V.template head<3>(), v = V.template tail<3>();
  const Vector3<S> n = W.template head<3>(), f = W.template tail<3>();
  out.template head<3>() = w.cross(n) + v.cross(f);
  out.template tail<3>() = w.cross(f);
  return out;
}

// The spatial inertia of a rigid body about its frame's origin (the header's I).
Matrix6d rigid_body_inertia(double mass, const Eigen::Vector3d& center,
                            const Eigen::Matrix3d& central_inertia);

}  // namespace unidyn::tree
