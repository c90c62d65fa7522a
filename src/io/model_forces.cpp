// The model file's forces: gravity, springs, dampers, forces and moments, potentials, torsion
// springs and dampers, gravity gradient, gravitation.
#include "model_reader.hpp"

namespace unidyn::model_reading {

// A particle's name, {on: B, point: [X1, X2, X3]} (a material point of body B, components on its
// basis from its centre), or a fixed vector. A point that moves must be one of the first two: a
// force at a point of no mass would be seen by Lagrange's equations (through its potential) and
// not by Euler's laws.
ForcePoint ModelReader::force_point(const YAML::Node& node, const System& system,
                                    const Scope& scope) {
  if (node.IsScalar()) {
    if (const auto p = system.find_particle(node.Scalar())) {
      return {p, system.particles[*p].position, std::nullopt};
    }
  }
  if (node.IsMap()) {
    expect_keys(node, {"on", "point"}, "a body point");
    if (!node["on"]) fail(node, "a body point is {on: B, point: [X1, X2, X3]}");
    const auto b = system.find_body(scalar(node["on"], "on"));
    if (!b) fail(node["on"], "on: must name a body");
    const VectorExpr X = node["point"] ? vector_expr(node["point"], scope, "point") : VectorExpr{};
    expect_state_only(node["point"] ? node["point"] : node, X, system, "a body point");
    for (int i = 0; i < 3; ++i) {
      for (const auto& q : system.coordinates()) {
        if (X[i].has(q.value) || X[i].has(system.time())) {
          fail(node["point"], "a point on a body is constant on its basis");
        }
      }
    }
    return {std::nullopt, system.material_point(*b, X), b};
  }
  const VectorExpr point = vector_expr(node, scope, "a point (a particle name or a vector)");
  expect_state_only(node, point, system, "a point");
  for (int i = 0; i < 3; ++i) {
    for (const auto& q : system.coordinates()) {
      if (point[i].has(q.value)) {
        fail(node, "this point moves with " + q.name +
                       " but is neither a particle nor on a body: use a particle's name or {on: B, "
                       "point: [X1, X2, X3]}");
      }
    }
  }
  return {std::nullopt, point, std::nullopt};
}

// The keys of a torsion spring or damper checked, then its angle (`angle:`, with `on:` the body it
// turns) and the moments of a unit torque about it: a joint's angle, or one of a body's Euler
// angles.
std::pair<std::size_t, std::vector<AngleTorque>> ModelReader::torsion_angle(
    const YAML::Node& spec, const System& system, const std::string& what,
    const std::string& required, const std::set<std::string>& optional) {
  // its keys: on, angle, the required constant (stiffness or coefficient) and the optional ones
  expect_map(spec, what);
  std::set<std::string> keys = optional;
  keys.insert({"on", "angle", required});
  expect_keys(spec, keys, what);
  if (!spec["angle"] || !spec[required]) {
    fail(spec, "a " + what + " needs angle: (a joint's angle or a body's Euler angle) and " +
                   required + ":");
  }
  std::optional<std::size_t> on;
  if (spec["on"]) {
    on = system.find_body(scalar(spec["on"], "on"));
    if (!on) fail(spec["on"], "on: must name a body");
  }
  const auto q = system.find_coordinate(scalar(spec["angle"], "angle"));
  if (!q) fail(spec["angle"], "angle: must name a coordinate");
  std::vector<AngleTorque> unit_torque = unit_torque_about(system, *q, on);
  if (unit_torque.empty()) {
    fail(spec["angle"],
         "a " + what + " needs the angle of a joint (two bodies, or a body and the ground, whose " +
             "relative angular velocity is " + system.coordinates()[*q].name +
             "' times a unit vector)" + (on ? " of body '" + system.bodies[*on].name + "'" : "") +
             " or one of a body's Euler angles; a spring on the coordinate alone is a potential: " +
             "K*(q - q0)^2/2");
  }
  return {*q, std::move(unit_torque)};
}

// The two ends of a spring or a damper: not one point, where its direction would be 0/0.
std::pair<ForcePoint, ForcePoint> ModelReader::force_ends(const YAML::Node& spec,
                                                          const std::string& kind,
                                                          const System& system,
                                                          const Scope& scope) {
  ForcePoint from = force_point(spec["from"], system, scope);
  ForcePoint to = force_point(spec["to"], system, scope);
  const VectorExpr d = to.position - from.position;
  if (expand_within_budget(d[0], "a force").is_zero() &&
      expand_within_budget(d[1], "a force").is_zero() &&
      expand_within_budget(d[2], "a force").is_zero()) {
    fail(spec, "a " + kind + " needs two different points: from: and to: are the same");
  }
  return {std::move(from), std::move(to)};
}

// (2.5) spring: {from, to, stiffness: K or energy: U(s), rest_length}: U(s) of its stretch s
// (U = ½ K s² for a linear one).
ForceElement ModelReader::read_spring(const YAML::Node& spec, const System& system,
                                      const Scope& scope) {
  expect_map(spec, "spring");
  expect_keys(spec, {"from", "to", "stiffness", "rest_length", "energy"}, "spring");
  if (!spec["from"] || !spec["to"]) fail(spec, "a spring needs from: and to:");
  if (!!spec["stiffness"] == !!spec["energy"]) {
    fail(spec, "a spring needs either stiffness: K or energy: U(s) of its stretch s");
  }
  const GiNaC::realsymbol s("s");
  Expr rest = 0;
  if (spec["rest_length"]) {
    rest = scalar_expr(spec["rest_length"], scope, "rest_length");
    expect_state_only(spec["rest_length"], rest, system, "a rest length");
  }
  Expr energy;
  if (spec["stiffness"]) {
    const Expr K = scalar_expr(spec["stiffness"], scope, "stiffness");
    expect_state_only(spec["stiffness"], K, system, "a stiffness");
    energy = K * GiNaC::pow(s, 2) / 2;
  } else {
    SystemScope with_stretch(system);
    with_stretch.define("s", Value::of(s));
    energy = scalar_expr(spec["energy"], with_stretch, "energy");
    expect_state_only(spec["energy"], energy, system, "a spring's energy");
  }
  const auto [from, to] = force_ends(spec, "spring", system, scope);
  return spring(from, to, rest, s, energy);
}

// damper: {from, to, coefficient: c}: F_to = −c ṡ e along the line e of its ends.
ForceElement ModelReader::read_damper(const YAML::Node& spec, const System& system,
                                      const Scope& scope) {
  expect_map(spec, "damper");
  expect_keys(spec, {"from", "to", "coefficient"}, "damper");
  if (!spec["from"] || !spec["to"] || !spec["coefficient"]) {
    fail(spec, "a damper needs from:, to: and coefficient:");
  }
  const Expr c = scalar_expr(spec["coefficient"], scope, "coefficient");
  expect_state_only(spec["coefficient"], c, system, "a damping coefficient", true);
  const auto [from, to] = force_ends(spec, "damper", system, scope);
  return damper(system, from, to, c);
}

// force: {value: F, at: a particle} or {value: F, on: a body, point: [X1, X2, X3]}.
ForceElement ModelReader::read_applied_force(const YAML::Node& spec, const System& system,
                                             const Scope& scope) {
  expect_map(spec, "force");
  expect_keys(spec, {"at", "on", "point", "value"}, "force");
  if (!spec["value"] || !!spec["at"] == !!spec["on"]) {
    fail(spec,
         "a force needs value: and either at: (a particle) or on: (a body, with point: "
         "[X1, X2, X3] on its basis from its centre)");
  }
  const VectorExpr F = vector_expr(spec["value"], scope, "value");
  expect_state_only(spec["value"], F, system, "a force", true);
  if (spec["at"]) {
    const auto p = system.find_particle(scalar(spec["at"], "at"));
    if (!p) fail(spec["at"], "at: must name a particle");
    return applied_force(*p, F);
  }
  const auto b = system.find_body(scalar(spec["on"], "on"));
  if (!b) fail(spec["on"], "on: must name a body");
  const VectorExpr X = spec["point"] ? vector_expr(spec["point"], scope, "point") : VectorExpr{};
  return body_force(*b, system.material_point(*b, X), F);
}

// moment: {on: a body, value: M}.
ForceElement ModelReader::read_moment(const YAML::Node& spec, const System& system,
                                      const Scope& scope) {
  expect_map(spec, "moment");
  expect_keys(spec, {"on", "value"}, "moment");
  if (!spec["on"] || !spec["value"]) fail(spec, "a moment needs on: (a body) and value:");
  const auto b = system.find_body(scalar(spec["on"], "on"));
  if (!b) fail(spec["on"], "on: must name a body");
  const VectorExpr M = vector_expr(spec["value"], scope, "value");
  expect_state_only(spec["value"], M, system, "a moment", true);
  return body_moment(*b, M);
}

// (8.25) gravity_gradient: {on: a body, GM, center}: MacCullagh's far field of a sphere.
ForceElement ModelReader::read_gravity_gradient(const YAML::Node& spec, const System& system,
                                                const Scope& scope) {
  expect_map(spec, "gravity_gradient");
  expect_keys(spec, {"on", "GM", "center"}, "gravity_gradient");
  if (!spec["on"] || !spec["GM"]) {
    fail(spec, "gravity_gradient needs on: (a body) and GM: (center: defaults to the origin)");
  }
  const auto b = system.find_body(scalar(spec["on"], "on"));
  if (!b) fail(spec["on"], "on: must name a body");
  const Expr GM = scalar_expr(spec["GM"], scope, "GM");
  expect_state_only(spec["GM"], GM, system, "GM");
  VectorExpr center;
  if (spec["center"]) {
    center = vector_expr(spec["center"], scope, "center");
    expect_state_only(spec["center"], center, system, "the attracting centre");
  }
  return gravity_gradient(system, *b, GM, center);
}

// (8.27) torsion_spring: {angle, on, stiffness: K, rest_angle}: U = ½ K (γ − γ0)²;
// torsion_damper: {angle, on, coefficient: c}: the moments −c γ̇ m_B.
ForceElement ModelReader::read_torsion(const std::string& kind, const YAML::Node& spec,
                                       const System& system, const Scope& scope) {
  if (kind == "torsion_damper") {
    const auto [q, unit_torque] = torsion_angle(spec, system, "torsion_damper", "coefficient");
    const Expr c = scalar_expr(spec["coefficient"], scope, "coefficient");
    expect_state_only(spec["coefficient"], c, system, "a damping coefficient");
    return torsion_damper(system, q, unit_torque, c);
  }
  const auto [q, unit_torque] =
      torsion_angle(spec, system, "torsion_spring", "stiffness", {"rest_angle"});
  const Expr K = scalar_expr(spec["stiffness"], scope, "stiffness");
  expect_state_only(spec["stiffness"], K, system, "a stiffness");
  Expr rest = 0;
  if (spec["rest_angle"]) {
    rest = scalar_expr(spec["rest_angle"], scope, "rest_angle");
    expect_state_only(spec["rest_angle"], rest, system, "a rest angle");
  }
  return torsion_spring(system, q, unit_torque, K, rest);
}

// (2.5) gravitation: {between: [P, Q], G}: U = −G m1 m2 / ‖r2 − r1‖.
ForceElement ModelReader::read_gravitation(const YAML::Node& spec, const System& system,
                                           const Scope& scope) {
  expect_map(spec, "gravitation");
  expect_keys(spec, {"between", "G"}, "gravitation");
  if (!spec["between"] || !spec["G"]) fail(spec, "gravitation needs between: [P, Q] and G:");
  const YAML::Node& pair = spec["between"];
  if (!pair.IsSequence() || pair.size() != 2) fail(pair, "between: must list two particles");
  const auto p1 = system.find_particle(scalar(pair[0], "particle"));
  const auto p2 = system.find_particle(scalar(pair[1], "particle"));
  if (!p1) fail(pair[0], "not a particle");
  if (!p2) fail(pair[1], "not a particle");
  if (*p1 == *p2) fail(pair, "gravitation needs two different particles");
  const Expr G = scalar_expr(spec["G"], scope, "G");
  expect_state_only(spec["G"], G, system, "G");
  return gravitation(system, *p1, *p2, G);
}

// slide_damper: {displacement: d, coefficient: c}: −c ḋ along the axis of d's prismatic joint.
ForceElement ModelReader::read_slide_damper(const YAML::Node& spec, const System& system,
                                            const Scope& scope) {
  expect_map(spec, "slide_damper");
  expect_keys(spec, {"displacement", "coefficient"}, "slide_damper");
  if (!spec["displacement"] || !spec["coefficient"]) {
    fail(spec,
         "a slide_damper needs displacement: (a prismatic joint's coordinate) and "
         "coefficient:");
  }
  const auto d = system.find_coordinate(scalar(spec["displacement"], "displacement"));
  if (!d) fail(spec["displacement"], "displacement: must name a coordinate");
  std::optional<std::size_t> body;
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const auto& joint = system.bodies[b].joint;
    if (joint && joint->kind == TreeJoint::Kind::prismatic && joint->coordinates.front() == *d) {
      body = b;
    }
  }
  if (!body) {
    fail(spec["displacement"], "a slide_damper needs the coordinate of a prismatic joint ('" +
                                   system.coordinates()[*d].name + "' is not one)");
  }
  const Expr c = scalar_expr(spec["coefficient"], scope, "coefficient");
  expect_state_only(spec["coefficient"], c, system, "a damping coefficient");
  return slide_damper(system, *body, c);
}

// One force of the list, {kind: spec}, by its kind.
ForceElement ModelReader::read_force(const YAML::Node& entry, const System& system) {
  const std::string kind = entry.begin()->first.Scalar();
  const YAML::Node spec = entry.begin()->second;  // a copy: the iterator is a temporary
  SystemScope scope(system);
  if (kind == "gravity") {
    const VectorExpr g = vector_expr(spec, scope, "gravity");
    expect_state_only(spec, g, system, "gravity");
    return uniform_gravity(system, g);
  }
  if (kind == "spring") return read_spring(spec, system, scope);
  if (kind == "damper") return read_damper(spec, system, scope);
  if (kind == "force") return read_applied_force(spec, system, scope);
  if (kind == "moment") return read_moment(spec, system, scope);
  if (kind == "gravity_gradient") return read_gravity_gradient(spec, system, scope);
  if (kind == "torsion_spring" || kind == "torsion_damper") {
    return read_torsion(kind, spec, system, scope);
  }
  if (kind == "slide_damper") return read_slide_damper(spec, system, scope);
  if (kind == "potential") {
    const Expr U = scalar_expr(spec, scope, "potential");
    expect_state_only(spec, U, system, "a potential U(q, t)");
    return coordinate_potential(U);
  }
  if (kind == "gravitation") return read_gravitation(spec, system, scope);
  fail(entry.begin()->first, "unknown force '" + kind +
                                 "' (expected gravity, spring, damper, force, moment, "
                                 "potential, gravitation, gravity_gradient, "
                                 "torsion_spring, torsion_damper or slide_damper)");
}

void ModelReader::read_forces(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "forces must be a list, e.g. [{gravity: -g*E3}]");
  for (const auto& entry : node) {
    if (!entry.IsMap() || entry.size() != 1) {
      fail(entry,
           "each force is one of: gravity, spring, damper, force, moment, potential, gravitation, "
           "gravity_gradient, torsion_spring, torsion_damper, slide_damper");
    }
    ForceElement element;
    try {
      element = read_force(entry, system);
    } catch (const ModelError&) {
      throw;
    } catch (const YAML::Exception&) {
      throw;
    } catch (const std::exception& e) {
      // GiNaC refusing to build it, e.g. a division by zero for two particles at one fixed point
      fail(entry, "this " + entry.begin()->first.Scalar() + " cannot be built: " + e.what());
    }
    element.where = at(entry);
    system.forces.push_back(std::move(element));
  }
}

}  // namespace unidyn::model_reading
