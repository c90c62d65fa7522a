// T = T2 + T1 + T0 from the partial velocities.
#include "unidyn/kinematics/kinetic_energy.hpp"

namespace unidyn {

KineticEnergyForm kinetic_energy_form(const System& system) {
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  KineticEnergyForm form{ExprMatrix(n, n), std::vector<Expr>(n, 0), 0};
  for (const auto& particle : system.particles) {
    // the partial velocities ∂r/∂q^i and ∂r/∂t
    std::vector<VectorExpr> partial;
    for (const auto& c : q) partial.push_back(diff(particle.position, c.value));
    const VectorExpr drift = diff(particle.position, system.time());
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < n; ++k) {
        form.mass_matrix(i, k) += particle.mass * dot(partial[i], partial[k]);
      }
      form.linear[i] += particle.mass * dot(partial[i], drift);
    }
    form.constant += particle.mass * dot(drift, drift) / 2;
  }
  GiNaC::exmap at_rest;
  for (const auto& c : q) at_rest[c.rate] = 0;
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const Body& body = system.bodies[b];
    // v̄ = Σ a_i q̇^i + ∂x̄/∂t and, in body components, ω0 = Σ Qᵀ g_i q̇^i + ω0_t (10.12)
    const VectorExpr omega0 = system.body_angular_velocity(b);
    std::vector<VectorExpr> a, g0;
    for (const auto& c : q) {
      a.push_back(diff(body.center, c.value));
      g0.push_back(diff(omega0, c.rate));
    }
    const VectorExpr drift = diff(body.center, system.time());
    const VectorExpr spin = subs(omega0, at_rest);
    const auto inertia = [&](const VectorExpr& x, const VectorExpr& y) {
      return dot(x, times(body.inertia, y));
    };
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < n; ++k) {
        form.mass_matrix(i, k) += body.mass * dot(a[i], a[k]) + inertia(g0[i], g0[k]);
      }
      form.linear[i] += body.mass * dot(a[i], drift) + inertia(g0[i], spin);
    }
    form.constant += body.mass * dot(drift, drift) / 2 + inertia(spin, spin) / 2;
  }
  return form;
}

}  // namespace unidyn
