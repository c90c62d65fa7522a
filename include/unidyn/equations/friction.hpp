// Coulomb friction on a particle held to a surface or curve (book §2.11, (2.27)–(2.31); §5.6).
//
// Constraint k keeps particle P on a surface (or, with other constraints, a curve); its normal
// force is N = λ g with g = ∂Ψ/∂r_P. Relative to the surface P moves at v_rel = Σ J_i q̇^i + e with
// J_i = ∂r_P/∂q^i and e = ∂r_P/∂t − v_surface; its slip is the tangential part v_t = v_rel −
// (v_rel · n̂) n̂, n̂ = g/|g|.
//   sliding:  F = −μ_d |N| v_t/|v_t|, i.e. the generalised force λ d with d = −μ_d sign(λ) |g| Jᵀ ĉ
//             — linear in λ, so q̈ and λ are solved together, not with a lagged normal force;
//   sticking: v_rel = 0 (three velocity rows J q̇ + e = 0 in place of Ψ's), whose multipliers are
//             the whole contact force R on P; it holds while |R_t| ≤ μ_s |R · n̂|.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct FrictionContact {
  std::size_t constraint;
  std::size_t particle;
  std::vector<VectorExpr> jacobian;  // J_i = ∂r_P/∂q^i
  VectorExpr velocity_term;          // e = ∂r_P/∂t − v_surface
  VectorExpr acceleration_bias;      // d/dt (J q̇ + e) at q̈ = 0
  VectorExpr normal;                 // g = ∂Ψ/∂r_P
  Expr dynamic_coefficient;
  Expr static_coefficient;
};

// The rough constraints of a system. Throws std::invalid_argument when the coordinates do not fix
// P's position one to one (g cannot be found) or a constraint is not a position constraint.
std::vector<FrictionContact> friction_contacts(const System& system);

}  // namespace unidyn
