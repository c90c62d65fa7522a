// Coulomb friction at a contact with a surface or curve (book §2.11, (2.27)–(2.31); §2.6, §3.8;
// §5.6; §9.8; Ex. 9.13).
//
// The rough constraint k — with, on a curve, the constraints named in its `with:` — keeps particle
// P (or body B's point of contact P) on a surface or curve. Constraint j's force on P is λ_j g_j
// with g_j = ∂Ψ_j/∂r_P (for a body, the force f_B of (8.22)); the normal force is their sum
// N = Σ_j λ_j g_j (§2.6: on a circle |N| = √(λ1² + λ2²) for unit g's). Relative to the surface the
// contact moves at v_rel = Σ J_i q̇^i + e with J_i = ∂v_P/∂q̇^i and e = v_P at q̇ = 0 − v_surface
// (v_P = v̄ + ω × (x_P − x̄) for a body); its slip v_t is the part of v_rel off the normals' span.
//   sliding:  F = −μ_d(|v_t|) |N| v_t/|v_t| − c v_t at P. With N̂ = N/|N| held, |N| = N̂ · Σ λ_j g_j
//             is linear in the λ's: the friction is the generalised force Σ_j λ_j d_j with
//             d_j = −μ_d (N̂ · g_j) Jᵀ ĉ, so q̈ and λ are solved together, not with a lagged normal
//             force; N̂ is then iterated to its fixed point (one normal: N̂ = ±g/|g|, the sign of λ);
//   sticking: v_t = 0 (rows t · (J q̈ + bias) = 0 along the tangents off the normals' span), whose
//             multipliers are the friction force; it holds while |R_t| ≤ μ_s |N|.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct FrictionContact {
  // the rough constraint, then those of its `with:` (the curve's other surfaces)
  std::vector<std::size_t> constraints;
  std::vector<VectorExpr> jacobian;  // J_i = ∂v_P/∂q̇^i
  VectorExpr velocity_term;          // e = v_P at q̇ = 0, − v_surface
  VectorExpr acceleration_bias;      // d/dt (J q̇ + e) at q̈ = 0
  std::vector<VectorExpr> normals;   // g_j = ∂Ψ_j/∂r_P, one per constraint
  Expr dynamic_coefficient;          // with the slip speed |v_t| in place of slip_speed
  Expr static_coefficient;
  Expr viscous_coefficient;
};

// The rough constraints of a system. Throws std::invalid_argument when g cannot be found (the
// coordinates do not fix the positions one to one), a constraint is not a position constraint or
// a `with:` names no constraint.
std::vector<FrictionContact> friction_contacts(const System& system);

// Whether constraint k carries a rough contact's normal force: it is rough, or named in a rough
// constraint's `with:`.
bool carries_friction(const System& system, std::size_t k);

}  // namespace unidyn
