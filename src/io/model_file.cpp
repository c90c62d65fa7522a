// The YAML model reader.
//
// Sections, in the order they may refer to each other: parameters → coordinates → particles →
// forces → constraints → initial → simulate → outputs → conserved.
#include "unidyn/io/model_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string_view>
#include <type_traits>

#include "unidyn/equations/newton.hpp"
#include "unidyn/kinematics/constraint_gradient.hpp"
#include "unidyn/kinematics/inertia.hpp"
#include "unidyn/model/forces.hpp"
#include "unidyn/model/joints.hpp"
#include "unidyn/model/scope.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/expression_parser.hpp"
#include "unidyn/symbolic/printable_text.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// Outputs may also name constraint forces: P.constraint_force = m a − F and B.constraint_force =
// m ā − F, B.constraint_moment = Ḣ − M (the resultants on a particle or body, §4.4, §8.6), and
// c.force.N = Σ λ ∂Ψ/∂r_N or Σ λ f_N, c.moment.N = Σ λ h_N (8.22): the force (moment about the
// centre of mass) of constraint c — or of all rows of joint c — on the particle or body N.
class OutputScope : public SystemScope {
 public:
  explicit OutputScope(const System& system) : SystemScope(system), system_(system) {}

  std::optional<Value> lookup(std::string_view name) const override {
    if (auto value = SystemScope::lookup(name)) return value;
    const std::string key(name);
    const std::size_t dot = key.find('.');
    if (dot == std::string::npos) return std::nullopt;
    const std::string owner = key.substr(0, dot), member = key.substr(dot + 1);
    if (const auto p = system_.find_particle(owner); p && member == "constraint_force") {
      VectorExpr R = system_.particles[*p].mass * system_.acceleration(*p);
      for (const auto& element : system_.forces) {
        for (const auto& [particle, F] : element.forces) {
          if (particle == *p) R = R - F;
        }
      }
      return Value::of(R);
    }
    if (const auto b = system_.find_body(owner)) {
      if (member != "constraint_force" && member != "constraint_moment") return std::nullopt;
      const BodyBalance balance = newton_equations(system_).bodies[*b];
      return Value::of(member == "constraint_force" ? balance.constraint_force()
                                                    : balance.constraint_moment());
    }
    return constraint_load(owner, member);
  }

  std::vector<std::string> names() const override {
    std::vector<std::string> all = SystemScope::names();
    for (const auto& p : system_.particles) all.push_back(p.name + ".constraint_force");
    for (const auto& b : system_.bodies) {
      all.push_back(b.name + ".constraint_force");
      all.push_back(b.name + ".constraint_moment");
    }
    std::set<std::string> joints;
    for (const auto& c : system_.constraints) {
      joints.insert(c.name);
      joints.insert(c.joint);
    }
    for (const auto& j : joints) {
      for (const auto& p : system_.particles) all.push_back(j + ".force." + p.name);
      for (const auto& b : system_.bodies) {
        all.push_back(j + ".force." + b.name);
        all.push_back(j + ".moment." + b.name);
      }
    }
    return all;
  }

 private:
  // c.force.N or c.moment.N summed over the rows of c
  std::optional<Value> constraint_load(const std::string& owner, const std::string& member) const {
    const bool force = member.starts_with("force."), moment = member.starts_with("moment.");
    if (!force && !moment) return std::nullopt;
    const std::string target = member.substr(force ? 6 : 7);
    const auto p = system_.find_particle(target);
    const auto b = system_.find_body(target);
    if (!b && (!p || moment)) return std::nullopt;
    VectorExpr sum;
    bool found = false;
    for (std::size_t k = 0; k < system_.constraints.size(); ++k) {
      const Constraint& c = system_.constraints[k];
      if (c.name != owner && c.joint != owner) continue;
      found = true;
      const ConstraintLoads loads = constraint_loads(system_, k);
      const VectorExpr& v =
          p ? loads.particle_force[*p] : (force ? loads.body_force[*b] : loads.body_moment[*b]);
      sum = sum + Expr(c.multiplier) * v;
    }
    if (!found) return std::nullopt;
    return Value::of(sum);
  }

  const System& system_;
};

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

class ModelReader {
 public:
  ModelReader(std::string file, std::string_view source)
      : file_(std::move(file)), source_(source) {}

  System read(const YAML::Node& root);

 private:
  // Position of a node (of its tag, anchor or quote, if it has one).
  SourcePosition at(const YAML::Node& node) const {
    const YAML::Mark mark = node.Mark();
    return {file_, mark.line + 1, mark.column + 1};
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
    expect_unique_keys(node);
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

  // YAML keeps only one of two equal keys: the other would be silently lost.
  void expect_unique_keys(const YAML::Node& node) const {
    std::set<std::string> seen;
    for (const auto& item : node) {
      if (item.first.IsScalar() && !seen.insert(item.first.Scalar()).second) {
        fail(item.first, "'" + item.first.Scalar() + "' is given twice");
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

  // The text of a scalar as the expression parser should read it, and where it starts.
  struct ScalarText {
    std::string text;
    SourcePosition where;
  };
  ScalarText scalar_text(const YAML::Node& node, const std::string& what) const;

  Expr scalar_expr(const YAML::Node& node, const Scope& scope, const std::string& what) const {
    const ScalarText s = scalar_text(node, what);
    return within_budget(parse_scalar(s.text, scope, s.where), s.where);
  }

  // Notes the expression with the largest power of a sum (named when an expansion of the
  // derivation exceeds its budget).
  template <typename E>
  const E& within_budget(const E& e, const SourcePosition& where) const {
    double terms = 0;
    if constexpr (std::is_same_v<E, VectorExpr>) {
      for (int i = 0; i < 3; ++i) terms = std::max(terms, largest_power_terms(e[i]));
    } else {
      terms = largest_power_terms(e);
    }
    if (terms > largest_terms_) {
      largest_terms_ = terms;
      largest_at_ = where;
    }
    return e;
  }

  // Refuses an expression that depends on the rates der(q) (unless `rates` allows them), on the
  // accelerations (P.acceleration) or on a multiplier c.lambda: only outputs may.
  void expect_state_only(const YAML::Node& node, const Expr& e, const System& system,
                         const std::string& what, bool rates = false) const {
    for (const auto& q : system.coordinates()) {
      if (!rates && e.has(q.rate)) fail(node, what + " cannot depend on der(" + q.name + ")");
      if (e.has(q.acceleration)) fail(node, what + " cannot depend on accelerations");
    }
    for (const auto& c : system.constraints) {
      if (e.has(c.multiplier)) fail(node, what + " cannot depend on " + c.name + ".lambda");
    }
  }
  void expect_state_only(const YAML::Node& node, const VectorExpr& v, const System& system,
                         const std::string& what, bool rates = false) const {
    for (int i = 0; i < 3; ++i) expect_state_only(node, v[i], system, what, rates);
  }

  // A vector: a YAML list of three scalars, or one vector expression.
  VectorExpr vector_expr(const YAML::Node& node, const Scope& scope,
                         const std::string& what) const {
    if (node.IsSequence()) {
      if (node.size() != 3) fail(node, what + " must have three components [x, y, z]");
      return {scalar_expr(node[0], scope, what), scalar_expr(node[1], scope, what),
              scalar_expr(node[2], scope, what)};
    }
    const ScalarText s = scalar_text(node, what);
    return within_budget(parse_vector(s.text, scope, s.where), s.where);
  }

  // A name of free text that reaches the terminal (and, for a CSV column, a spreadsheet).
  std::string printable_name(const YAML::Node& node, const std::string& what, bool csv_column) {
    const std::string name = scalar(node, what);
    if (const std::string why = unprintable_name_reason(name, csv_column); !why.empty()) {
      fail(node, what + " '" + name + "' " + why);
    }
    return name;
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
    if (system.find_parameter(name) || system.find_coordinate(name) || system.find_particle(name) ||
        system.find_body(name)) {
      fail(node, "'" + name + "' is already defined");
    }
    return name;
  }

  void read_parameters(const YAML::Node& node, System& system);
  void read_coordinates(const YAML::Node& node, System& system);
  void read_particles(const YAML::Node& node, System& system);
  void read_bodies(const YAML::Node& node, System& system);
  TensorExpr rotation(const YAML::Node& node, const System& system);
  std::optional<EulerChart> euler_chart(const YAML::Node& node, const System& system);
  void add_unit_norm_constraint(const YAML::Node& node, const std::string& body, System& system);
  GiNaC::matrix inertia(const YAML::Node& node, const System& system);
  void read_forces(const YAML::Node& node, System& system);
  ForcePoint force_point(const YAML::Node& node, const System& system, const Scope& scope);
  void read_constraints(const YAML::Node& node, System& system);
  void read_joint(const YAML::Node& spec, const std::string& name, System& system);
  void read_rolling(const YAML::Node& spec, const std::string& name, System& system);
  void read_initial(const YAML::Node& node, System& system);
  void read_simulate(const YAML::Node& node, System& system);
  std::vector<Output> read_outputs(const YAML::Node& node, const System& system,
                                   const std::string& what);
  void read_stop_when(const YAML::Node& node, System& system);

  std::string file_;
  std::string_view source_;
  std::set<std::string> columns_;  // names of the CSV columns taken so far
  Expr shape_mass_;                // the mass of the body whose inertia is being read
  // the expression read so far with the largest expansion, and where
  mutable double largest_terms_ = 0;
  mutable SourcePosition largest_at_;
};

// YAML puts tags, anchors, quotes or a block header before a scalar's value, and folds and
// unindents values over several lines, so the value's characters are not where the node's mark
// is. The file from the mark on is matched against the value (a run of whitespace matching a run
// of whitespace); when it matches, that slice of the file is what the parser reads: the same
// tokens, at their own lines and columns. When it does not (escape sequences), the value is read
// as if it started right after the quote.
ModelReader::ScalarText ModelReader::scalar_text(const YAML::Node& node,
                                                 const std::string& what) const {
  std::string value = scalar(node, what);
  const YAML::Mark mark = node.Mark();
  const std::string_view src = source_;
  if (mark.pos < 0 || static_cast<std::size_t>(mark.pos) > src.size()) return {value, at(node)};
  const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; };
  const auto flow = [](char c) { return c == ',' || c == '[' || c == ']' || c == '{' || c == '}'; };
  const auto start = static_cast<std::size_t>(mark.pos);
  std::size_t i = start;
  while (i < src.size() && (src[i] == '!' || src[i] == '&')) {  // tags and anchors
    while (i < src.size() && !space(src[i]) && !flow(src[i])) ++i;
    while (i < src.size() && space(src[i])) ++i;
  }
  if (i < src.size() && (src[i] == '"' || src[i] == '\'')) {
    ++i;
  } else if (i < src.size() && (src[i] == '|' || src[i] == '>')) {
    while (i < src.size() && src[i] != '\n') ++i;  // the block header
  }
  if (!value.empty() && !space(value[0])) {
    while (i < src.size() && space(src[i])) ++i;
  }
  const std::size_t begin = i;
  bool same = true;
  for (std::size_t k = 0; same && k < value.size(); ++k) {
    if (space(value[k])) {
      same = i < src.size() && space(src[i]);
      while (k + 1 < value.size() && space(value[k + 1])) ++k;
      while (i < src.size() && space(src[i])) ++i;
    } else {
      same = i < src.size() && src[i] == value[k];
      ++i;
    }
  }
  // where `begin` is; columns count characters, as the parser's do
  int line = mark.line + 1, column = mark.column + 1;
  for (std::size_t k = start; k < begin; ++k) {
    if (src[k] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(src[k]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  if (same && i - begin <= ExpressionLimits::max_length) value = src.substr(begin, i - begin);
  return {std::move(value), {file_, line, column}};
}

System ModelReader::read(const YAML::Node& root) {
  if (!root.IsDefined() || root.IsNull())
    throw ModelError({file_, 1, 1}, "the model file is empty");
  expect_map(root, "a model file");
  expect_keys(root,
              {"unidyn", "name", "description", "reference", "parameters", "coordinates",
               "particles", "bodies", "forces", "constraints", "initial", "simulate", "outputs",
               "conserved", "stop_when"},
              "the model");
  if (!root["unidyn"]) throw ModelError(at(root), "missing 'unidyn: 1' (the model format version)");
  if (scalar(root["unidyn"], "unidyn") != "1")
    fail(root["unidyn"], "unsupported format version: expected 'unidyn: 1'");

  System system;
  system.source = file_;
  system.name = root["name"] ? printable_name(root["name"], "the model's name", false) : file_;
  if (root["parameters"]) read_parameters(root["parameters"], system);
  if (!root["coordinates"]) throw ModelError(at(root), "missing 'coordinates:' (a list of names)");
  read_coordinates(root["coordinates"], system);
  if (root["particles"]) read_particles(root["particles"], system);
  if (root["bodies"]) read_bodies(root["bodies"], system);
  if (system.particles.empty() && system.bodies.empty()) {
    throw ModelError(at(root), "the model has no particles and no bodies");
  }
  if (root["forces"]) read_forces(root["forces"], system);
  if (root["constraints"]) read_constraints(root["constraints"], system);
  system.initial_values.assign(system.coordinates().size(), 0);
  system.initial_rates.assign(system.coordinates().size(), 0);
  if (root["initial"]) read_initial(root["initial"], system);
  if (root["simulate"]) read_simulate(root["simulate"], system);
  columns_ = {"t", "energy"};
  for (const auto& q : system.coordinates()) columns_.insert({q.name, "der(" + q.name + ")"});
  for (const auto& c : system.constraints) columns_.insert("lambda(" + c.name + ")");
  if (root["outputs"]) system.outputs = read_outputs(root["outputs"], system, "outputs");
  if (root["conserved"]) system.conserved = read_outputs(root["conserved"], system, "conserved");
  if (root["stop_when"]) read_stop_when(root["stop_when"], system);
  system.largest_expression = largest_at_;
  system.largest_expression_terms = largest_terms_;
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
    expect_state_only(spec["mass"], mass, system, "a mass");
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
    expect_keys(spec, {"mass", "inertia", "rotation", "center"}, "body '" + name + "'");
    if (!spec["mass"] || !spec["inertia"] || !spec["rotation"] || !spec["center"]) {
      fail(spec, "body '" + name + "' needs mass:, inertia:, rotation: and center:");
    }
    const SystemScope scope(system);
    const Expr mass = scalar_expr(spec["mass"], scope, "mass");
    expect_state_only(spec["mass"], mass, system, "a mass");
    shape_mass_ = mass;
    Body body{name,
              mass,
              inertia(spec["inertia"], system),
              rotation(spec["rotation"], system),
              VectorExpr{},
              at(item.first),
              euler_chart(spec["rotation"], system)};
    add_unit_norm_constraint(spec["rotation"], name, system);
    // the centre may use the body's own basis (l*top.e3): the body is known before it is read
    system.bodies.push_back(body);
    const SystemScope with_body(system);
    const VectorExpr center = vector_expr(spec["center"], with_body, "center");
    expect_state_only(spec["center"], center, system, "a centre of mass");
    system.bodies.back().center = center;
  }
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
    if (expand_within_budget(dot(axis, axis), "an axis").is_zero()) {
      fail(node["axis"], "the axis of a rotation must not be the zero vector");
    }
    Q = axis_angle_rotation_expr(axis / norm(axis), scalar_expr(node["angle"], scope, "angle"));
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

// {quaternion: [e0, e1, e2, e3]} of four coordinates: unidyn keeps e0² + e · e = 1 itself, as a
// position constraint named <body>_unit (its multiplier does no work).
void ModelReader::add_unit_norm_constraint(const YAML::Node& node, const std::string& body,
                                           System& system) {
  if (!node.IsMap() || !node["quaternion"]) return;
  Expr norm_squared = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    const auto q = system.find_coordinate(node["quaternion"][i].Scalar());
    if (!q) return;  // the parameters are expressions: their norm is the model's business
    norm_squared += GiNaC::pow(system.coordinates()[*q].value, 2);
  }
  const std::string name = body + "_unit";
  system.constraints.push_back(
      {name,
       Constraint::Kind::position,
       norm_squared - 1,
       GiNaC::realsymbol("lambda(" + name + ")", "\\lambda_{\\mathrm{" + name + "}}"),
       false,
       std::nullopt,
       at(node),
       name,
       {},
       true,
       0});
}

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

void ModelReader::read_forces(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "forces must be a list, e.g. [{gravity: -g*E3}]");
  for (const auto& entry : node) {
    if (!entry.IsMap() || entry.size() != 1) {
      fail(entry,
           "each force is one of: gravity, spring, damper, force, moment, potential, gravitation, "
           "gravity_gradient, torsion_spring");
    }
    const std::string kind = entry.begin()->first.Scalar();
    const YAML::Node spec = entry.begin()->second;  // a copy: the iterator is a temporary
    SystemScope scope(system);
    // The two ends of a spring or a damper: not one point, where its direction would be 0/0.
    const auto ends = [&]() -> std::pair<ForcePoint, ForcePoint> {
      ForcePoint from = force_point(spec["from"], system, scope);
      ForcePoint to = force_point(spec["to"], system, scope);
      const VectorExpr d = to.position - from.position;
      if (expand_within_budget(d[0], "a force").is_zero() &&
          expand_within_budget(d[1], "a force").is_zero() &&
          expand_within_budget(d[2], "a force").is_zero()) {
        fail(spec, "a " + kind + " needs two different points: from: and to: are the same");
      }
      return {std::move(from), std::move(to)};
    };
    ForceElement element;
    try {
      if (kind == "gravity") {
        const VectorExpr g = vector_expr(spec, scope, "gravity");
        expect_state_only(spec, g, system, "gravity");
        element = uniform_gravity(system, g);
      } else if (kind == "spring") {
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
        const auto [from, to] = ends();
        element = spring(from, to, rest, s, energy);
      } else if (kind == "damper") {
        expect_map(spec, "damper");
        expect_keys(spec, {"from", "to", "coefficient"}, "damper");
        if (!spec["from"] || !spec["to"] || !spec["coefficient"]) {
          fail(spec, "a damper needs from:, to: and coefficient:");
        }
        const Expr c = scalar_expr(spec["coefficient"], scope, "coefficient");
        expect_state_only(spec["coefficient"], c, system, "a damping coefficient", true);
        const auto [from, to] = ends();
        element = damper(system, from, to, c);
      } else if (kind == "force") {
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
          element = applied_force(*p, F);
        } else {
          const auto b = system.find_body(scalar(spec["on"], "on"));
          if (!b) fail(spec["on"], "on: must name a body");
          const VectorExpr X =
              spec["point"] ? vector_expr(spec["point"], scope, "point") : VectorExpr{};
          element = body_force(*b, system.material_point(*b, X), F);
        }
      } else if (kind == "moment") {
        expect_map(spec, "moment");
        expect_keys(spec, {"on", "value"}, "moment");
        if (!spec["on"] || !spec["value"]) fail(spec, "a moment needs on: (a body) and value:");
        const auto b = system.find_body(scalar(spec["on"], "on"));
        if (!b) fail(spec["on"], "on: must name a body");
        const VectorExpr M = vector_expr(spec["value"], scope, "value");
        expect_state_only(spec["value"], M, system, "a moment", true);
        element = body_moment(*b, M);
      } else if (kind == "gravity_gradient") {
        expect_map(spec, "gravity_gradient");
        expect_keys(spec, {"on", "GM", "center"}, "gravity_gradient");
        if (!spec["on"] || !spec["GM"]) {
          fail(spec,
               "gravity_gradient needs on: (a body) and GM: (center: defaults to the origin)");
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
        element = gravity_gradient(system, *b, GM, center);
      } else if (kind == "torsion_spring") {
        expect_map(spec, "torsion_spring");
        expect_keys(spec, {"on", "angle", "stiffness", "rest_angle"}, "torsion_spring");
        if (!spec["on"] || !spec["angle"] || !spec["stiffness"]) {
          fail(spec,
               "a torsion_spring needs on: (a body), angle: (one of its Euler angles) and "
               "stiffness:");
        }
        const auto b = system.find_body(scalar(spec["on"], "on"));
        if (!b) fail(spec["on"], "on: must name a body");
        const auto& chart = system.bodies[*b].chart;
        if (!chart)
          fail(spec["on"], "a torsion_spring needs a body turned by {euler: .., angles: [..]}");
        const auto q = system.find_coordinate(scalar(spec["angle"], "angle"));
        int angle = -1;
        for (int i = 0; i < 3; ++i) {
          if (q && chart->coordinates[static_cast<std::size_t>(i)] == *q) angle = i;
        }
        if (angle < 0) fail(spec["angle"], "angle: must be one of the body's Euler angles");
        const Expr K = scalar_expr(spec["stiffness"], scope, "stiffness");
        expect_state_only(spec["stiffness"], K, system, "a stiffness");
        Expr rest = 0;
        if (spec["rest_angle"]) {
          rest = scalar_expr(spec["rest_angle"], scope, "rest_angle");
          expect_state_only(spec["rest_angle"], rest, system, "a rest angle");
        }
        element = torsion_spring(system, *b, angle, K, rest);
      } else if (kind == "potential") {
        const Expr U = scalar_expr(spec, scope, "potential");
        expect_state_only(spec, U, system, "a potential U(q, t)");
        element = coordinate_potential(U);
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
        const Expr G = scalar_expr(spec["G"], scope, "G");
        expect_state_only(spec["G"], G, system, "G");
        element = gravitation(system, *p1, *p2, G);
      } else {
        fail(entry.begin()->first, "unknown force '" + kind +
                                       "' (expected gravity, spring, damper, force, moment, "
                                       "potential, gravitation, gravity_gradient or "
                                       "torsion_spring)");
      }
    } catch (const ModelError&) {
      throw;
    } catch (const YAML::Exception&) {
      throw;
    } catch (const std::exception& e) {
      // GiNaC refusing to build it, e.g. a division by zero for two particles at one fixed point
      fail(entry, "this " + kind + " cannot be built: " + e.what());
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
    expect_keys(spec,
                {"name", "position", "velocity", "ball", "pin", "rolling", "unilateral",
                 "restitution", "friction"},
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
        0};
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
        if (!c.expression.diff(q.rate, 2).is_zero()) {
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
      for (const auto& q : system.coordinates()) {
        if (c.restitution.has(q.value) || c.restitution.has(system.time())) {
          fail(spec["restitution"], "a restitution is a number or depends on parameters only");
        }
      }
    }
    if (spec["friction"]) {
      const YAML::Node& f = spec["friction"];
      expect_map(f, "friction");
      expect_keys(f, {"on", "at", "dynamic", "static", "surface_velocity"}, "friction");
      if (!f["on"] || !f["dynamic"]) {
        fail(f,
             "friction needs on: (a particle, or a body with at: its point of contact) and "
             "dynamic:");
      }
      if (c.kind != Constraint::Kind::position) {
        fail(f, "friction acts at the contact of a position constraint (a surface or curve)");
      }
      Friction friction{scalar(f["on"], "on"), scalar_expr(f["dynamic"], scope, "dynamic"), 0,
                        VectorExpr{}, VectorExpr{}};
      expect_state_only(f["dynamic"], friction.dynamic_coefficient, system, "a coefficient");
      friction.static_coefficient =
          f["static"] ? scalar_expr(f["static"], scope, "static") : friction.dynamic_coefficient;
      expect_state_only(f["static"] ? f["static"] : f, friction.static_coefficient, system,
                        "a coefficient");
      if (f["surface_velocity"]) {
        friction.surface_velocity = vector_expr(f["surface_velocity"], scope, "surface_velocity");
        expect_state_only(f["surface_velocity"], friction.surface_velocity, system,
                          "a surface velocity");
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
      c.friction = friction;
    }
    system.constraints.push_back(std::move(c));
  }
  // a rough contact needs its normal ∂Ψ/∂r_P, which needs the coordinates to fix the positions
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    if (!system.constraints[k].friction) continue;
    try {
      constraint_loads(system, k);
    } catch (const std::invalid_argument& e) {
      throw ModelError(system.constraints[k].where,
                       "friction on '" + system.constraints[k].name + "': " + e.what());
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

// rolling: {body: B, at: <its point of contact>, normal: [n1, n2, n3]}: rows name_1, name_2 that
// keep the contact from slipping on the fixed surface (model/joints.hpp).
void ModelReader::read_rolling(const YAML::Node& spec, const std::string& name, System& system) {
  const YAML::Node r = spec["rolling"];
  expect_map(r, "rolling");
  expect_keys(r, {"body", "at", "normal"}, "rolling");
  if (spec["unilateral"] || spec["friction"] || spec["restitution"]) {
    fail(spec, "rolling cannot be unilateral or carry friction (it is the no-slip condition)");
  }
  if (!r["body"] || !r["at"] || !r["normal"]) {
    fail(r, "rolling needs body:, at: (its point of contact) and normal: (the surface's, numbers)");
  }
  const auto b = system.find_body(scalar(r["body"], "body"));
  if (!b) fail(r["body"], "body: must name a body");
  const SystemScope scope(system);
  const VectorExpr contact = vector_expr(r["at"], scope, "at");
  expect_state_only(r["at"], contact, system, "a point of contact");
  const VectorExpr normal = vector_expr(r["normal"], scope, "normal");
  for (int i = 0; i < 3; ++i) {
    if (!GiNaC::is_a<GiNaC::numeric>(normal[i])) {
      fail(r["normal"], "a normal is a vector of numbers, e.g. [0, 0, 1]");
    }
  }
  if (norm(normal).is_zero()) fail(r["normal"], "a normal cannot be zero");
  for (auto& c : rolling_contact(system, name, *b, contact, normal, at(spec))) {
    if (system.find_parameter(c.name) || system.find_coordinate(c.name) ||
        system.find_particle(c.name) || system.find_body(c.name)) {
      fail(spec, "the rolling row '" + c.name + "' clashes with a name already defined");
    }
    system.constraints.push_back(std::move(c));
  }
}

void ModelReader::read_initial(const YAML::Node& node, System& system) {
  expect_map(node, "initial");
  const SystemScope scope(system);
  std::set<std::string> given;
  for (const auto& item : node) {
    std::string key = scalar(item.first, "an initial value's name");
    bool is_rate = false;
    if (key.starts_with("der(") && key.ends_with(")")) {
      key = key.substr(4, key.size() - 5);
      is_rate = true;
    }
    const auto q = system.find_coordinate(key);
    if (!q) fail(item.first, "'" + key + "' is not a coordinate");
    if (!given.insert(std::string(is_rate ? "der(" : "") + key).second) {
      fail(item.first, "'" + item.first.Scalar() + "' is given twice");
    }
    const Expr value = scalar_expr(item.second, scope, "initial value");
    // a real number once the parameters have their values (no q, der(q), t, accelerations, λ)
    const bool real = real_value(value, system.parameter_values()).has_value();
    if (!real) {
      fail(item.second, "an initial value must be a real number, from numbers and parameters only");
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
  if (s.method != "dopri5" && s.method != "rk4" && s.method != "cvode" && s.method != "rattle")
    fail(node["method"], "method must be dopri5, rk4, cvode or rattle");
  // (the integrators would refuse these only once the run has started)
  if (!(s.rtol > 0)) fail(node["rtol"], "rtol must be positive");
  if (!(s.atol > 0)) fail(node["atol"], "atol must be positive");
  if (s.step < 0) fail(node["step"], "step must not be negative (0: output_step / 10)");
}

std::vector<Output> ModelReader::read_outputs(const YAML::Node& node, const System& system,
                                              const std::string& what) {
  expect_map(node, what);
  expect_unique_keys(node);
  const OutputScope scope(system);
  std::vector<Output> outputs;
  for (const auto& item : node) {
    const std::string name = printable_name(item.first, "a name in " + what, true);
    // one CSV column each: not t, q, der(q), energy, lambda(c), nor another output's name
    if (!columns_.insert(name).second) {
      fail(item.first, "'" + name + "' is already the name of a CSV column");
    }
    outputs.push_back({name, scalar_expr(item.second, scope, name), at(item.first)});
  }
  return outputs;
}

// stop_when: [expr, ...]: functions of t, q and der(q) (and of outputs' names: accelerations,
// multipliers); the run stops when one, non-zero at the start, reaches 0.
void ModelReader::read_stop_when(const YAML::Node& node, System& system) {
  if (!node.IsSequence()) fail(node, "stop_when must be a list of expressions, e.g. [z, 2 - t]");
  const OutputScope scope(system);
  for (const auto& item : node) {
    const std::string text = scalar(item, "a stop_when expression");
    system.stop_when.push_back({text, scalar_expr(item, scope, "stop_when"), at(item)});
  }
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
    // yaml-cpp's marks do not count a byte-order mark
    std::string_view source = text;
    if (source.starts_with("\xEF\xBB\xBF")) source.remove_prefix(3);
    return ModelReader(file, source).read(root);
  } catch (const YAML::Exception& e) {
    throw ModelError({file, e.mark.line + 1, e.mark.column + 1}, e.msg);
  }
}

std::string read_model_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ModelError({path, 0, 0}, "cannot open the model file");
  std::stringstream text;
  text << in.rdbuf();
  if (in.bad()) throw ModelError({path, 0, 0}, "cannot read the model file");
  return text.str();
}

System load_model(const std::string& path) {
  return parse_model(read_model_text(path), path);
}

}  // namespace unidyn
