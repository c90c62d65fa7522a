// The Rodrigues (Gibbs) vector λ = tan(φ/2) r (book §6.9).
#pragma once

#include "unidyn/rotation/euler_parameters.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

struct RodriguesVector {
  Vec3 lambda;
};

// (6.36) Q = ((1 − λ · λ) I + 2 λ⊗λ − 2 ελ) / (1 + λ · λ).
Tensor rotation_tensor(const RodriguesVector& v);

// λ = e / e0. Undefined at φ = π (e0 = 0): throws SingularConfiguration when |e0| ≤ 1e-12.
RodriguesVector rodrigues_vector(const Tensor& Q);
RodriguesVector rodrigues_vector(const EulerParameters& p);

// e0 = 1/√(1 + λ · λ), e = λ e0.
EulerParameters euler_parameters(const RodriguesVector& v);

// (6.38) ω = 2 (λ̇ − λ̇ × λ) / (1 + λ · λ).
Vec3 angular_velocity(const RodriguesVector& v, const Vec3& lambda_rate);

// The inverse of (6.38): λ̇ = ½ (ω + ω × λ + (λ · ω) λ).
Vec3 rodrigues_vector_rate(const RodriguesVector& v, const Vec3& omega);

}  // namespace unidyn
