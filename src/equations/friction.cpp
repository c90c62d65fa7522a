// The pieces of Coulomb friction at each rough contact.
#include "unidyn/equations/friction.hpp"

#include <stdexcept>

#include "unidyn/kinematics/constraint_gradient.hpp"

namespace unidyn {

std::vector<FrictionContact> friction_contacts(const System& system) {
  std::vector<FrictionContact> contacts;
  const Configuration& config = system.configuration;
  GiNaC::exmap no_acceleration = config.zero_accelerations();
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    if (!c.friction) continue;
    if (c.kind != Constraint::Kind::position) {
      throw std::invalid_argument("friction on '" + c.name + "' needs a position constraint");
    }
    const auto p = system.find_particle(c.friction->on);
    if (!p)
      throw std::invalid_argument("friction on '" + c.name + "': no particle " + c.friction->on);
    FrictionContact contact{
        k, *p, {}, {}, {}, {}, c.friction->dynamic_coefficient, c.friction->static_coefficient};
    const VectorExpr& r = system.particles[*p].position;
    for (const auto& q : system.coordinates()) contact.jacobian.push_back(diff(r, q.value));
    contact.velocity_term = diff(r, system.time()) - c.friction->surface_velocity;
    // d/dt (v_P − v_surface) with q̈ = 0
    contact.acceleration_bias =
        subs(config.total_derivative(system.velocity(*p) - c.friction->surface_velocity),
             no_acceleration);
    contact.normal = constraint_gradient(system, constraint_row(system, k))[*p];
    contacts.push_back(std::move(contact));
  }
  return contacts;
}

}  // namespace unidyn
