// The pieces of Coulomb friction at each rough contact.
#include "unidyn/equations/friction.hpp"

#include <stdexcept>

#include "unidyn/kinematics/constraint_gradient.hpp"

namespace unidyn {
namespace {

// The slip speed |v_t|: v_rel less its part along the normals (one: the surface's; two: off the
// curve's tangent g1 × g2), written as a square root of a sum of squares.
Expr slip_speed(const VectorExpr& relative, const std::vector<VectorExpr>& normals) {
  if (normals.size() == 2) {
    const VectorExpr tangent = cross(normals[0], normals[1]);
    const Expr along = dot(relative, tangent);
    return GiNaC::sqrt(along * along / dot(tangent, tangent));
  }
  const VectorExpr& g = normals.front();
  const VectorExpr slip = relative - (dot(relative, g) / dot(g, g)) * g;
  return GiNaC::sqrt(dot(slip, slip));
}

}  // namespace

bool carries_friction(const System& system, std::size_t k) {
  const Constraint& c = system.constraints[k];
  if (c.friction) return true;
  for (const Constraint& rough : system.constraints) {
    if (!rough.friction) continue;
    for (const std::string& name : rough.friction->with) {
      if (name == c.name) return true;
    }
  }
  return false;
}

std::vector<FrictionContact> friction_contacts(const System& system) {
  std::vector<FrictionContact> contacts;
  const Configuration& config = system.configuration;
  const GiNaC::exmap no_acceleration = config.zero_accelerations();
  GiNaC::exmap at_rest;
  for (const auto& q : system.coordinates()) at_rest[q.rate] = 0;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    if (!c.friction) continue;
    const Friction& friction = *c.friction;
    FrictionContact contact{
        {k}, {}, {}, {}, {}, 0, friction.static_coefficient, friction.viscous_coefficient};
    for (const std::string& name : friction.with) {
      const auto j = system.find_constraint(name);
      if (!j) {
        throw std::invalid_argument("friction on '" + c.name + "': with: names no constraint " +
                                    name);
      }
      contact.constraints.push_back(*j);
    }
    // the contact's velocity v_P and each constraint's normal g_j on P
    const auto p = system.find_particle(friction.on);
    const auto b = system.find_body(friction.on);
    if (!p && !b) {
      throw std::invalid_argument("friction on '" + c.name + "': no particle or body " +
                                  friction.on);
    }
    for (const std::size_t j : contact.constraints) {
      if (system.constraints[j].kind != Constraint::Kind::position) {
        throw std::invalid_argument("friction on '" + c.name + "' needs position constraints");
      }
      const ConstraintLoads loads = constraint_loads(system, j);
      contact.normals.push_back(p ? loads.particle_force[*p] : loads.body_force[*b]);
    }
    const VectorExpr v =
        p ? system.velocity(*p)
          : system.center_velocity(*b) +
                cross(system.angular_velocity(*b), friction.at - system.bodies[*b].center);
    for (const auto& q : system.coordinates()) contact.jacobian.push_back(diff(v, q.rate));
    const VectorExpr relative = v - friction.surface_velocity;
    contact.velocity_term = subs(relative, at_rest);
    // d/dt (v_P − v_surface) with q̈ = 0
    contact.acceleration_bias = subs(config.total_derivative(relative), no_acceleration);
    contact.dynamic_coefficient = friction.dynamic_coefficient;
    if (contact.dynamic_coefficient.has(slip_speed_symbol())) {
      contact.dynamic_coefficient = contact.dynamic_coefficient.subs(
          GiNaC::lst{slip_speed_symbol()}, GiNaC::lst{slip_speed(relative, contact.normals)});
    }
    contacts.push_back(std::move(contact));
  }
  return contacts;
}

}  // namespace unidyn
