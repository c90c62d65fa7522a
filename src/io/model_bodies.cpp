// The model file's parameters, coordinates, particles and bodies (inertia, rotation, Euler charts).
#include "model_reader.hpp"

#include <algorithm>
#include <cctype>

#include "unidyn/symbolic/printing.hpp"

namespace unidyn::model_reading {

void ModelReader::read_parameters(const YAML::Node& node, System& system) {
  expect_map(node, "parameters");
  for (const auto& item : node) {
    const std::string name = new_name(item.first, system, "parameter");
    // a number as typed, or an expression of numbers and earlier parameters (pi/10, 2*L, 30*deg)
    if (const auto value = plain_number(item.second)) {
      system.parameters.push_back(
          {name, GiNaC::realsymbol(name, latex_name(name)), *value, at(item.first)});
      continue;
    }
    const Expr definition =
        scalar_expr(item.second, SystemScope(system), "parameter '" + name + "'");
    const auto value = real_value(definition, system.parameter_values());
    if (!value) {
      fail(item.second, "parameter '" + name +
                            "' must be a real number, or an expression of numbers and earlier "
                            "parameters (such as pi/10 or 2*L)");
    }
    system.parameters.push_back({name, GiNaC::realsymbol(name, latex_name(name)), *value,
                                 at(item.first), definition, true});
  }
}

void ModelReader::read_coordinates(const YAML::Node& node, System& system) {
  if (!node.IsSequence() || node.size() == 0)
    fail(node, "coordinates must be a list of names, e.g. [x, y]");
  for (const auto& item : node) {
    system.configuration.add(new_name(item, system, "coordinate"));
    coordinate_at_.push_back(at(item));
  }
}

void ModelReader::read_particles(const YAML::Node& node, System& system) {
  expect_map(node, "particles");
  for (const auto& item : node) {
    const std::string name = new_name(item.first, system, "particle");
    const YAML::Node& spec = item.second;
    expect_map(spec, "particle '" + name + "'");
    expect_keys(spec, {"mass", "position"}, "particle '" + name + "'");
    if (!spec["mass"] || !spec["position"])
      fail(spec, "particle '" + name + "' needs mass: and position:");
    const SystemScope scope(system);
    const Expr mass = scalar_expr(spec["mass"], scope, "mass");
    expect_state_only(spec["mass"], mass, system, "a mass");
    expect_positive_mass(spec["mass"], mass, system);
    const VectorExpr position = vector_expr(spec["position"], scope, "position");
    expect_state_only(spec["position"], position, system, "a position");
    system.particles.push_back({name, mass, position, at(item.first)});
  }
}

void ModelReader::read_bodies(const YAML::Node& node, System& system) {
  expect_map(node, "bodies");
  for (const auto& item : node) {
    const std::string name = new_name(item.first, system, "body");
    const YAML::Node& spec = item.second;
    expect_map(spec, "body '" + name + "'");
    const bool jointed = static_cast<bool>(spec["joint"]);
    if (jointed) {
      expect_keys(spec, {"mass", "inertia", "joint", "center", "visual"}, "body '" + name + "'");
      if (!spec["mass"]) fail(spec, "body '" + name + "' needs mass:");
    } else {
      expect_keys(spec, {"mass", "inertia", "rotation", "center", "visual"}, "body '" + name + "'");
      if (!spec["mass"] || !spec["inertia"] || !spec["rotation"] || !spec["center"]) {
        fail(spec, "body '" + name + "' needs mass:, inertia:, rotation: and center:");
      }
    }
    const SystemScope scope(system);
    const Expr mass = scalar_expr(spec["mass"], scope, "mass");
    expect_state_only(spec["mass"], mass, system, "a mass");
    // mass: 0 with a joint: a frame of the tree (a URDF link without inertia)
    if (!(jointed && mass.is_zero())) expect_positive_mass(spec["mass"], mass, system);
    shape_mass_ = mass;
    Body body;
    body.name = name;
    body.mass = mass;
    body.inertia = spec["inertia"] ? inertia(spec["inertia"], system) : GiNaC::matrix(3, 3);
    body.where = at(item.first);
    if (jointed) {
      place_by_joint(spec["joint"], body, system);
    } else {
      body.rotation = rotation(spec["rotation"], system);
      body.chart = euler_chart(spec["rotation"], system);
      add_unit_norm_constraint(spec["rotation"], name, system);
    }
    // the centre may use the body's own basis (l*top.e3): the body is known before it is read
    system.bodies.push_back(body);
    Body& added = system.bodies.back();
    if (spec["center"]) {
      const SystemScope with_body(system);
      added.center = vector_expr(spec["center"], with_body, "center");
      expect_state_only(spec["center"], added.center, system, "a centre of mass");
    } else {
      added.center = added.origin;
    }
    if (!jointed) added.origin = added.center;
    if (spec["inertia"]) expect_realisable_inertia(spec["inertia"], added.inertia, system);
    added.visual = spec["visual"]    ? visual(spec["visual"], system)
                   : spec["inertia"] ? visual_of_inertia(spec["inertia"], system)
                                     : BodyVisual{};
  }
  // each body's ω (all at once: their simplification shared among processes), then whether a
  // body turns about an axis along which it has no inertia (a frame has none at all)
  system.make_angular_velocities();
  std::size_t b = 0;
  for (const auto& item : node) {
    const YAML::Node& spec = item.second;
    if (!system.bodies[b].mass.is_zero())
      expect_inertia_about_rotation_axes(spec["joint"] ? spec["joint"] : spec["rotation"], b,
                                         system);
    ++b;
  }
}

// A shape with its dimensions, {disk: {radius: R}}, as the inertia's shapes are written.
BodyVisual ModelReader::shape_visual(const YAML::Node& node, const std::string& shape,
                                     const System& system) {
  const SystemScope scope(system);
  BodyVisual out{shape, {}, ""};
  const auto names = shape_dimensions(shape);
  expect_map(node, shape);
  expect_keys(node, std::set<std::string>(names.begin(), names.end()), shape);
  for (const auto& n : names) {
    if (!node[n]) fail(node, shape + " needs " + n + ":");
    out.dimensions.push_back(scalar_expr(node[n], scope, n));
    expect_state_only(node[n], out.dimensions.back(), system, "a dimension");
  }
  return out;
}

// visual: {SHAPE: {dimensions}, color: "#rrggbb"} (both optional).
BodyVisual ModelReader::visual(const YAML::Node& node, const System& system) {
  expect_map(node, "visual");
  BodyVisual out;
  for (const auto& item : node) {
    const std::string key = item.first.Scalar();
    if (key == "color") {
      const std::string color = scalar(item.second, "color");
      const bool hex = color.size() == 7 && color[0] == '#' &&
                       std::all_of(color.begin() + 1, color.end(), [](char c) {
                         return std::isxdigit(static_cast<unsigned char>(c));
                       });
      if (!hex) fail(item.second, "a colour is written #rrggbb (six hexadecimal digits)");
      out.color = color;
    } else if (!shape_dimensions(key).empty()) {
      if (!out.shape.empty()) fail(item.first, "visual: has one shape");
      const std::string color = out.color;
      out = shape_visual(item.second, key, system);
      out.color = color;
    } else {
      fail(item.first,
           "visual: has a shape (sphere, hollow_sphere, cylinder, hollow_cylinder, "
           "disk, rod, box, ellipsoid, cone) and a color");
    }
  }
  return out;
}

// An inertia given as a shape is drawn as that shape; otherwise nothing is said.
BodyVisual ModelReader::visual_of_inertia(const YAML::Node& node, const System& system) {
  if (node.IsMap() && node.size() == 1 && !shape_dimensions(node.begin()->first.Scalar()).empty()) {
    return shape_visual(node.begin()->second, node.begin()->first.Scalar(), system);
  }
  return {};
}

// [A, B, C] principal moments along e1, e2, e3, or {tensor: [[..], [..], [..]]} (components on
// e_i).
GiNaC::matrix ModelReader::inertia(const YAML::Node& node, const System& system) {
  const SystemScope scope(system);
  GiNaC::matrix J(3, 3);
  if (node.IsSequence()) {
    if (node.size() != 3) fail(node, "inertia: [A, B, C] takes three principal moments");
    for (unsigned i = 0; i < 3; ++i) J(i, i) = scalar_expr(node[i], scope, "a moment of inertia");
  } else if (node.IsMap() && node["tensor"] && node.size() == 1) {
    const YAML::Node& rows = node["tensor"];
    if (!rows.IsSequence() || rows.size() != 3) fail(rows, "tensor: takes three rows of three");
    for (unsigned i = 0; i < 3; ++i) {
      if (!rows[i].IsSequence() || rows[i].size() != 3) fail(rows[i], "a row of three components");
      for (unsigned k = 0; k < 3; ++k) J(i, k) = scalar_expr(rows[i][k], scope, "a component");
    }
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned k = 0; k < i; ++k) {
        if (!expand_within_budget(J(i, k) - J(k, i), "an inertia tensor").is_zero())
          fail(rows, "an inertia tensor is symmetric");
      }
    }
  } else if (node.IsMap() && node.size() == 1 &&
             !shape_dimensions(node.begin()->first.Scalar()).empty()) {
    // a uniform shape: {cylinder: {radius: R, height: h}}; its mass is filled in by read_bodies
    const std::string shape = node.begin()->first.Scalar();
    const YAML::Node dims = node.begin()->second;
    const auto names = shape_dimensions(shape);
    expect_map(dims, shape);
    expect_keys(dims, std::set<std::string>(names.begin(), names.end()), shape);
    std::vector<Expr> values;
    for (const auto& n : names) {
      if (!dims[n]) fail(dims, shape + " needs " + n + ":");
      values.push_back(scalar_expr(dims[n], scope, n));
    }
    const auto moments = shape_principal_moments(shape, shape_mass_, values);
    for (unsigned i = 0; i < 3; ++i) J(i, i) = moments[i];
  } else {
    fail(node,
         "inertia must be [A, B, C], {tensor: [[..], [..], [..]]} or a shape: sphere, "
         "hollow_sphere, cylinder, hollow_cylinder, disk, rod, box, ellipsoid, cone");
  }
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) expect_state_only(node, J(i, k), system, "an inertia");
  }
  return J;
}

// {euler: I-J-K, angles: [..]}, {axis: [..], angle: ..}, {quaternion: [e0, e1, e2, e3]}, or a list
// of these, multiplied left to right.
TensorExpr ModelReader::rotation(const YAML::Node& node, const System& system) {
  const SystemScope scope(system);
  if (node.IsSequence()) {
    if (node.size() == 0) fail(node, "an empty product of rotations");
    TensorExpr Q = identity_tensor_expr();
    for (const auto& factor : node) Q = Q.mul(rotation(factor, system));
    return Q;
  }
  expect_map(node, "a rotation");
  TensorExpr Q;
  if (node["euler"]) {
    expect_keys(node, {"euler", "angles"}, "an Euler-angle rotation");
    const auto set = EulerSet::parse(scalar(node["euler"], "euler"));
    if (!set) fail(node["euler"], "expected an Euler-angle set I-J-K such as 3-1-3 or 3-2-1");
    const YAML::Node& angles = node["angles"];
    if (!angles || !angles.IsSequence() || angles.size() != 3) {
      fail(node, "an Euler-angle rotation needs angles: [a, b, c]");
    }
    Q = euler_rotation_expr(*set, scalar_expr(angles[0], scope, "an angle"),
                            scalar_expr(angles[1], scope, "an angle"),
                            scalar_expr(angles[2], scope, "an angle"));
  } else if (node["axis"]) {
    expect_keys(node, {"axis", "angle"}, "an axis-angle rotation");
    if (!node["angle"]) fail(node, "an axis-angle rotation needs angle:");
    const VectorExpr axis = vector_expr(node["axis"], scope, "axis");
    // |axis|² simplified: [sin(lam), 0, -cos(lam)] is a unit axis, not one over √(sin² + cos²)
    const Expr length_squared = simplify(dot(axis, axis));
    if (length_squared.is_zero()) {
      fail(node["axis"], "the axis of a rotation must not be the zero vector");
    }
    Q = axis_angle_rotation_expr(axis / GiNaC::sqrt(length_squared),
                                 scalar_expr(node["angle"], scope, "angle"));
  } else if (node["quaternion"]) {
    expect_keys(node, {"quaternion"}, "a quaternion rotation");
    const YAML::Node& e = node["quaternion"];
    if (!e.IsSequence() || e.size() != 4) fail(e, "quaternion: takes [e0, e1, e2, e3]");
    Q = euler_parameter_rotation_expr(
        scalar_expr(e[0], scope, "e0"),
        {scalar_expr(e[1], scope, "e1"), scalar_expr(e[2], scope, "e2"),
         scalar_expr(e[3], scope, "e3")});
  } else {
    fail(node,
         "a rotation is {euler: I-J-K, angles: [..]}, {axis: [..], angle: ..}, "
         "{quaternion: [e0, e1, e2, e3]} or a list of these");
  }
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) expect_state_only(node, Q(i, k), system, "a rotation");
  }
  return Q;
}

// The chart of {euler: I-J-K, angles: [a, b, c]} when a, b, c are coordinates.
std::optional<EulerChart> ModelReader::euler_chart(const YAML::Node& node, const System& system) {
  if (!node.IsMap() || !node["euler"] || !node["angles"] || !node["angles"].IsSequence()) return {};
  EulerChart chart{*EulerSet::parse(node["euler"].Scalar()), {}};
  for (std::size_t i = 0; i < 3; ++i) {
    const auto q = system.find_coordinate(node["angles"][i].Scalar());
    if (!q) return {};
    chart.coordinates[i] = *q;
  }
  return chart;
}

// {quaternion: [e0, e1, e2, e3]} of four coordinates, alone or a factor of a product: unidyn keeps
// e0² + e · e = 1 itself, as a position constraint named <body>_unit (<body>_unit2, ... for more
// quaternions in one product; its multiplier does no work).
void ModelReader::add_unit_norm_constraint(const YAML::Node& node, const std::string& body,
                                           System& system) {
  if (node.IsSequence()) {
    for (const auto& factor : node) add_unit_norm_constraint(factor, body, system);
    return;
  }
  if (!node.IsMap() || !node["quaternion"]) return;
  std::vector<std::size_t> parameters;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto q = system.find_coordinate(node["quaternion"][i].Scalar());
    if (!q) return;  // the parameters are expressions: their norm is the model's business
    parameters.push_back(*q);
  }
  add_unit_norm_constraint(parameters, body, at(node), system);
}

void ModelReader::add_unit_norm_constraint(const std::vector<std::size_t>& parameters,
                                           const std::string& body, const SourcePosition& where,
                                           System& system) {
  Expr norm_squared = 0;
  for (const std::size_t q : parameters)
    norm_squared += GiNaC::pow(system.coordinates()[q].value, 2);
  std::string name = body + "_unit";
  for (int k = 2; std::any_of(system.constraints.begin(), system.constraints.end(),
                              [&](const Constraint& c) { return c.name == name; });
       ++k) {
    name = body + "_unit" + std::to_string(k);
  }
  system.constraints.push_back(
      {name,
       Constraint::Kind::position,
       norm_squared - 1,
       GiNaC::realsymbol("lambda(" + name + ")", "\\lambda_{\\mathrm{" + name + "}}"),
       false,
       std::nullopt,
       where,
       name,
       {},
       true,
       0,
       {}});
}

// definitions: name: expression, in order; each may use the parameters, coordinates, particles,
// bodies and the definitions before it, and every expression read after it may use it.
void ModelReader::read_definitions(const YAML::Node& node, System& system) {
  expect_map(node, "definitions");
  expect_unique_keys(node);
  for (const auto& item : node) {
    const std::string name = new_name(item.first, system, "definition");
    const SystemScope scope(system);
    const Value value = item.second.IsSequence() ? Value::of(vector_expr(item.second, scope, name))
                                                 : any_expr(item.second, scope, name);
    Definition definition{name, value.is_vector(), 0, {}, at(item.first)};
    if (value.is_vector()) {
      definition.vector = value.vector;
    } else {
      definition.scalar = value.scalar;
    }
    system.definitions.push_back(std::move(definition));
  }
}

}  // namespace unidyn::model_reading
