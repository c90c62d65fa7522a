// Angular velocity tensors and vectors (§6.4, §6.7).
#include "unidyn/rotation/angular_velocity.hpp"

namespace unidyn {

Tensor angular_velocity_tensor(const Tensor& Q, const Tensor& Q_rate) {
  return Q_rate * Q.transpose();
}

Vec3 angular_velocity(const Tensor& Q, const Tensor& Q_rate) {
  return axial(angular_velocity_tensor(Q, Q_rate));
}

Tensor body_angular_velocity_tensor(const Tensor& Q, const Tensor& Q_rate) {
  // (6.7) Ω0 = Qᵀ Q̇
  return Q.transpose() * Q_rate;
}

Vec3 body_angular_velocity(const Tensor& Q, const Tensor& Q_rate) {
  return axial(body_angular_velocity_tensor(Q, Q_rate));
}

Tensor rotation_rate(const Tensor& Q, const Vec3& omega) {
  return skew(omega) * Q;
}

Vec3 corotational_rate(const Vec3& a, const Vec3& a_rate, const Vec3& omega) {
  // ȧ = å + ω × a
  return a_rate - omega.cross(a);
}

Tensor corotational_rate(const Tensor& A, const Tensor& A_rate, const Vec3& omega) {
  const Tensor Omega = skew(omega);
  // Ȧ = Å + Ω A − A Ω
  return A_rate - Omega * A + A * Omega;
}

Vec3 relative_angular_velocity(const Tensor& R1, const Tensor& R1_rate, const Tensor& R2,
                               const Tensor& R2_rate) {
  const Tensor Omega1 = angular_velocity_tensor(R1, R1_rate);
  // R̊2 = Ṙ2 + R2 Ω_R1 + Ω_R1ᵀ R2, the rate of R2 with the basis of R1 held fixed
  const Tensor R2_corotational = R2_rate + R2 * Omega1 - Omega1 * R2;
  // (6.18) ω̂_R2 = −½ ε[R̊2 R2ᵀ]
  return axial(R2_corotational * R2.transpose());
}

}  // namespace unidyn
