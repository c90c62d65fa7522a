// Lagrange's equations in the second form (10.16) with the partial velocities.
#include "unidyn/equations/second_form.hpp"

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

SecondForm lagrange_second_form(const System& system, const NewtonEquations& newton,
                                const EquationsOfMotion& lagrange) {
  const auto& q = system.coordinates();
  SecondForm form;
  form.inertia_terms = lagrange.inertia_terms;
  std::vector<VectorExpr> v, v_bar, omega;
  for (std::size_t p = 0; p < system.particles.size(); ++p) v.push_back(system.velocity(p));
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    v_bar.push_back(system.center_velocity(b));
    omega.push_back(system.angular_velocity(b));
  }
  for (std::size_t A = 0; A < q.size(); ++A) {
    // the partial velocities and partial angular velocities of u^A
    std::vector<VectorExpr> particle, center, angular;
    for (const auto& x : v) particle.push_back(simplified(diff(x, q[A].rate)));
    for (const auto& x : v_bar) center.push_back(simplified(diff(x, q[A].rate)));
    for (const auto& x : omega) angular.push_back(simplified(diff(x, q[A].rate)));
    // (10.16) Φ_A = Σ F · ∂v/∂u̇^A + M · ∂ω/∂u̇^A, and −∂U_q/∂u^A
    Expr phi = newton.coordinate_potential_force[A];
    for (std::size_t p = 0; p < particle.size(); ++p) {
      phi += dot(newton.particles[p].applied_force, particle[p]);
    }
    for (std::size_t b = 0; b < center.size(); ++b) {
      phi += dot(newton.bodies[b].applied_force, center[b]) +
             dot(newton.bodies[b].applied_moment, angular[b]);
    }
    form.particle_velocity.push_back(std::move(particle));
    form.center_velocity.push_back(std::move(center));
    form.angular_velocity.push_back(std::move(angular));
    form.generalized_force.push_back(phi);
  }
  return form;
}

}  // namespace unidyn
