// The pieces of Coulomb friction at each rough contact.
#include "unidyn/equations/friction.hpp"

#include <stdexcept>

#include "unidyn/kinematics/constraint_gradient.hpp"

namespace unidyn {

std::vector<FrictionContact> friction_contacts(const System& system) {
  std::vector<FrictionContact> contacts;
  const Configuration& config = system.configuration;
  const GiNaC::exmap no_acceleration = config.zero_accelerations();
  GiNaC::exmap at_rest;
  for (const auto& q : system.coordinates()) at_rest[q.rate] = 0;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    if (!c.friction) continue;
    if (c.kind != Constraint::Kind::position) {
      throw std::invalid_argument("friction on '" + c.name + "' needs a position constraint");
    }
    const ConstraintLoads loads = constraint_loads(system, k);
    // the contact's velocity v_P and the normal g
    VectorExpr v, g;
    if (const auto p = system.find_particle(c.friction->on)) {
      v = system.velocity(*p);
      g = loads.particle_force[*p];
    } else if (const auto b = system.find_body(c.friction->on)) {
      v = system.center_velocity(*b) +
          cross(system.angular_velocity(*b), c.friction->at - system.bodies[*b].center);
      g = loads.body_force[*b];
    } else {
      throw std::invalid_argument("friction on '" + c.name + "': no particle or body " +
                                  c.friction->on);
    }
    FrictionContact contact{
        k, {}, {}, {}, g, c.friction->dynamic_coefficient, c.friction->static_coefficient};
    for (const auto& q : system.coordinates()) contact.jacobian.push_back(diff(v, q.rate));
    const VectorExpr relative = v - c.friction->surface_velocity;
    contact.velocity_term = subs(relative, at_rest);
    // d/dt (v_P − v_surface) with q̈ = 0
    contact.acceleration_bias = subs(config.total_derivative(relative), no_acceleration);
    contacts.push_back(std::move(contact));
  }
  return contacts;
}

}  // namespace unidyn
