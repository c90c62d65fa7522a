// Queries on a System.
#include "unidyn/model/system.hpp"

#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/rotation_expr.hpp"

namespace unidyn {
namespace {

template <class T>
std::optional<std::size_t> find_by_name(const std::vector<T>& items, const std::string& wanted) {
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (items[i].name == wanted) return i;
  }
  return std::nullopt;
}

// The angular velocity of a joint's motion on its joint frame: a q̇ (revolute; planar, about a),
// 0 (fixed, prismatic), or for Euler parameters ((6.36), R(e) of e / |e|)
// 2 (e0 ė − ė0 e + e × ė) / (e0² + e · e).
VectorExpr joint_motion_rate(const TreeJoint& joint, const std::vector<CoordinateSymbols>& q) {
  using Kind = TreeJoint::Kind;
  if (joint.kind == Kind::revolute) return joint.axis * q[joint.coordinates[0]].rate;
  if (joint.kind == Kind::planar) return joint.axis * q[joint.coordinates[2]].rate;
  if (joint.kind != Kind::ball && joint.kind != Kind::floating) return VectorExpr();
  const std::size_t first = joint.kind == Kind::floating ? 3 : 0;
  const auto& c = joint.coordinates;
  const Expr e0 = q[c[first]].value, e0_rate = q[c[first]].rate;
  const VectorExpr e(q[c[first + 1]].value, q[c[first + 2]].value, q[c[first + 3]].value);
  const VectorExpr e_rate(q[c[first + 1]].rate, q[c[first + 2]].rate, q[c[first + 3]].rate);
  return (2 / (e0 * e0 + dot(e, e))) * (e0 * e_rate - e0_rate * e + cross(e, e_rate));
}

// Whether a body moves with Euler parameters: on a ball or floating joint, or below one.
std::vector<bool> below_euler_parameters(const System& system) {
  std::vector<bool> below(system.bodies.size(), false);
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const std::optional<TreeJoint>& joint = system.bodies[b].joint;
    if (!joint) continue;
    below[b] = joint->kind == TreeJoint::Kind::ball || joint->kind == TreeJoint::Kind::floating ||
               (joint->parent && *joint->parent < b && below[*joint->parent]);
  }
  return below;
}

}  // namespace

const GiNaC::realsymbol& slip_speed_symbol() {
  static const GiNaC::realsymbol slip_speed("slip_speed");
  return slip_speed;
}

bool is_integration_method(std::string_view name) {
  for (const std::string_view known : integration_method_names) {
    if (name == known) return true;
  }
  return false;
}

std::string integration_methods() {
  std::string text;
  for (std::size_t i = 0; i < integration_method_names.size(); ++i) {
    if (i > 0) text += i + 1 == integration_method_names.size() ? " or " : ", ";
    text += integration_method_names[i];
  }
  return text;
}

std::string integration_method_choices() {
  std::string text;
  for (const std::string_view name : integration_method_names) {
    if (!text.empty()) text += " | ";
    text += name;
  }
  return text;
}

std::optional<std::size_t> System::find_parameter(const std::string& wanted) const {
  return find_by_name(parameters, wanted);
}

std::optional<std::size_t> System::find_coordinate(const std::string& wanted) const {
  return find_by_name(coordinates(), wanted);
}

std::optional<std::size_t> System::find_particle(const std::string& wanted) const {
  return find_by_name(particles, wanted);
}

std::optional<std::size_t> System::find_body(const std::string& wanted) const {
  return find_by_name(bodies, wanted);
}

std::optional<std::size_t> System::find_constraint(const std::string& wanted) const {
  return find_by_name(constraints, wanted);
}

std::optional<std::size_t> System::find_definition(const std::string& wanted) const {
  return find_by_name(definitions, wanted);
}

VectorExpr System::angular_velocity(std::size_t b) const {
  const TensorExpr& Q = bodies[b].rotation;
  if (const auto cached = angular_velocity_cache_.find(b);
      cached != angular_velocity_cache_.end() && Expr(cached->second.first).is_equal(Q)) {
    return cached->second.second;
  }
  const VectorExpr omega = simplified(axial_rate(b));
  angular_velocity_cache_.insert_or_assign(b, std::make_pair(Q, omega));
  return omega;
}

VectorExpr System::axial_rate(std::size_t b) const {
  const TensorExpr& Q = bodies[b].rotation;
  TensorExpr Q_rate(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) Q_rate(i, k) = configuration.total_derivative(Q(i, k));
  }
  // ω = axial(Q̇ Qᵀ)
  return axial_expr(Q_rate.mul(Q.transpose()));
}

void System::make_angular_velocities() const {
  // a body that moves with Euler parameters takes ω by the tree (below); the others
  // axial(Q̇ Qᵀ), simplified, all at once
  const std::vector<bool> below = below_euler_parameters(*this);
  std::vector<Expr> components;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const VectorExpr omega = below[b] ? VectorExpr() : axial_rate(b);
    components.insert(components.end(), omega.c.begin(), omega.c.end());
  }
  const std::vector<Expr> simple = simplify_all(components);
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    VectorExpr omega{simple[3 * b], simple[3 * b + 1], simple[3 * b + 2]};
    // ω = ω_parent + Q_parent R0 ω_joint, the same as axial(Q̇ Qᵀ), whose expansion grows with
    // every joint above the body (a humanoid's hand did not finish in 10 minutes)
    if (below[b]) {
      const TreeJoint& joint = *bodies[b].joint;
      const TensorExpr frame = joint.parent
                                   ? bodies[*joint.parent].rotation.mul(joint.fixed_rotation)
                                   : joint.fixed_rotation;
      omega = times(frame, joint_motion_rate(joint, coordinates()));
      if (joint.parent) omega = angular_velocity_cache_.at(*joint.parent).second + omega;
    }
    angular_velocity_cache_.insert_or_assign(b, std::make_pair(bodies[b].rotation, omega));
  }
}

VectorExpr System::body_angular_velocity(std::size_t b) const {
  return simplified(times(bodies[b].rotation.transpose(), angular_velocity(b)));
}

VectorExpr System::body_basis_vector(std::size_t b, int k) const {
  return column(bodies[b].rotation, k - 1);
}

VectorExpr System::center_velocity(std::size_t b) const {
  return configuration.total_derivative(bodies[b].center);
}

VectorExpr System::angular_momentum(std::size_t b) const {
  // H = J ω = Q J0 ω0
  return times(bodies[b].rotation, times(bodies[b].inertia, body_angular_velocity(b)));
}

std::array<VectorExpr, 3> System::euler_basis(std::size_t b) const {
  const VectorExpr omega = angular_velocity(b);
  std::array<VectorExpr, 3> g;
  for (std::size_t i = 0; i < 3; ++i) {
    g[i] = simplified(diff(omega, coordinates()[bodies[b].chart->coordinates[i]].rate));
  }
  return g;
}

std::array<VectorExpr, 3> System::dual_euler_basis(std::size_t b) const {
  const std::array<VectorExpr, 3> g = euler_basis(b);
  const Expr volume = simplify(dot(g[0], cross(g[1], g[2])));
  std::array<VectorExpr, 3> dual;
  for (std::size_t i = 0; i < 3; ++i) {
    dual[i] = simplified(cross(g[(i + 1) % 3], g[(i + 2) % 3]) / volume);
  }
  return dual;
}

VectorExpr System::material_point(std::size_t b, const VectorExpr& X) const {
  return bodies[b].center + times(bodies[b].rotation, X);
}

VectorExpr System::velocity(std::size_t p) const {
  return configuration.total_derivative(particles[p].position);
}

VectorExpr System::acceleration(std::size_t p) const {
  return configuration.total_derivative(velocity(p));
}

Expr System::potential_energy() const {
  Expr U = 0;
  for (const auto& f : forces) U += f.potential;
  return U;
}

Expr System::kinetic_energy() const {
  Expr T = 0;
  for (std::size_t p = 0; p < particles.size(); ++p) {
    const VectorExpr v = velocity(p);
    T += particles[p].mass * dot(v, v) / 2;
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    // Koenig: ½ m v̄ · v̄ + ½ ω0 · J0 ω0
    const VectorExpr v = center_velocity(b);
    const VectorExpr w0 = body_angular_velocity(b);
    T += bodies[b].mass * dot(v, v) / 2 + dot(w0, times(bodies[b].inertia, w0)) / 2;
  }
  return T;
}

GiNaC::exmap System::parameter_values() const {
  GiNaC::exmap map;
  for (const auto& p : parameters) map[p.symbol] = p.value;
  return map;
}

GiNaC::exmap System::parameter_values(const std::vector<double>& values) const {
  GiNaC::exmap map;
  for (std::size_t k = 0; k < parameters.size(); ++k) map[parameters[k].symbol] = values[k];
  return map;
}

}  // namespace unidyn
