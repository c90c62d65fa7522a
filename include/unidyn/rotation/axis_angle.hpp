// Euler's representation of a rotation by an angle about an axis (book §6.5).
#pragma once

#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// The pair (φ, r) of L(φ, r): a counter-clockwise rotation by φ about the unit vector r.
struct AxisAngle {
  Vec3 axis;
  double angle;
};

// (6.8) L(φ, r) = cos φ (I − r⊗r) − sin φ (εr) + r⊗r. The axis is normalised; a zero axis throws
// NotARotation.
Tensor rotation_tensor(const AxisAngle& rotation);

// L(φ, E_i), i = 1, 2, 3: the rotation about a fixed basis vector (6.5).
Tensor elementary_rotation(int i, double angle);

// (6.9) Euler's formula: L(φ, r) a = cos φ a⊥ + sin φ r × a⊥ + a∥.
Vec3 rotate(const AxisAngle& rotation, const Vec3& a);

// Axis and angle of a rotation tensor with φ ∈ [0, π] (the book's (6.11)–(6.12) replaced by a
// method that stays exact at φ = 0 and φ = π, where sin φ = 0). At φ = 0 the axis is E3.
AxisAngle axis_angle(const Tensor& Q);

// (6.14) ω = φ̇ r + sin φ ṙ + (1 − cos φ) r × ṙ, with r · ṙ = 0.
Vec3 angular_velocity(const AxisAngle& rotation, double angle_rate, const Vec3& axis_rate);

// The inverse of (6.14): φ̇ = ω · r and ṙ = ½ (cot(φ/2) ω⊥ − r × ω⊥), ω⊥ = (I − r⊗r) ω.
// ṙ does not exist at φ = 0 (mod 2π): throws SingularConfiguration there.
struct AxisAngleRate {
  Vec3 axis_rate;
  double angle_rate;
};
AxisAngleRate axis_angle_rates(const AxisAngle& rotation, const Vec3& omega);

}  // namespace unidyn
