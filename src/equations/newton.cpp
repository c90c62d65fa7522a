// Newton's law per particle and its projection onto Lagrange's equations.
#include "unidyn/equations/newton.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {

NewtonEquations newton_equations(const System& system) {
  NewtonEquations newton;
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    const Particle& particle = system.particles[p];
    newton.particles.push_back({particle.mass * system.acceleration(p), VectorExpr{}});
  }
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const Body& body = system.bodies[b];
    const VectorExpr acceleration =
        system.configuration.total_derivative(system.center_velocity(b));
    newton.bodies.push_back({body.mass * acceleration, VectorExpr{},
                             system.configuration.total_derivative(system.angular_momentum(b)),
                             VectorExpr{}});
  }
  const auto& q = system.coordinates();
  newton.coordinate_potential_force.assign(q.size(), 0);
  for (const auto& element : system.forces) {
    for (const auto& [p, F] : element.forces) {
      newton.particles[p].applied_force = newton.particles[p].applied_force + F;
    }
    for (const auto& f : element.body_forces) {
      BodyBalance& balance = newton.bodies[f.body];
      balance.applied_force = balance.applied_force + f.force;
      // its moment about the centre of mass, (x − x̄) × F
      balance.applied_moment =
          balance.applied_moment + cross(f.point - system.bodies[f.body].center, f.force);
    }
    for (const auto& m : element.moments) {
      newton.bodies[m.body].applied_moment = newton.bodies[m.body].applied_moment + m.moment;
    }
    if (element.kind == ForceElement::Kind::potential) {
      for (std::size_t i = 0; i < q.size(); ++i) {
        newton.coordinate_potential_force[i] -= derivative(element.potential, q[i].value);
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
    for (std::size_t b = 0; b < system.bodies.size(); ++b) {
      // the partial velocity of the centre and the partial angular velocity
      const VectorExpr partial_velocity = diff(system.bodies[b].center, q[i].value);
      const VectorExpr partial_angular_velocity = diff(system.angular_velocity(b), q[i].rate);
      projected += dot(newton.bodies[b].constraint_force(), partial_velocity) +
                   dot(newton.bodies[b].constraint_moment(), partial_angular_velocity);
    }
    // Lagrange's row i without the constraint forces
    const Expr lagrange_row = lagrange.inertia_terms[i] +
                              derivative(lagrange.potential_energy, q[i].value) -
                              lagrange.generalized_force[i];
    residual[i] = projected - lagrange_row;
  }
  return residual;
}

}  // namespace unidyn
