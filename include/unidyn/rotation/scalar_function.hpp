// Derivatives of a scalar function of a rotation, U = U(Q) (book §6.10).
//
// The rotation gradient u_Q is the vector with U̇ = u_Q · ω (6.40); it is how a potential energy of
// a rotation gives a conservative moment in the later chapters. Each function below computes u_Q
// from the partial derivatives of U in one parametrisation (6.42); all of them agree.
#pragma once

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/rotation/euler_parameters.hpp"
#include "unidyn/rotation/rodrigues_vector.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// (6.39) u_Q = −ε[U_Q], U_Q = ½ (∂U/∂Q Qᵀ − Q (∂U/∂Q)ᵀ), with ∂U/∂Q = Σ ∂U/∂Q_ik E_i⊗E_k.
Vec3 rotation_gradient(const Tensor& Q, const Tensor& dU_dQ);

// (6.41) u_Q = Σ ∂Û/∂γ^i g^i (dual Euler basis). Throws SingularConfiguration at gimbal lock.
Vec3 rotation_gradient(const EulerSet& set, const Vec3& angles, const Vec3& dU_dangles);

// (6.42)₂ u_Q = ∂Ũ/∂φ r + ½ (cot(φ/2) (I − r⊗r) − εr) ∂Ũ/∂r.
Vec3 rotation_gradient(const AxisAngle& rotation, double dU_dangle, const Vec3& dU_daxis);

// (6.42)₃ u_Q = ½ ((e0 I − εe) ∂Ū/∂e − ∂Ū/∂e0 e).
Vec3 rotation_gradient(const EulerParameters& p, double dU_de0, const Vec3& dU_de);

// (6.42)₄ u_Q = ½ (I + λ⊗λ − ελ) ∂Ǔ/∂λ.
Vec3 rotation_gradient(const RodriguesVector& v, const Vec3& dU_dlambda);

}  // namespace unidyn
