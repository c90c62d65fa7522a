// Lagrange's equations in the second form (book (10.16), (10.19)), for particles and bodies:
//
//   d/dt(∂T/∂u̇^A) − ∂T/∂u^A = Φ_A + Σ_k λ_k ∂Ψ_k/∂u^A,
//   Φ_A = Σ_P F_P · ∂v_P/∂u̇^A + Σ_B (F_B · ∂v̄_B/∂u̇^A + M_B · ∂ω_B/∂u̇^A) − ∂U_q/∂u^A,
//
// every applied load — conservative or not — entering through the partial velocities ∂v/∂u̇^A and
// the partial angular velocities ∂ω/∂u̇^A (for Euler angles these are the Euler basis vectors g_i,
// (10.6)); U_q are the potentials given directly in the coordinates, which have no vectors.
#pragma once

#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/equations/newton.hpp"

namespace unidyn {

struct SecondForm {
  // [A][P] ∂v_P/∂u̇^A; [A][B] ∂v̄_B/∂u̇^A and ∂ω_B/∂u̇^A
  std::vector<std::vector<VectorExpr>> particle_velocity;
  std::vector<std::vector<VectorExpr>> center_velocity;
  std::vector<std::vector<VectorExpr>> angular_velocity;
  // d/dt(∂T/∂u̇^A) − ∂T/∂u^A and Φ_A
  std::vector<Expr> inertia_terms;
  std::vector<Expr> generalized_force;
};

SecondForm lagrange_second_form(const System& system, const NewtonEquations& newton,
                                const EquationsOfMotion& lagrange);

}  // namespace unidyn
