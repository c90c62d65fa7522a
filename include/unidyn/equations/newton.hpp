// Newton's second law for each particle, F + R = m a (book (2.1), §4.4), and its equivalence with
// Lagrange's equations: projected onto the partial velocities ∂r_P/∂q^i,
//   Σ_P (m_P a_P − F_P) · ∂r_P/∂q^i + ∂U_q/∂q^i = d/dt(∂T/∂q̇^i) − ∂T/∂q^i + ∂U/∂q^i − Φ_i
// (U_q: potentials given directly in the coordinates, which have no force vectors).
#pragma once

#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/model/system.hpp"

namespace unidyn {

struct ParticleBalance {
  VectorExpr mass_times_acceleration;  // m a
  VectorExpr applied_force;            // F, all force elements with vectors
  // R = m a − F: the resultant constraint force on the particle (reduced coordinates).
  VectorExpr constraint_force() const { return mass_times_acceleration - applied_force; }
};

struct NewtonEquations {
  std::vector<ParticleBalance> particles;
  // −∂U_q/∂q^i of the potentials that have no force vectors.
  std::vector<Expr> coordinate_potential_force;
};

NewtonEquations newton_equations(const System& system);

// Newton's law projected onto ∂r_P/∂q^i minus Lagrange's row i (both without multipliers), per
// coordinate: identically zero when the two derivations agree.
std::vector<Expr> equivalence_residual(const System& system, const NewtonEquations& newton,
                                       const EquationsOfMotion& lagrange);

}  // namespace unidyn
