// Chasles' theorem (book §7.2, (7.5)–(7.7)): every displacement of a rigid body is a screw — a
// rotation by φ about an axis s through a point ρ, and a slide σ along it.
//
// From t0 to t a material point moves as x(t) = Q(t) Q(t0)ᵀ x(t0) + z (7.5), with
// z = d(t) − Q(t) Q(t0)ᵀ d(t0) and d = x_P − Q X_P for any material point X_P (7.4). With s and φ
// the axis and angle of Q(t) Q(t0)ᵀ, (7.6) asks (I − Q Q(t0)ᵀ) ρ + σ s = z; the ρ ⟂ s that solves
// it is (7.7) ρ = ½ (z⊥ + cot(φ/2) s × z), σ = s · z, z⊥ = z − (z · s) s.
#pragma once

#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

struct ScrewMotion {
  Vec3 axis;     // s (unit)
  double angle;  // φ ∈ (0, π]
  Vec3 point;    // ρ, the point of the axis nearest the origin (ρ · s = 0)
  double slide;  // σ
};

// The screw of the displacement x ↦ R x + z (R a rotation). A pure translation (R = I) has no
// axis: throws SingularConfiguration.
ScrewMotion screw_motion(const Tensor& R, const Vec3& z);

// The screw that takes a body from its placement (Q0, d0) at t0 to (Q, d) at t, (7.4)–(7.5).
ScrewMotion screw_motion(const Tensor& Q0, const Vec3& d0, const Tensor& Q, const Vec3& d);

}  // namespace unidyn
