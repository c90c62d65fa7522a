// Euler's representation L(φ, r) of a rotation (§6.5).
#include "unidyn/rotation/axis_angle.hpp"

#include <cmath>

#include "unidyn/rotation/errors.hpp"
#include "unidyn/rotation/euler_parameters.hpp"

namespace unidyn {
namespace {

Vec3 unit_axis(const Vec3& axis) {
  const double norm = axis.norm();
  if (!(norm > 0.0) || !std::isfinite(norm)) throw NotARotation("rotation axis must be non-zero");
  return axis / norm;
}

}  // namespace

Tensor rotation_tensor(const AxisAngle& rotation) {
  const Vec3 r = unit_axis(rotation.axis);
  const double c = std::cos(rotation.angle);
  const double s = std::sin(rotation.angle);
  const Tensor rr = tensor_product(r, r);
  // (6.8) L(φ, r) = cos φ (I − r⊗r) − sin φ (εr) + r⊗r
  return c * (Tensor::Identity() - rr) - s * alternator_times(r) + rr;
}

Tensor elementary_rotation(int i, double angle) {
  return rotation_tensor(AxisAngle{basis_vector(i), angle});
}

Vec3 rotate(const AxisAngle& rotation, const Vec3& a) {
  const Vec3 r = unit_axis(rotation.axis);
  const Vec3 a_parallel = r.dot(a) * r;
  const Vec3 a_perp = a - a_parallel;
  // (6.9) Ra = cos φ a⊥ + sin φ r × a⊥ + a∥
  return std::cos(rotation.angle) * a_perp + std::sin(rotation.angle) * r.cross(a_perp) +
         a_parallel;
}

AxisAngle axis_angle(const Tensor& Q) {
  // Through the Euler parameters with e0 ≥ 0, so φ = 2 atan2(|e|, e0) ∈ [0, π]: unlike
  // (6.11)–(6.12) this neither divides by sin φ nor loses the angle to acos near φ = 0.
  const EulerParameters p = euler_parameters(Q);
  const double sin_half = p.e.norm();
  if (sin_half == 0.0) return {basis_vector(3), 0.0};
  return {p.e / sin_half, 2.0 * std::atan2(sin_half, p.e0)};
}

Vec3 angular_velocity(const AxisAngle& rotation, double angle_rate, const Vec3& axis_rate) {
  const Vec3 r = unit_axis(rotation.axis);
  const double phi = rotation.angle;
  // (6.14) ω = φ̇ r + sin φ ṙ + (1 − cos φ) r × ṙ
  return angle_rate * r + std::sin(phi) * axis_rate + (1.0 - std::cos(phi)) * r.cross(axis_rate);
}

AxisAngleRate axis_angle_rates(const AxisAngle& rotation, const Vec3& omega) {
  const Vec3 r = unit_axis(rotation.axis);
  const double half = 0.5 * rotation.angle;
  if (std::abs(std::sin(half)) <= 1e-12) {
    throw SingularConfiguration("axis rate is undefined at rotation angle 0 (mod 2π)");
  }
  const Vec3 omega_perp = omega - r.dot(omega) * r;
  // Inverse of (6.14) on the plane normal to r: ṙ = ½ (cot(φ/2) ω⊥ − r × ω⊥)
  const Vec3 axis_rate = 0.5 * (std::cos(half) / std::sin(half) * omega_perp - r.cross(omega_perp));
  return {axis_rate, r.dot(omega)};
}

}  // namespace unidyn
