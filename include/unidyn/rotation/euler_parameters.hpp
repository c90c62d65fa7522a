// Euler–Rodrigues symmetric parameters, the unit quaternion e0 + e1 i + e2 j + e3 k (book §6.9).
#pragma once

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// e0 = cos(φ/2), e = sin(φ/2) r, with e0² + e · e = 1.
struct EulerParameters {
  double e0;
  Vec3 e;
};

// (6.36) Q = (e0² − e · e) I + 2 e⊗e − 2 e0 εe.
Tensor rotation_tensor(const EulerParameters& p);

// The parameters of a rotation tensor with e0 ≥ 0 (Shepperd's method: exact at every angle).
EulerParameters euler_parameters(const Tensor& Q);

// e0 = cos(φ/2), e = sin(φ/2) r.
EulerParameters euler_parameters(const AxisAngle& rotation);

// Axis and angle back, φ ∈ [0, 2π) following the sign of e0; the axis is E3 at φ = 0.
AxisAngle axis_angle(const EulerParameters& p);

// Scaled to unit norm; a zero quaternion throws NotARotation.
EulerParameters normalised(const EulerParameters& p);

// (6.48)–(6.49) Rodrigues–Cayley composition: C = B A ↔ g0 = e0 f0 − e · f, g = e0 f + f0 e + f ×
// e, with A ↔ (e0, e) applied first and B ↔ (f0, f) second.
EulerParameters compose(const EulerParameters& second, const EulerParameters& first);

// (6.38) ω = 2 (e0 ė − ė0 e + e × ė).
Vec3 angular_velocity(const EulerParameters& p, const EulerParameters& rate);

// The inverse of (6.38) on the unit sphere: ė0 = −½ e · ω, ė = ½ (e0 ω + ω × e).
EulerParameters euler_parameter_rates(const EulerParameters& p, const Vec3& omega);

}  // namespace unidyn
