// Euler–Rodrigues parameters (unit quaternions) (§6.9, Exercise 6.4).
#include "unidyn/rotation/euler_parameters.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include "unidyn/rotation/errors.hpp"

namespace unidyn {

Tensor rotation_tensor(const EulerParameters& p) {
  // (6.36) Q = (e0² − e · e) I + 2 e⊗e − 2 e0 εe
  return (p.e0 * p.e0 - p.e.dot(p.e)) * Tensor::Identity() + 2.0 * tensor_product(p.e, p.e) -
         2.0 * p.e0 * alternator_times(p.e);
}

EulerParameters euler_parameters(const Tensor& Q) {
  // Shepperd's method: of 4e0² = 1 + tr Q and 4e_i² = 1 + 2Q_ii − tr Q take the largest, so the
  // divisions below are by a number no smaller than ½.
  const double trace = Q.trace();
  const std::array<double, 4> four_squares = {1.0 + trace, 1.0 + 2.0 * Q(0, 0) - trace,
                                              1.0 + 2.0 * Q(1, 1) - trace,
                                              1.0 + 2.0 * Q(2, 2) - trace};
  int largest = 0;
  for (int n = 1; n < 4; ++n) {
    if (four_squares[n] > four_squares[largest]) largest = n;
  }
  // Off-diagonal sums and differences of (6.36): Q_ij − Q_ji = 4 e0 ε_ijk e_k (skew part),
  // Q_ij + Q_ji = 4 e_i e_j (i ≠ j).
  const double d0 = Q(2, 1) - Q(1, 2);   // 4 e0 e1
  const double d1 = Q(0, 2) - Q(2, 0);   // 4 e0 e2
  const double d2 = Q(1, 0) - Q(0, 1);   // 4 e0 e3
  const double s01 = Q(0, 1) + Q(1, 0);  // 4 e1 e2
  const double s02 = Q(0, 2) + Q(2, 0);  // 4 e1 e3
  const double s12 = Q(1, 2) + Q(2, 1);  // 4 e2 e3
  const double q = 0.5 * std::sqrt(std::max(four_squares[largest], 0.0));
  const double f = 0.25 / q;
  EulerParameters p{};
  switch (largest) {
    case 0:
      p = {q, Vec3(d0 * f, d1 * f, d2 * f)};
      break;
    case 1:
      p = {d0 * f, Vec3(q, s01 * f, s02 * f)};
      break;
    case 2:
      p = {d1 * f, Vec3(s01 * f, q, s12 * f)};
      break;
    default:
      p = {d2 * f, Vec3(s02 * f, s12 * f, q)};
      break;
  }
  if (p.e0 < 0.0) p = {-p.e0, -p.e};
  return normalised(p);
}

EulerParameters euler_parameters(const AxisAngle& rotation) {
  const double norm = rotation.axis.norm();
  if (!(norm > 0.0)) throw NotARotation("rotation axis must be non-zero");
  const double half = 0.5 * rotation.angle;
  return {std::cos(half), std::sin(half) / norm * rotation.axis};
}

AxisAngle axis_angle(const EulerParameters& p) {
  const double sin_half = p.e.norm();
  if (sin_half == 0.0) return {basis_vector(3), p.e0 >= 0.0 ? 0.0 : 2.0 * std::numbers::pi};
  return {p.e / sin_half, 2.0 * std::atan2(sin_half, p.e0)};
}

EulerParameters normalised(const EulerParameters& p) {
  // Scaled by the largest component first, so the squared norm neither underflows nor overflows.
  const double largest = std::max(std::abs(p.e0), p.e.cwiseAbs().maxCoeff());
  if (!(largest > 0.0) || !std::isfinite(largest) || !p.e.allFinite()) {
    throw NotARotation("Euler parameters must be finite and not all zero");
  }
  const double e0 = p.e0 / largest;
  const Vec3 e = p.e / largest;
  const double norm = std::sqrt(e0 * e0 + e.squaredNorm());
  return {e0 / norm, e / norm};
}

EulerParameters compose(const EulerParameters& second, const EulerParameters& first) {
  const double f0 = second.e0;
  const Vec3& f = second.e;
  const double e0 = first.e0;
  const Vec3& e = first.e;
  // (6.49) g0 = e0 f0 − e · f,  g = e0 f + f0 e + f × e
  return {e0 * f0 - e.dot(f), e0 * f + f0 * e + f.cross(e)};
}

Vec3 angular_velocity(const EulerParameters& p, const EulerParameters& rate) {
  // (6.38) ω = 2 (e0 ė − ė0 e + e × ė)
  return 2.0 * (p.e0 * rate.e - rate.e0 * p.e + p.e.cross(rate.e));
}

EulerParameters euler_parameter_rates(const EulerParameters& p, const Vec3& omega) {
  // The quaternion product ṗ = ½ (0, ω) ∘ p, which inverts (6.38) and keeps e0² + e · e constant.
  return {-0.5 * p.e.dot(omega), 0.5 * (p.e0 * omega + omega.cross(p.e))};
}

}  // namespace unidyn
