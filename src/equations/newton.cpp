// Newton's law per particle and its projection onto Lagrange's equations.
#include "unidyn/equations/newton.hpp"

namespace unidyn {

NewtonEquations newton_equations(const System& system) {
  NewtonEquations newton;
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    const Particle& particle = system.particles[p];
    newton.particles.push_back({particle.mass * system.acceleration(p), VectorExpr{}});
  }
  const auto& q = system.coordinates();
  newton.coordinate_potential_force.assign(q.size(), 0);
  for (const auto& element : system.forces) {
    for (const auto& [p, F] : element.forces) {
      newton.particles[p].applied_force = newton.particles[p].applied_force + F;
    }
    if (element.kind == ForceElement::Kind::potential) {
      for (std::size_t i = 0; i < q.size(); ++i) {
        newton.coordinate_potential_force[i] -= element.potential.diff(q[i].value);
      }
    }
  }
  return newton;
}

std::vector<Expr> equivalence_residual(const System& system, const NewtonEquations& newton,
                                       const EquationsOfMotion& lagrange) {
  const auto& q = system.coordinates();
  std::vector<Expr> residual(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    // Newton projected onto the partial velocity ∂r_P/∂q^i
    Expr projected = -newton.coordinate_potential_force[i];
    for (std::size_t p = 0; p < system.particles.size(); ++p) {
      const VectorExpr partial_velocity = diff(system.particles[p].position, q[i].value);
      projected += dot(newton.particles[p].constraint_force(), partial_velocity);
    }
    // Lagrange's row i without the constraint forces
    const Expr lagrange_row = lagrange.inertia_terms[i] +
                              lagrange.potential_energy.diff(q[i].value) -
                              lagrange.generalized_force[i];
    residual[i] = projected - lagrange_row;
  }
  return residual;
}

}  // namespace unidyn
