// Lagrange's equations, approach I: coordinates plus a multiplier per constraint (book (3.7),
// (4.23)–(4.26), §5.1).
//
//   d/dt(∂T/∂q̇^i) − ∂T/∂q^i = −∂U/∂q^i + Φ_i + Σ_k λ_k a_k^i,        i = 1..n
//   Φ_i = Σ_P F_P · ∂r_P/∂q^i   (non-conservative forces)
//
// arranged as M(q, t) q̈ = f(q, q̇, t) + Aᵀ λ, with each constraint k a row a_k · q̇ + e_k = 0
// (a_k = ∂Ψ_k/∂q, e_k = ∂Ψ_k/∂t for a position constraint), differentiated once more for the
// acceleration level A q̈ + b = 0.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// One particle's or one body's share of Kane's sums (equations/kane.hpp): with its partial
// velocities J = [∂v/∂q̇^i] (3 × n, nonzero only in `columns`), a weight W and its inertia force h,
//   M += Jᵀ W J,   c += Jᵀ h
// (a point: W = m I, J = ∂v/∂q̇, h = m a⁰; a body's rotation on its own basis: W = J0, J = ∂ω0/∂q̇,
// h = J0 ω̇0⁰ + ω0 × J0 ω0). Evaluated numerically, M and c cost O(n²) per point instead of the
// symbolic M's O(n⁴) terms for a chain (numeric/inertia_assembly.hpp).
struct PartialVelocityTerm {
  Expr mass;                                 // a point's m
  std::optional<GiNaC::matrix> inertia;      // a rotation's J0 (W = J0); none for a point
  std::vector<std::size_t> columns;          // the coordinates with a nonzero partial velocity
  std::vector<VectorExpr> partial_velocity;  // ∂v/∂q̇^i (or ∂ω0/∂q̇^i), one per column
  VectorExpr inertia_force;                  // h
};

struct EquationsOfMotion {
  // M q̈ = f + Aᵀ λ
  ExprMatrix mass_matrix;
  std::vector<Expr> forcing;
  // f = applied_forcing − c: Φ − ∂U/∂q, and the convective terms c
  std::vector<Expr> applied_forcing;
  // M and c as sums over the particles and bodies (Kane's method only; empty otherwise)
  std::vector<PartialVelocityTerm> partial_velocity_terms;
  // Each row a_k of A and e_k: the constraints at velocity level, a_k · q̇ + e_k = 0.
  ExprMatrix constraint_matrix;
  std::vector<Expr> constraint_velocity_term;
  // A q̈ + b = 0: b_k = ȧ_k · q̇ + ė_k.
  std::vector<Expr> constraint_bias;
  // Ψ_k for position constraints (0 for velocity constraints).
  std::vector<Expr> constraint_position;
  // The pieces: T, U, Φ, and each equation's left side d/dt(∂T/∂q̇) − ∂T/∂q.
  Expr kinetic_energy;
  Expr potential_energy;
  std::vector<Expr> generalized_force;
  std::vector<Expr> inertia_terms;
};

// Derives the equations of motion of a system by Lagrange's equations, approach I.
EquationsOfMotion lagrange_equations(const System& system);

// The pieces every form of the equations shares: Φ_i of the non-conservative loads; the
// constraint rows a_k, e_k, b_k, Ψ_k (into eq); T, U, Φ and an n × n zero M to start from; and,
// once M and the q̈-free part c_i of each row's inertia terms are known, the inertia terms
// Σ_j M_ij q̈^j + c_i, f_i = Φ_i − ∂U/∂q^i − c_i and the constraint rows.
std::vector<Expr> generalized_forces(const System& system);
// One force element's Φ_i = Σ F · ∂r/∂q^i + Σ M · ∂ω/∂q̇^i, with each body's ω (angular_velocities).
std::vector<Expr> element_generalized_forces(const System& system, const ForceElement& element,
                                             const std::vector<VectorExpr>& omega);
std::vector<VectorExpr> angular_velocities(const System& system);
void constraint_rows(const System& system, EquationsOfMotion& eq);
EquationsOfMotion energies_and_forces(const System& system);
void finish_equations(const System& system, const std::vector<Expr>& convective,
                      EquationsOfMotion& eq);

}  // namespace unidyn
