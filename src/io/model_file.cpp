// The YAML model reader.
//
// Sections, in the order they may refer to each other: parameters → coordinates → particles →
// forces → constraints → initial → simulate → outputs → conserved.
#include "unidyn/io/model_file.hpp"

#include <yaml-cpp/yaml.h>

#include <fstream>
#include <set>
#include <sstream>

#include "unidyn/model/forces.hpp"
#include "unidyn/model/scope.hpp"
#include "unidyn/symbolic/expression_parser.hpp"

namespace unidyn {
namespace {

class ModelReader {
 public:
  explicit ModelReader(std::string file) : file_(std::move(file)) {}

  System read(const YAML::Node& root);

 private:
  // Position of a node; the first character of a quoted scalar's text is one past its mark.
  SourcePosition at(const YAML::Node& node, bool text_start = false) const {
    const YAML::Mark mark = node.Mark();
    const int quote = (text_start && node.IsScalar() && node.Tag() == "!") ? 1 : 0;
    return {file_, mark.line + 1, mark.column + 1 + quote};
  }

  [[noreturn]] void fail(const YAML::Node& node, const std::string& message) const {
    throw ModelError(at(node), message);
  }

  void expect_map(const YAML::Node& node, const std::string& what) const {
    if (!node.IsMap()) fail(node, what + " must be a mapping (key: value)");
  }

  // Keys outside `allowed` are mistakes (a misspelt key would otherwise be silently ignored).
  void expect_keys(const YAML::Node& node, const std::set<std::string>& allowed,
                   const std::string& what) const {
    for (const auto& item : node) {
      const std::string key = item.first.Scalar();
      if (!allowed.count(key)) {
        std::string list;
        for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
        throw ModelError(at(item.first), "unknown key '" + key + "' in " + what +
                                             " (expected one of: " + list + ")");
      }
    }
  }

  std::string scalar(const YAML::Node& node, const std::string& what) const {
    if (!node.IsScalar()) fail(node, what + " must be a single value");
    return node.Scalar();
  }

  double number(const YAML::Node& node, const std::string& what) const {
    const std::string text = scalar(node, what);
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(text, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != text.size() || !std::isfinite(x)) fail(node, what + " must be a number");
    return x;
  }

  Expr scalar_expr(const YAML::Node& node, const Scope& scope, const std::string& what) const {
    return parse_scalar(scalar(node, what), scope, at(node, true));
  }

  // A vector: a YAML list of three scalars, or one vector expression.
  VectorExpr vector_expr(const YAML::Node& node, const Scope& scope,
                         const std::string& what) const {
    if (node.IsSequence()) {
      if (node.size() != 3) fail(node, what + " must have three components [x, y, z]");
      return {scalar_expr(node[0], scope, what), scalar_expr(node[1], scope, what),
              scalar_expr(node[2], scope, what)};
    }
    return parse_vector(scalar(node, what), scope, at(node, true));
  }

  // A name that must not clash with another or with a reserved word.
  std::string new_name(const YAML::Node& node, const System& system, const std::string& what) {
    const std::string name = scalar(node, what);
    static const std::set<std::string> reserved = {
        "t",    "pi",   "E1",   "E2",    "E3",    "der",  "sin",   "cos", "tan",
        "asin", "acos", "atan", "atan2", "sinh",  "cosh", "tanh",  "exp", "log",
        "sqrt", "abs",  "sign", "dot",   "cross", "norm", "lambda"};
    bool valid =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char c : name) valid = valid && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!valid) fail(node, what + " '" + name + "' is not a valid name (letters, digits, _)");
    if (reserved.count(name)) fail(node, what + " '" + name + "' is a reserved word");
    if (system.find_parameter(name) || system.find_coordinate(name) || system.find_particle(name)) {
      fail(node, "'" + name + "' is already defined");
    }
    return name;
  }

  void read_parameters(const YAML::Node& node, System& system);
  void read_coordinates(const YAML::Node& node, System& system);
  void read_particles(const YAML::Node& node, System& system);
  void read_forces(const YAML::Node& node, System& system);
  ForcePoint force_point(const YAML::Node& node, const System& system, const Scope& scope);
  void read_constraints(const YAML::Node& node, System& system);
  void read_initial(const YAML::Node& node, System& system);
  void read_simulate(const YAML::Node& node, System& system);
  std::vector<Output> read_outputs(const YAML::Node& node, const System& system,
                                   const std::string& what);

  std::string file_;
};

System ModelReader::read(const YAML::Node& root) {
  if (!root.IsDefined() || root.IsNull())
    throw ModelError({file_, 1, 1}, "the model file is empty");
  expect_map(root, "a model file");
  expect_keys(root,
              {"unidyn", "name", "description", "reference", "parameters", "coordinates",
               "particles", "forces", "constraints", "initial", "simulate", "outputs", "conserved"},
              "the model");
  if (!root["unidyn"]) throw ModelError(at(root), "missing 'unidyn: 1' (the model format version)");
  if (scalar(root["unidyn"], "unidyn") != "1")
    fail(root["unidyn"], "unsupported format version: expected 'unidyn: 1'");

  System system;
  system.source = file_;
  system.name = root["name"] ? scalar(root["name"], "name") : file_;
  if (root["parameters"]) read_parameters(root["parameters"], system);
  if (!root["coordinates"]) throw ModelError(at(root), "missing 'coordinates:' (a list of names)");
  read_coordinates(root["coordinates"], system);
  if (root["particles"]) read_particles(root["particles"], system);
  if (system.particles.empty()) throw ModelError(at(root), "the model has no particles");
  if (root["forces"]) read_forces(root["forces"], system);
  if (root["constraints"]) read_constraints(root["constraints"], system);
  system.initial_values.assign(system.coordinates().size(), 0);
  system.initial_rates.assign(system.coordinates().size(), 0);
  if (root["initial"]) read_initial(root["initial"], system);
  if (root["simulate"]) read_simulate(root["simulate"], system);
  if (root["outputs"]) system.outputs = read_outputs(root["outputs"], system, "outputs");
  if (root["conserved"]) system.conserved = read_outputs(root["conserved"], system, "conserved");
  return system;
}

void ModelReader::read_parameters(const YAML::Node& node, System& system) {
  expect_map(node, "parameters");
  for (const auto& item : node) {
    const std::string name = new_name(item.first, system, "parameter");
    const double value = number(item.second, "parameter '" + name + "'");
    system.parameters.push_back({name, GiNaC::realsymbol(name), value, at(item.first)});
  }
}

void ModelReader::read_coordinates(const YAML::Node& node, System& system) {
  if (!node.IsSequence() || node.size() == 0)
    fail(node, "coordinates must be a list of names, e.g. [x, y]");
  for (const auto& item : node) system.configuration.add(new_name(item, system, "coordinate"));
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
    const VectorExpr position = vector_expr(spec["position"], scope, "position");
    system.particles.push_back({name, mass, position, at(item.first)});
  }
}

ForcePoint ModelReader::force_point(const YAML::Node& node, const System& system,
                                    const Scope& scope) {
  if (node.IsScalar()) {
    if (const auto p = system.find_particle(node.Scalar())) {
      return {p, system.particles[*p].position};
    }
  }
  return {std::nullopt, vector_expr(node, scope, "a point (a particle name or a vector)")};
}

void ModelReader::read_forces(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "forces must be a list, e.g. [{gravity: -g*E3}]");
  for (const auto& entry : node) {
    if (!entry.IsMap() || entry.size() != 1) {
      fail(entry, "each force is one of: gravity, spring, damper, force, potential, gravitation");
    }
    const std::string kind = entry.begin()->first.Scalar();
    const YAML::Node& spec = entry.begin()->second;
    SystemScope scope(system);
    ForceElement element;
    if (kind == "gravity") {
      element = uniform_gravity(system, vector_expr(spec, scope, "gravity"));
    } else if (kind == "spring") {
      expect_map(spec, "spring");
      expect_keys(spec, {"from", "to", "stiffness", "rest_length", "energy"}, "spring");
      if (!spec["from"] || !spec["to"]) fail(spec, "a spring needs from: and to:");
      if (!!spec["stiffness"] == !!spec["energy"]) {
        fail(spec, "a spring needs either stiffness: K or energy: U(s) of its stretch s");
      }
      const GiNaC::realsymbol s("s");
      const Expr rest =
          spec["rest_length"] ? scalar_expr(spec["rest_length"], scope, "rest_length") : Expr(0);
      Expr energy;
      if (spec["stiffness"]) {
        energy = scalar_expr(spec["stiffness"], scope, "stiffness") * GiNaC::pow(s, 2) / 2;
      } else {
        SystemScope with_stretch(system);
        with_stretch.define("s", Value::of(s));
        energy = scalar_expr(spec["energy"], with_stretch, "energy");
      }
      element = spring(force_point(spec["from"], system, scope),
                       force_point(spec["to"], system, scope), rest, s, energy);
    } else if (kind == "damper") {
      expect_map(spec, "damper");
      expect_keys(spec, {"from", "to", "coefficient"}, "damper");
      if (!spec["from"] || !spec["to"] || !spec["coefficient"]) {
        fail(spec, "a damper needs from:, to: and coefficient:");
      }
      element = damper(system, force_point(spec["from"], system, scope),
                       force_point(spec["to"], system, scope),
                       scalar_expr(spec["coefficient"], scope, "coefficient"));
    } else if (kind == "force") {
      expect_map(spec, "force");
      expect_keys(spec, {"at", "value"}, "force");
      if (!spec["at"] || !spec["value"]) fail(spec, "a force needs at: (a particle) and value:");
      const auto p = system.find_particle(scalar(spec["at"], "at"));
      if (!p) fail(spec["at"], "at: must name a particle");
      element = applied_force(*p, vector_expr(spec["value"], scope, "value"));
    } else if (kind == "potential") {
      element = coordinate_potential(scalar_expr(spec, scope, "potential"));
    } else if (kind == "gravitation") {
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
      element = gravitation(system, *p1, *p2, scalar_expr(spec["G"], scope, "G"));
    } else {
      fail(entry.begin()->first, "unknown force '" + kind +
                                     "' (expected gravity, spring, damper, force, potential or "
                                     "gravitation)");
    }
    element.where = at(entry);
    system.forces.push_back(std::move(element));
  }
}

void ModelReader::read_constraints(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "constraints must be a list");
  const SystemScope scope(system);
  std::set<std::string> names;
  for (const auto& spec : node) {
    expect_map(spec, "a constraint");
    expect_keys(spec, {"name", "position", "velocity", "unilateral", "friction"}, "a constraint");
    if (!!spec["position"] == !!spec["velocity"]) {
      fail(spec,
           "a constraint needs exactly one of position: Ψ(q, t) or velocity: (linear in der(q))");
    }
    const std::string name = spec["name"] ? scalar(spec["name"], "name")
                                          : "c" + std::to_string(system.constraints.size() + 1);
    Constraint c{
        name,    Constraint::Kind::position,
        0,       GiNaC::realsymbol("lambda(" + name + ")", "\\lambda_{\\mathrm{" + name + "}}"),
        false,   std::nullopt,
        at(spec)};
    if (!names.insert(c.name).second || system.find_particle(c.name)) {
      fail(spec["name"], "'" + c.name + "' is already defined");
    }
    if (spec["position"]) {
      c.kind = Constraint::Kind::position;
      c.expression = scalar_expr(spec["position"], scope, "position");
      for (const auto& q : system.coordinates()) {
        if (c.expression.has(q.rate))
          fail(spec["position"],
               "a position constraint cannot depend on der(" + q.name + "); use velocity:");
      }
    } else {
      c.kind = Constraint::Kind::velocity;
      c.expression = scalar_expr(spec["velocity"], scope, "velocity");
      for (const auto& q : system.coordinates()) {
        if (!c.expression.diff(q.rate, 2).is_zero()) {
          fail(spec["velocity"],
               "a velocity constraint must be linear in the rates; it is not in der(" + q.name +
                   ")");
        }
      }
    }
    if (spec["unilateral"]) c.unilateral = scalar(spec["unilateral"], "unilateral") == "true";
    if (spec["friction"]) {
      const YAML::Node& f = spec["friction"];
      expect_map(f, "friction");
      expect_keys(f, {"on", "dynamic", "static"}, "friction");
      if (!f["on"] || !f["dynamic"]) fail(f, "friction needs on: (a particle) and dynamic:");
      Friction friction{scalar(f["on"], "on"), scalar_expr(f["dynamic"], scope, "dynamic"), 0};
      friction.static_coefficient =
          f["static"] ? scalar_expr(f["static"], scope, "static") : friction.dynamic_coefficient;
      if (!system.find_particle(friction.on)) fail(f["on"], "on: must name a particle");
      c.friction = friction;
    }
    system.constraints.push_back(std::move(c));
  }
}

void ModelReader::read_initial(const YAML::Node& node, System& system) {
  expect_map(node, "initial");
  const SystemScope scope(system);
  for (const auto& item : node) {
    std::string key = scalar(item.first, "an initial value's name");
    bool is_rate = false;
    if (key.starts_with("der(") && key.ends_with(")")) {
      key = key.substr(4, key.size() - 5);
      is_rate = true;
    }
    const auto q = system.find_coordinate(key);
    if (!q) fail(item.first, "'" + key + "' is not a coordinate");
    const Expr value = scalar_expr(item.second, scope, "initial value");
    for (const auto& c : system.coordinates()) {
      if (value.has(c.value) || value.has(c.rate) || value.has(system.time())) {
        fail(item.second, "an initial value may use numbers and parameters only");
      }
    }
    (is_rate ? system.initial_rates : system.initial_values)[*q] = value;
  }
}

void ModelReader::read_simulate(const YAML::Node& node, System& system) {
  expect_map(node, "simulate");
  expect_keys(node, {"t_end", "output_step", "method", "rtol", "atol", "step"}, "simulate");
  SimulationSettings& s = system.simulate;
  if (node["t_end"]) s.t_end = number(node["t_end"], "t_end");
  if (node["output_step"]) s.output_step = number(node["output_step"], "output_step");
  if (node["method"]) s.method = scalar(node["method"], "method");
  if (node["rtol"]) s.rtol = number(node["rtol"], "rtol");
  if (node["atol"]) s.atol = number(node["atol"], "atol");
  if (node["step"]) s.step = number(node["step"], "step");
  if (!(s.t_end > 0)) fail(node["t_end"], "t_end must be positive");
  if (!(s.output_step > 0)) fail(node["output_step"], "output_step must be positive");
  if (s.method != "dopri5" && s.method != "rk4")
    fail(node["method"], "method must be dopri5 or rk4");
}

std::vector<Output> ModelReader::read_outputs(const YAML::Node& node, const System& system,
                                              const std::string& what) {
  expect_map(node, what);
  const SystemScope scope(system);
  std::vector<Output> outputs;
  for (const auto& item : node) {
    const std::string name = scalar(item.first, "a name");
    outputs.push_back({name, scalar_expr(item.second, scope, name), at(item.first)});
  }
  return outputs;
}

}  // namespace

System parse_model(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, "YAML syntax: " + e.msg);
  }
  try {
    return ModelReader(file).read(root);
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, e.msg);
  }
}

System load_model(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ModelError({path, 0, 0}, "cannot open the model file");
  std::stringstream text;
  text << in.rdbuf();
  return parse_model(text.str(), path);
}

}  // namespace unidyn
