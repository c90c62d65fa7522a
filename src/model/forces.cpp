// Force elements: potentials and particle forces.
#include "unidyn/model/forces.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {
namespace {

// Adds F at a point to the element when the point is a particle or on a body (forces on fixed
// points are reactions the system does not see).
void push_force(ForceElement& element, const ForcePoint& point, const VectorExpr& F) {
  if (point.particle) element.forces.push_back({*point.particle, F});
  if (point.body) element.body_forces.push_back({*point.body, point.position, F});
}

}  // namespace

ForceElement new_element(ForceElement::Kind kind, const std::string& label, bool conservative) {
  ForceElement element;
  element.kind = kind;
  element.label = label;
  element.conservative = conservative;
  return element;
}

ForceElement uniform_gravity(const System& system, const VectorExpr& g) {
  ForceElement element = new_element(ForceElement::Kind::gravity, "gravity", true);
  element.field = g;
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    const Particle& particle = system.particles[p];
    // (2.5) U = −m g · r, F = −∂U/∂r = m g
    element.potential -= particle.mass * dot(g, particle.position);
    element.forces.push_back({p, particle.mass * g});
  }
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    // (8.x) on a body: the resultant m g at the centre of mass, U = −m g · x̄
    const Body& body = system.bodies[b];
    element.potential -= body.mass * dot(g, body.center);
    element.body_forces.push_back({b, body.center, body.mass * g});
  }
  return element;
}

ForceElement spring(const ForcePoint& from, const ForcePoint& to, const Expr& rest_length,
                    const GiNaC::symbol& stretch, const Expr& energy) {
  ForceElement element = new_element(ForceElement::Kind::spring, "spring", true);
  const VectorExpr d = to.position - from.position;
  const Expr length = norm(d);
  const Expr s = length - rest_length;
  const VectorExpr e = d / length;
  // U'(s) at the current stretch
  const Expr tension = derivative(energy, stretch).subs(GiNaC::lst{stretch}, GiNaC::lst{s});
  element.potential = energy.subs(GiNaC::lst{stretch}, GiNaC::lst{s});
  push_force(element, to, -tension * e);
  push_force(element, from, tension * e);
  return element;
}

ForceElement damper(const System& system, const ForcePoint& from, const ForcePoint& to,
                    const Expr& coefficient) {
  ForceElement element = new_element(ForceElement::Kind::damper, "damper", false);
  const VectorExpr d = to.position - from.position;
  const VectorExpr e = d / norm(d);
  const VectorExpr relative_velocity = system.configuration.total_derivative(d);
  const Expr stretch_rate = dot(e, relative_velocity);
  push_force(element, to, -coefficient * stretch_rate * e);
  push_force(element, from, coefficient * stretch_rate * e);
  return element;
}

ForceElement applied_force(std::size_t particle, const VectorExpr& force) {
  ForceElement element = new_element(ForceElement::Kind::force, "force", false);
  element.forces.push_back({particle, force});
  return element;
}

ForceElement coordinate_potential(const Expr& U) {
  ForceElement element = new_element(ForceElement::Kind::potential, "potential", true);
  element.potential = U;
  return element;
}

ForceElement gravitation(const System& system, std::size_t first, std::size_t second,
                         const Expr& G) {
  ForceElement element = new_element(ForceElement::Kind::gravitation, "gravitation", true);
  const Particle& p1 = system.particles[first];
  const Particle& p2 = system.particles[second];
  const VectorExpr d = p2.position - p1.position;
  const Expr distance = norm(d);
  // (2.5) U = −G m1 m2 / ‖r2 − r1‖; F_2 = −G m1 m2 (r2 − r1)/‖r2 − r1‖³ = −F_1
  element.potential = -G * p1.mass * p2.mass / distance;
  const VectorExpr F2 = (-G * p1.mass * p2.mass / GiNaC::pow(distance, 3)) * d;
  element.forces.push_back({second, F2});
  element.forces.push_back({first, -F2});
  return element;
}

}  // namespace unidyn

namespace unidyn {

ForceElement body_force(std::size_t body, const VectorExpr& point, const VectorExpr& force) {
  ForceElement element = new_element(ForceElement::Kind::force, "force", false);
  element.body_forces.push_back({body, point, force});
  return element;
}

ForceElement body_moment(std::size_t body, const VectorExpr& moment) {
  ForceElement element = new_element(ForceElement::Kind::moment, "moment", false);
  element.moments.push_back({body, moment});
  return element;
}

}  // namespace unidyn

namespace unidyn {

ForceElement gravity_gradient(const System& system, std::size_t body, const Expr& GM,
                              const VectorExpr& attractor) {
  ForceElement element =
      new_element(ForceElement::Kind::gravity_gradient, "gravity_gradient", true);
  const Body& b = system.bodies[body];
  const VectorExpr d = b.center - attractor;
  const Expr R = norm(d);
  const VectorExpr c = d / R;
  // J c = Q J0 Qᵀ c; tr J = tr J0
  const VectorExpr Jc = times(b.rotation, times(b.inertia, times(b.rotation.transpose(), c)));
  const Expr trace = b.inertia(0, 0) + b.inertia(1, 1) + b.inertia(2, 2);
  const Expr cJc = dot(c, Jc);
  // (8.25) MacCullagh's potential, force and moment
  element.potential = -GM * b.mass / R - GM * trace / (2 * GiNaC::pow(R, 3)) +
                      3 * GM * cJc / (2 * GiNaC::pow(R, 3));
  const VectorExpr F = (-GM * b.mass / GiNaC::pow(R, 2)) * c -
                       (3 * GM / (2 * GiNaC::pow(R, 4))) * (2 * Jc + (trace - 5 * cJc) * c);
  element.body_forces.push_back({body, b.center, F});
  element.moments.push_back({body, (3 * GM / GiNaC::pow(R, 3)) * cross(c, Jc)});
  return element;
}

}  // namespace unidyn

namespace unidyn {

ForceElement torsion_spring(const System& system, std::size_t angle,
                            const std::vector<AngleTorque>& unit_torque, const Expr& K,
                            const Expr& rest_angle) {
  ForceElement element = new_element(ForceElement::Kind::torsion_spring, "torsion_spring", true);
  element.angle = angle;
  const Expr gamma = system.coordinates()[angle].value;
  // U = ½ K (γ − γ0)²; (8.27) M = −∂U/∂γ m_B
  element.potential = K * GiNaC::pow(gamma - rest_angle, 2) / 2;
  for (const AngleTorque& m : unit_torque) {
    element.moments.push_back({m.body, -K * (gamma - rest_angle) * m.per_unit_torque});
  }
  return element;
}

ForceElement torsion_damper(const System& system, std::size_t angle,
                            const std::vector<AngleTorque>& unit_torque, const Expr& c) {
  ForceElement element = new_element(ForceElement::Kind::torsion_damper, "torsion_damper", false);
  element.angle = angle;
  element.coefficient = c;
  // M = −c γ̇ m_B
  const Expr rate = system.coordinates()[angle].rate;
  for (const AngleTorque& m : unit_torque) {
    element.moments.push_back({m.body, -c * rate * m.per_unit_torque});
  }
  return element;
}

ForceElement slide_damper(const System& system, std::size_t body, const Expr& c) {
  ForceElement element = new_element(ForceElement::Kind::slide_damper, "slide_damper", false);
  const Body& b = system.bodies[body];
  const std::size_t d = b.joint->coordinates.front();
  element.angle = d;
  element.coefficient = c;
  // F = −c ḋ u at o on B; −F on the parent at the joint's origin o_P + Q_P p, a point of the parent
  // on the same line (o = o_P + Q_P p + d u): the same moment as at o, and its partial velocities
  // are the parent's (the virtual work of (3.7) takes a material point)
  const VectorExpr F = (-c * system.coordinates()[d].rate) * times(b.rotation, b.joint->axis);
  element.body_forces.push_back({body, b.origin, F});
  if (b.joint->parent) {
    const Body& parent = system.bodies[*b.joint->parent];
    element.body_forces.push_back(
        {*b.joint->parent, parent.origin + times(parent.rotation, b.joint->origin), Expr(-1) * F});
  }
  return element;
}

}  // namespace unidyn
