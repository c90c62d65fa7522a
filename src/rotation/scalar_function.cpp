// Derivatives of scalar functions of a rotation (§6.10).
#include "unidyn/rotation/scalar_function.hpp"

#include <cmath>

#include "unidyn/rotation/errors.hpp"

namespace unidyn {

Vec3 rotation_gradient(const Tensor& Q, const Tensor& dU_dQ) {
  // U_Q = ½ (∂U/∂Q Qᵀ − Q (∂U/∂Q)ᵀ), the skew part of ∂U/∂Q Qᵀ
  const Tensor U_Q = skew_part(dU_dQ * Q.transpose());
  // (6.39) u_Q = −ε[U_Q]
  return -alternator_contract(U_Q);
}

Vec3 rotation_gradient(const EulerSet& set, const Vec3& angles, const Vec3& dU_dangles) {
  // (6.41) u_Q = Σ ∂Û/∂γ^i g^i
  return dual_euler_basis(set, angles) * dU_dangles;
}

Vec3 rotation_gradient(const AxisAngle& rotation, double dU_dangle, const Vec3& dU_daxis) {
  const Vec3 r = rotation.axis.normalized();
  const double half = 0.5 * rotation.angle;
  if (std::abs(std::sin(half)) <= 1e-12) {
    throw SingularConfiguration("the axis–angle gradient is undefined at rotation angle 0");
  }
  const Tensor tangential = Tensor::Identity() - tensor_product(r, r);
  // (6.42)₂ u_Q = ∂Ũ/∂φ r + ½ (cot(φ/2) (I − r⊗r) − εr) ∂Ũ/∂r
  return dU_dangle * r +
         0.5 * (std::cos(half) / std::sin(half) * tangential - alternator_times(r)) * dU_daxis;
}

Vec3 rotation_gradient(const EulerParameters& p, double dU_de0, const Vec3& dU_de) {
  // (6.42)₃ u_Q = ½ ((e0 I − εe) ∂Ū/∂e − ∂Ū/∂e0 e)
  return 0.5 * ((p.e0 * Tensor::Identity() - alternator_times(p.e)) * dU_de - dU_de0 * p.e);
}

Vec3 rotation_gradient(const RodriguesVector& v, const Vec3& dU_dlambda) {
  const Vec3& l = v.lambda;
  // (6.42)₄ u_Q = ½ (I + λ⊗λ − ελ) ∂Ǔ/∂λ
  return 0.5 * (Tensor::Identity() + tensor_product(l, l) - alternator_times(l)) * dU_dlambda;
}

}  // namespace unidyn
