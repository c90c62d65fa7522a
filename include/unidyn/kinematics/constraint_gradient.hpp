// The load a constraint puts on each particle and body (book §2.6, §4.4, §8.6): from its gradient
// in the coordinates, the Lagrange prescription R_P = λ ∂Ψ/∂r_P on a particle and (8.22)
// F_c = λ f_B, M_c = λ h_B (about the centre of mass) on a body.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// g_P = ∂Ψ/∂r_P on each particle; f_B and h_B on each body.
struct ConstraintLoads {
  std::vector<VectorExpr> particle_force;
  std::vector<VectorExpr> body_force;
  std::vector<VectorExpr> body_moment;
};

// Solves Σ_P g_P · ∂r_P/∂q^i + Σ_B (f_B · ∂x̄_B/∂q^i + h_B · ∂ω_B/∂q̇^i) = a_i for g, f and h
// (a = ∂Ψ/∂q for a position constraint, the coefficients of q̇ for a velocity constraint): the
// velocity form Σ (g · v + f · v̄ + h · ω) of the constraint. Unique when the coordinates map
// one-to-one to the moving positions and orientations (3 coordinates per moving particle, 3 per
// moving centre, 3 per turning body, and one per unit norm of Euler parameters, whose row joins the
// system with a multiplier of its own). With fewer coordinates than that, when each coordinate
// moves one particle or body alone (particles kept in planes, say; not with Euler parameters), the
// least-norm solution: each load along the directions its coordinates move it. Throws
// std::invalid_argument otherwise. What does not move gets 0.
ConstraintLoads solve_constraint_loads(const System& system, const std::vector<Expr>& a);

// The loads of constraint k: the closed forms a joint gave it (8.23), none for a parametrisation
// constraint, or solve_constraint_loads of its row.
ConstraintLoads constraint_loads(const System& system, std::size_t k);

// The particles' part of solve_constraint_loads: g_P = ∂Ψ/∂r_P.
std::vector<VectorExpr> constraint_gradient(const System& system, const std::vector<Expr>& a);

// The row a of constraint k: ∂Ψ/∂q^i, or ∂(velocity form)/∂q̇^i.
std::vector<Expr> constraint_row(const System& system, std::size_t k);

}  // namespace unidyn
