// Angular velocity tensors and vectors, corotational and relative rates (book §6.4 and §6.7).
#pragma once

#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// Ω = Q̇ Qᵀ, the (spatial) angular velocity tensor; it is skew (§6.4).
Tensor angular_velocity_tensor(const Tensor& Q, const Tensor& Q_rate);

// ω = −½ ε[Q̇ Qᵀ], so that ω × a = Ω a (§6.4).
Vec3 angular_velocity(const Tensor& Q, const Tensor& Q_rate);

// (6.7) body (convected) versions Ω0 = Qᵀ Q̇, ω0 = −½ ε[Qᵀ Q̇] = Qᵀ ω.
Tensor body_angular_velocity_tensor(const Tensor& Q, const Tensor& Q_rate);
Vec3 body_angular_velocity(const Tensor& Q, const Tensor& Q_rate);

// Q̇ = Ω Q for a given ω (the rate of a rotation tensor spinning at ω).
Tensor rotation_rate(const Tensor& Q, const Vec3& omega);

// (§6.4) corotational rates relative to a basis spinning at ω (Ω = skew(ω)):
//   å = ȧ − ω × a,   Å = Ȧ − Ω A + A Ω.
Vec3 corotational_rate(const Vec3& a, const Vec3& a_rate, const Vec3& omega);
Tensor corotational_rate(const Tensor& A, const Tensor& A_rate, const Vec3& omega);

// (6.17)–(6.18) relative angular velocity of R2 in the product R = R2 R1:
//   ω̂_R2 = ω_R − ω_R1 = −½ ε[R̊2 R2ᵀ],  R̊2 = Ṙ2 + R2 Ω_R1 − Ω_R1 R2
// (the rate of R2 seen from the basis R1 carries). In general ω̂_R2 ≠ ω_R2.
Vec3 relative_angular_velocity(const Tensor& R1, const Tensor& R1_rate, const Tensor& R2,
                               const Tensor& R2_rate);

}  // namespace unidyn
