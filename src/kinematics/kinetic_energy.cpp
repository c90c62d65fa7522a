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
  return form;
}

}  // namespace unidyn
