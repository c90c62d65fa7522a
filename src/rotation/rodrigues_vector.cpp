// The Rodrigues (Gibbs) vector λ = tan(φ/2) r (§6.9).
#include "unidyn/rotation/rodrigues_vector.hpp"

#include <cmath>

#include "unidyn/rotation/errors.hpp"

namespace unidyn {

Tensor rotation_tensor(const RodriguesVector& v) {
  const Vec3& l = v.lambda;
  const double ll = l.dot(l);
  // (6.36) Q = ((1 − λ · λ) I + 2 λ⊗λ − 2 ελ) / (1 + λ · λ)
  return ((1.0 - ll) * Tensor::Identity() + 2.0 * tensor_product(l, l) -
          2.0 * alternator_times(l)) /
         (1.0 + ll);
}

RodriguesVector rodrigues_vector(const EulerParameters& p) {
  if (std::abs(p.e0) <= 1e-12) {
    throw SingularConfiguration("the Rodrigues vector does not exist at rotation angle π");
  }
  return {p.e / p.e0};
}

RodriguesVector rodrigues_vector(const Tensor& Q) {
  return rodrigues_vector(euler_parameters(Q));
}

EulerParameters euler_parameters(const RodriguesVector& v) {
  const double e0 = 1.0 / std::sqrt(1.0 + v.lambda.dot(v.lambda));
  return {e0, e0 * v.lambda};
}

Vec3 angular_velocity(const RodriguesVector& v, const Vec3& lambda_rate) {
  // (6.38) ω = 2 (λ̇ − λ̇ × λ) / (1 + λ · λ)
  return 2.0 * (lambda_rate - lambda_rate.cross(v.lambda)) / (1.0 + v.lambda.dot(v.lambda));
}

Vec3 rodrigues_vector_rate(const RodriguesVector& v, const Vec3& omega) {
  const Vec3& l = v.lambda;
  // (I + [λ]×)⁻¹ = (I − [λ]× + λ⊗λ) / (1 + λ · λ) inverts (6.38)
  return 0.5 * (omega + omega.cross(l) + l.dot(omega) * l);
}

}  // namespace unidyn
