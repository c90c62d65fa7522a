// The model file's constraints: position and velocity constraints, unilateral contacts, friction,
// joints (ball, pin) and rolling.
#include "model_reader.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn::model_reading {

namespace {

// Whether an expanded expression is linear in the rates der(q): a rate may be a term or a factor
// of a term, never inside a power or a function, nor two of them in one product.
bool linear_in_rates(const Expr& e, const System& system) {
  bool has_rate = false;
  for (const auto& q : system.coordinates()) has_rate = has_rate || e.has(q.rate);
  if (!has_rate || GiNaC::is_a<GiNaC::symbol>(e)) return true;
  if (GiNaC::is_a<GiNaC::add>(e)) {
    for (const auto& term : e) {
      if (!linear_in_rates(term, system)) return false;
    }
    return true;
  }
  if (GiNaC::is_a<GiNaC::mul>(e)) {
    int with_rates = 0;
    for (const auto& factor : e) {
      if (!linear_in_rates(factor, system)) return false;
      for (const auto& q : system.coordinates()) {
        if (factor.has(q.rate)) {
          ++with_rates;
          break;
        }
      }
    }
    return with_rates <= 1;
  }
  return false;
}

}  // namespace

void ModelReader::read_constraints(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "constraints must be a list");
  const SystemScope scope(system);
  std::set<std::string> names;
  std::vector<std::pair<std::size_t, YAML::Node>> rough;     // each rough constraint's friction:
  std::vector<std::pair<std::size_t, YAML::Node>> switched;  // each off_while:
  for (const auto& spec : node) {
    expect_map(spec, "a constraint");
    expect_keys(spec,
                {"name", "position", "velocity", "ball", "pin", "rolling", "unilateral",
                 "restitution", "friction", "off_while"},
                "a constraint");
    if (!!spec["position"] + !!spec["velocity"] + !!spec["ball"] + !!spec["pin"] +
            !!spec["rolling"] !=
        1) {
      fail(spec,
           "a constraint needs exactly one of position: Ψ(q, t), velocity: (linear in der(q)), "
           "ball: or pin: (a joint), or rolling: (without slip)");
    }
    // one name space with parameters, coordinates and particles (c.lambda, lambda(c) columns)
    const std::string name = spec["name"] ? new_name(spec["name"], system, "constraint")
                                          : "c" + std::to_string(system.constraints.size() + 1);
    if (spec["ball"] || spec["pin"] || spec["rolling"]) {
      const std::size_t first_row = system.constraints.size();
      read_joint(spec, name, system);
      for (std::size_t k = first_row; k < system.constraints.size(); ++k) {
        if (!names.insert(system.constraints[k].name).second) {
          fail(spec, "the joint's row '" + system.constraints[k].name + "' is already defined");
        }
      }
      names.insert(name);
      continue;
    }
    Constraint c{
        name,     Constraint::Kind::position,
        0,        GiNaC::realsymbol("lambda(" + name + ")", "\\lambda_{\\mathrm{" + name + "}}"),
        false,    std::nullopt,
        at(spec), name,
        {},       false,
        0,        {}};
    if (!names.insert(c.name).second || system.find_parameter(c.name) ||
        system.find_coordinate(c.name) || system.find_particle(c.name)) {
      fail(spec["name"] ? spec["name"] : spec, "'" + c.name + "' is already defined");
    }
    if (spec["position"]) {
      c.kind = Constraint::Kind::position;
      c.expression = scalar_expr(spec["position"], scope, "position");
      for (const auto& q : system.coordinates()) {
        if (c.expression.has(q.rate))
          fail(spec["position"],
               "a position constraint cannot depend on der(" + q.name + "); use velocity:");
      }
      expect_state_only(spec["position"], c.expression, system, "a position constraint");
    } else {
      c.kind = Constraint::Kind::velocity;
      c.expression = scalar_expr(spec["velocity"], scope, "velocity");
      expect_state_only(spec["velocity"], c.expression, system, "a velocity constraint", true);
      for (const auto& q : system.coordinates()) {
        if (!derivative(derivative(c.expression, q.rate), q.rate).is_zero()) {
          fail(spec["velocity"],
               "a velocity constraint must be linear in the rates; it is not in der(" + q.name +
                   ")");
        }
      }
      // The second derivatives miss der(x)*der(y) and abs(der(x)); the form of the expanded
      // expression does not.
      if (!linear_in_rates(expand_within_budget(c.expression, "a velocity constraint"), system)) {
        fail(spec["velocity"],
             "a velocity constraint must be linear in the rates der(q), as A(q, t) der(q) + e(q, "
             "t)");
      }
    }
    if (spec["unilateral"]) {
      const std::string flag = scalar(spec["unilateral"], "unilateral");
      if (flag != "true" && flag != "false") {
        fail(spec["unilateral"], "unilateral must be true or false");
      }
      c.unilateral = flag == "true";
      if (c.unilateral && c.kind != Constraint::Kind::position) {
        fail(spec["unilateral"], "only a position constraint Ψ ≥ 0 can be unilateral");
      }
    }
    if (spec["restitution"]) {
      if (!c.unilateral) fail(spec["restitution"], "restitution: needs unilateral: true");
      c.restitution = scalar_expr(spec["restitution"], scope, "restitution");
      expect_state_only(spec["restitution"], c.restitution, system, "a restitution", false);
      expect_parameters_only(spec["restitution"], c.restitution, system,
                             "a restitution is a number or depends on parameters only");
    }
    if (spec["off_while"]) {
      if (c.kind != Constraint::Kind::velocity || c.unilateral) {
        fail(spec["off_while"], "off_while: is for a velocity constraint (bilateral)");
      }
      c.off_while = scalar(spec["off_while"], "off_while");
      switched.emplace_back(system.constraints.size(), spec["off_while"]);
    }
    if (spec["friction"]) {
      c.friction = read_friction(spec["friction"], c, system);
      rough.emplace_back(system.constraints.size(), spec["friction"]);
    }
    system.constraints.push_back(std::move(c));
  }
  check_friction(rough, system);
  // off_while: names a unilateral contact
  for (const auto& [k, off_while] : switched) {
    const std::string& name = system.constraints[k].off_while;
    const auto contact = system.find_constraint(name);
    if (!contact || !system.constraints[*contact].unilateral) {
      fail(off_while, "off_while: names no unilateral constraint '" + name + "'");
    }
  }
}

// ball: {body: A, point: [X on A], to: B, to_point: [X on B]} — or, without to:, a fixed point
// to_point: (default the origin); pin: the same with axis: [A on A] and to_axis: [on B, or a
// fixed direction; default the same numbers as axis]. Rows name_1 .. name_3 (.. name_5 for a pin).
void ModelReader::read_joint(const YAML::Node& spec, const std::string& name, System& system) {
  if (spec["rolling"]) {
    read_rolling(spec, name, system);
    return;
  }
  const bool pin = static_cast<bool>(spec["pin"]);
  const YAML::Node j = pin ? spec["pin"] : spec["ball"];
  const std::string what = pin ? "a pin" : "a ball joint";
  expect_map(j, what);
  if (pin) {
    expect_keys(j, {"body", "point", "axis", "to", "to_point", "to_axis"}, what);
  } else {
    expect_keys(j, {"body", "point", "to", "to_point"}, what);
  }
  if (spec["unilateral"] || spec["friction"] || spec["restitution"]) {
    fail(spec, "a joint cannot be unilateral or rough");
  }
  if (!j["body"]) fail(j, what + " needs body: (and to: another body, or the ground without it)");
  if (pin && !j["axis"]) fail(j, "a pin needs axis: [A1, A2, A3] on the body's basis");
  const SystemScope scope(system);
  const auto end = [&](const char* body_key, const char* point_key, const char* axis_key) {
    JointEnd e;
    if (j[body_key]) {
      e.body = system.find_body(scalar(j[body_key], body_key));
      if (!e.body) fail(j[body_key], std::string(body_key) + ": must name a body");
    }
    if (j[point_key]) {
      e.point = vector_expr(j[point_key], scope, point_key);
      expect_state_only(j[point_key], e.point, system, "a joint's point", false);
      if (e.body) {
        for (int i = 0; i < 3; ++i) {
          for (const auto& q : system.coordinates()) {
            if (e.point[i].has(q.value) || e.point[i].has(system.time())) {
              fail(j[point_key], "a point on a body is constant on its basis");
            }
          }
        }
      }
    }
    if (pin) {
      const YAML::Node& a = j[axis_key] ? j[axis_key] : j["axis"];
      e.axis = vector_expr(a, scope, axis_key);
      for (int i = 0; i < 3; ++i) {
        if (!GiNaC::is_a<GiNaC::numeric>(e.axis[i])) {
          fail(a, "an axis is a vector of numbers, e.g. [0, 0, 1]");
        }
      }
      if (norm(e.axis).is_zero()) fail(a, "an axis cannot be zero");
    }
    return e;
  };
  const JointEnd first = end("body", "point", "axis");
  const JointEnd second = end("to", "to_point", "to_axis");
  if (first.body && first.body == second.body) fail(j, what + " joins two different bodies");
  const std::vector<Constraint> rows = pin ? pin_joint(system, name, first, second, at(spec))
                                           : ball_joint(system, name, first, second, at(spec));
  for (const auto& c : rows) {
    if (system.find_parameter(c.name) || system.find_coordinate(c.name) ||
        system.find_particle(c.name) || system.find_body(c.name)) {
      fail(spec, "the joint's row '" + c.name + "' clashes with a name already defined");
    }
    system.constraints.push_back(c);
  }
}

// rolling: {body: B, at: <its point of contact>, normal: <the surface's normal there>}: rows
// name_1, name_2 that keep the contact from slipping on the fixed surface (model/joints.hpp).
void ModelReader::read_rolling(const YAML::Node& spec, const std::string& name, System& system) {
  const YAML::Node r = spec["rolling"];
  expect_map(r, "rolling");
  expect_keys(r, {"body", "at", "normal"}, "rolling");
  if (spec["unilateral"] || spec["friction"] || spec["restitution"]) {
    fail(spec, "rolling cannot be unilateral or carry friction (it is the no-slip condition)");
  }
  if (!r["body"] || !r["at"] || !r["normal"]) {
    fail(r, "rolling needs body:, at: (its point of contact) and normal: (the surface's there)");
  }
  const auto b = system.find_body(scalar(r["body"], "body"));
  if (!b) fail(r["body"], "body: must name a body");
  const SystemScope scope(system);
  const VectorExpr contact = vector_expr(r["at"], scope, "at");
  expect_state_only(r["at"], contact, system, "a point of contact");
  const VectorExpr normal = vector_expr(r["normal"], scope, "normal");
  expect_state_only(r["normal"], normal, system, "the normal of a fixed surface");
  for (int i = 0; i < 3; ++i) {
    if (normal[i].has(system.time())) {
      fail(r["normal"], "rolling is on a fixed surface: its normal cannot depend on t");
    }
  }
  if (norm(normal).is_zero()) fail(r["normal"], "a normal cannot be zero");
  std::vector<Constraint> rows;
  try {
    rows = rolling_contact(system, name, *b, contact, normal, at(spec));
  } catch (const std::invalid_argument& e) {
    fail(r["normal"], e.what());
  }
  for (auto& c : rows) {
    if (system.find_parameter(c.name) || system.find_coordinate(c.name) ||
        system.find_particle(c.name) || system.find_body(c.name)) {
      fail(spec, "the rolling row '" + c.name + "' clashes with a name already defined");
    }
    system.constraints.push_back(std::move(c));
  }
}

}  // namespace unidyn::model_reading
