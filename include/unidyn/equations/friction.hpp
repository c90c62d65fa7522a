// Coulomb friction at a contact with a surface or curve (book §2.11, (2.27)–(2.31); §5.6; §9.8).
//
// Constraint k keeps particle P (or body B's point of contact P) on a surface; its normal force is
// N = λ g with g = ∂Ψ/∂r_P (for a body, the force f_B of (8.22)). Relative to the surface the
// contact moves at v_rel = Σ J_i q̇^i + e with J_i = ∂v_P/∂q̇^i and e = v_P at q̇ = 0 − v_surface
// (v_P = v̄ + ω × (x_P − x̄) for a body); its slip is the tangential part v_t = v_rel −
// (v_rel · n̂) n̂, n̂ = g/|g|.
//   sliding:  F = −μ_d |N| v_t/|v_t| at P, i.e. the generalised force λ d with
//             d = −μ_d sign(λ) |g| Jᵀ ĉ — linear in λ, so q̈ and λ are solved together, not with a
//             lagged normal force;
//   sticking: v_t = 0 (rows t · (J q̈ + bias) = 0 along the surface's tangents), whose multipliers
//             are the friction force; it holds while |R_t| ≤ μ_s |N|.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct FrictionContact {
  std::size_t constraint;
  std::vector<VectorExpr> jacobian;  // J_i = ∂v_P/∂q̇^i
  VectorExpr velocity_term;          // e = v_P at q̇ = 0, − v_surface
  VectorExpr acceleration_bias;      // d/dt (J q̇ + e) at q̈ = 0
  VectorExpr normal;                 // g = ∂Ψ/∂r_P
  Expr dynamic_coefficient;
  Expr static_coefficient;
};

// The rough constraints of a system. Throws std::invalid_argument when g cannot be found (the
// coordinates do not fix the positions one to one) or a constraint is not a position constraint.
std::vector<FrictionContact> friction_contacts(const System& system);

}  // namespace unidyn
