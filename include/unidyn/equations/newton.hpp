// Newton's second law for each particle, F + R = m a (book (2.1), §4.4), Euler's laws for each
// body, and their equivalence with Lagrange's equations: projected onto the partial velocities
// ∂r/∂q^i and partial angular velocities ∂ω/∂q̇^i (10.x),
//   Σ_P (m a − F) · ∂r_P/∂q^i + Σ_B [(m ā − F) · ∂x̄/∂q^i + (Ḣ − M) · ∂ω/∂q̇^i] + ∂U_q/∂q^i
//     = d/dt(∂T/∂q̇^i) − ∂T/∂q^i + ∂U/∂q^i − Φ_i
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

// Euler's laws for a body (8.x): F + R = m ā and M + M_R = Ḣ about the centre of mass.
struct BodyBalance {
  VectorExpr mass_times_acceleration;  // m ā
  VectorExpr applied_force;            // F
  VectorExpr momentum_rate;            // Ḣ, H = J ω about the centre
  VectorExpr applied_moment;           // M about the centre: Σ (x − x̄) × F + pure moments
  VectorExpr constraint_force() const { return mass_times_acceleration - applied_force; }
  VectorExpr constraint_moment() const { return momentum_rate - applied_moment; }
};

struct NewtonEquations {
  std::vector<ParticleBalance> particles;
  std::vector<BodyBalance> bodies;
  // −∂U_q/∂q^i of the potentials that have no force vectors.
  std::vector<Expr> coordinate_potential_force;
};

NewtonEquations newton_equations(const System& system);

// Newton's law projected onto ∂r_P/∂q^i minus Lagrange's row i (both without multipliers), per
// coordinate: identically zero when the two derivations agree.
std::vector<Expr> equivalence_residual(const System& system, const NewtonEquations& newton,
                                       const EquationsOfMotion& lagrange);

}  // namespace unidyn
