// The model file's friction at a contact: `friction: {on, at, dynamic, static, viscous,
// surface_velocity, with}` on a position constraint (equations/friction.hpp).
#include "model_reader.hpp"
#include "unidyn/kinematics/constraint_gradient.hpp"

namespace unidyn::model_reading {

Friction ModelReader::read_friction(const YAML::Node& f, const Constraint& c,
                                    const System& system) {
  expect_map(f, "friction");
  expect_keys(f, {"on", "at", "dynamic", "static", "viscous", "surface_velocity", "with"},
              "friction");
  if (!f["on"] || !f["dynamic"]) {
    fail(f,
         "friction needs on: (a particle, or a body with at: its point of contact) and dynamic:");
  }
  if (c.kind != Constraint::Kind::position) {
    fail(f, "friction acts at the contact of a position constraint (a surface or curve)");
  }
  const SystemScope scope(system);
  // μ_d may depend on the slip speed (Ex. 9.13: mu_k + mu_v*slip_speed)
  SystemScope with_slip(system);
  with_slip.define("slip_speed", Value::of(slip_speed_symbol()));
  Friction friction{scalar(f["on"], "on"),
                    scalar_expr(f["dynamic"], with_slip, "dynamic"),
                    0,
                    VectorExpr{},
                    VectorExpr{},
                    {},
                    0};
  expect_state_only(f["dynamic"], friction.dynamic_coefficient, system, "a coefficient");
  if (f["static"]) {
    friction.static_coefficient = scalar_expr(f["static"], with_slip, "static");
    if (friction.static_coefficient.has(slip_speed_symbol())) {
      fail(f["static"], "the static coefficient acts without slip: slip_speed belongs in dynamic:");
    }
  } else {
    // μ_s defaults to μ_d at no slip
    friction.static_coefficient = friction.dynamic_coefficient.subs(GiNaC::lst{slip_speed_symbol()},
                                                                    GiNaC::lst{GiNaC::ex(0)});
  }
  expect_state_only(f["static"] ? f["static"] : f, friction.static_coefficient, system,
                    "a coefficient");
  if (f["viscous"]) {
    friction.viscous_coefficient = scalar_expr(f["viscous"], scope, "viscous");
    expect_state_only(f["viscous"], friction.viscous_coefficient, system, "a coefficient");
  }
  if (f["surface_velocity"]) {
    friction.surface_velocity = vector_expr(f["surface_velocity"], scope, "surface_velocity");
    expect_state_only(f["surface_velocity"], friction.surface_velocity, system,
                      "a surface velocity");
  }
  if (f["with"]) {
    if (!f["with"].IsSequence()) fail(f["with"], "with: is a list of constraint names");
    for (const auto& name : f["with"]) friction.with.push_back(scalar(name, "a constraint name"));
  }
  const bool body = system.find_body(friction.on).has_value();
  if (!system.find_particle(friction.on) && !body) {
    fail(f["on"], "on: must name a particle or a body");
  }
  if (body != static_cast<bool>(f["at"])) {
    fail(f, body ? "friction on a body needs at: its point of contact, e.g. \"B.center - R*E3\""
                 : "at: is for a body's point of contact; a particle is its own");
  }
  if (body) {
    friction.at = vector_expr(f["at"], scope, "at");
    expect_state_only(f["at"], friction.at, system, "a point of contact");
  }
  return friction;
}

void ModelReader::check_friction(const std::vector<std::pair<std::size_t, YAML::Node>>& rough,
                                 const System& system) const {
  std::set<std::string> held;  // the constraints some contact's with: names
  for (const auto& [k, f] : rough) {
    const Constraint& c = system.constraints[k];
    std::size_t item = 0;
    for (const std::string& name : c.friction->with) {
      const YAML::Node where = f["with"][item++];
      const std::optional<std::size_t> other = system.find_constraint(name);
      if (!other) fail(where, "with: names no constraint '" + name + "'");
      const Constraint& o = system.constraints[*other];
      if (*other == k) fail(where, "with: names the rough constraint itself");
      if (o.kind != Constraint::Kind::position) {
        fail(where, "'" + name + "' is not a position constraint: a curve is two surfaces");
      }
      if (o.friction) {
        fail(where, "'" + name + "' has friction of its own: give the curve's friction once");
      }
      if (!held.insert(name).second) {
        fail(where, "'" + name + "' is already in the with: of a rough contact");
      }
    }
  }
  // a rough contact needs each normal ∂Ψ/∂r_P, which needs the coordinates to fix the positions
  for (const auto& [k, f] : rough) {
    const Constraint& c = system.constraints[k];
    std::vector<std::size_t> holding{k};
    for (const std::string& name : c.friction->with)
      holding.push_back(*system.find_constraint(name));
    for (const std::size_t j : holding) {
      try {
        constraint_loads(system, j);
      } catch (const std::invalid_argument& e) {
        throw ModelError(c.where, "friction on '" + c.name + "': " + e.what());
      }
    }
  }
}

}  // namespace unidyn::model_reading
