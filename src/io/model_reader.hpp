// The model-file reader, shared by the files that read its sections (model_file.cpp: the file and
// its order; model_bodies.cpp: parameters, coordinates, particles, bodies; model_forces.cpp;
// model_constraints.cpp; model_run.cpp: initial state, simulate, outputs, stop_when). Private to
// the io layer.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
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
#include "unidyn/symbolic/symbols_in.hpp"

namespace unidyn::model_reading {

// Reads one model file: the helpers every section uses (positions, keys, scalars, expressions,
// names), and one member per section. Every mistake throws ModelError at its position.
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
                                             " (expected one of: " + list + ")" +
                                             (unbalanced(key) ? kCommaHint : ""));
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

  // The value of a scalar that is a plain decimal number, as std::stod reads it; else nothing.
  std::optional<double> plain_number(const YAML::Node& node) const {
    if (!node.IsScalar()) return std::nullopt;
    const std::string& text = node.Scalar();
    std::size_t used = 0;
    double x = 0;
    try {
      x = std::stod(text, &used);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (used != text.size() || !std::isfinite(x)) return std::nullopt;
    return x;
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
    return within_budget(hint_commas(s, [&] { return parse_scalar(s.text, scope, s.where); }),
                         s.where);
  }

  // A scalar or a vector, whichever the expression is.
  Value any_expr(const YAML::Node& node, const Scope& scope, const std::string& what) const {
    const ScalarText s = scalar_text(node, what);
    Value value = hint_commas(s, [&] { return parse_expression(s.text, scope, s.where); });
    if (value.is_vector()) {
      within_budget(value.vector, s.where);
    } else {
      within_budget(value.scalar, s.where);
    }
    return value;
  }

  // A YAML flow collection ({..} or [..]) splits an unquoted expression at its commas, leaving
  // unbalanced brackets: say so when such a piece does not parse.
  static bool unbalanced(std::string_view text) {
    int round = 0, square = 0;
    for (const char c : text) {
      round += c == '(' ? 1 : c == ')' ? -1 : 0;
      square += c == '[' ? 1 : c == ']' ? -1 : 0;
    }
    return round != 0 || square != 0;
  }
  static constexpr const char* kCommaHint =
      " (YAML's {..} and [..] split a value at its commas: quote an expression that contains "
      "one, e.g. \"dot(P.position, E3)\")";
  template <typename Parse>
  static auto hint_commas(const ScalarText& s, Parse parse) -> decltype(parse()) {
    try {
      return parse();
    } catch (const ModelError& e) {
      if (!unbalanced(s.text)) throw;
      throw ModelError(e.where(), e.message() + kCommaHint);
    }
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
    const SymbolsIn symbols(e);
    for (const auto& q : system.coordinates()) {
      if (!rates && symbols.has(q.rate)) {
        fail(node, what + " cannot depend on der(" + q.name + ")");
      }
      if (symbols.has(q.acceleration)) fail(node, what + " cannot depend on accelerations");
    }
    for (const auto& c : system.constraints) {
      if (symbols.has(c.multiplier)) fail(node, what + " cannot depend on " + c.name + ".lambda");
    }
  }
  // Refuses an expression of the coordinates, their rates or t: numbers and parameters only.
  void expect_parameters_only(const YAML::Node& node, const Expr& e, const System& system,
                              const std::string& message) const {
    bool constant = !e.has(system.time());
    for (const auto& q : system.coordinates())
      constant = constant && !e.has(q.value) && !e.has(q.rate);
    if (!constant) fail(node, message);
  }
  void expect_state_only(const YAML::Node& node, const VectorExpr& v, const System& system,
                         const std::string& what, bool rates = false) const {
    for (int i = 0; i < 3; ++i) expect_state_only(node, v[i], system, what, rates);
  }

  // A vector: a YAML list of three scalars, or one vector expression.
  VectorExpr vector_expr(const YAML::Node& node, const Scope& scope,
                         const std::string& what) const {
    if (node.IsSequence()) {
      if (node.size() != 3) {
        bool split = false;
        for (const auto& element : node)
          split = split || (element.IsScalar() && unbalanced(element.Scalar()));
        fail(node, what + " must have three components [x, y, z]" + (split ? kCommaHint : ""));
      }
      return {scalar_expr(node[0], scope, what), scalar_expr(node[1], scope, what),
              scalar_expr(node[2], scope, what)};
    }
    const ScalarText s = scalar_text(node, what);
    return within_budget(hint_commas(s, [&] { return parse_vector(s.text, scope, s.where); }),
                         s.where);
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
        "t",   "pi",   "deg",  "E1",   "E2",    "E3",    "der",  "sin",   "cos",
        "tan", "asin", "acos", "atan", "atan2", "sinh",  "cosh", "tanh",  "exp",
        "log", "sqrt", "abs",  "sign", "dot",   "cross", "norm", "lambda"};
    bool valid =
        !name.empty() && (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
    for (char c : name) valid = valid && (std::isalnum(static_cast<unsigned char>(c)) || c == '_');
    if (!valid) fail(node, what + " '" + name + "' is not a valid name (letters, digits, _)");
    if (reserved.count(name)) fail(node, what + " '" + name + "' is a reserved word");
    if (system.find_parameter(name) || system.find_coordinate(name) || system.find_particle(name) ||
        system.find_body(name) || system.find_definition(name)) {
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
  void add_unit_norm_constraint(const std::vector<std::size_t>& parameters, const std::string& body,
                                const SourcePosition& where, System& system);
  // A body placed by `joint:` on its parent (model_tree_joints.cpp).
  void place_by_joint(const YAML::Node& node, Body& body, System& system);
  TreeJoint tree_joint(const YAML::Node& node, const System& system);
  std::vector<std::size_t> joint_coordinates(const YAML::Node& node, TreeJoint::Kind kind,
                                             const System& system);
  VectorExpr joint_axis(const YAML::Node& node, TreeJoint::Kind kind, const System& system);
  VectorExpr constant_vector(const YAML::Node& node, const System& system, const std::string& what);
  GiNaC::matrix inertia(const YAML::Node& node, const System& system);
  BodyVisual visual(const YAML::Node& node, const System& system);
  BodyVisual visual_of_inertia(const YAML::Node& node, const System& system);
  BodyVisual shape_visual(const YAML::Node& node, const std::string& shape, const System& system);
  void read_definitions(const YAML::Node& node, System& system);
  void read_forces(const YAML::Node& node, System& system);
  ForceElement read_force(const YAML::Node& entry, const System& system);
  ForceElement read_spring(const YAML::Node& spec, const System& system, const Scope& scope);
  ForceElement read_damper(const YAML::Node& spec, const System& system, const Scope& scope);
  ForceElement read_applied_force(const YAML::Node& spec, const System& system, const Scope& scope);
  ForceElement read_moment(const YAML::Node& spec, const System& system, const Scope& scope);
  ForceElement read_gravity_gradient(const YAML::Node& spec, const System& system,
                                     const Scope& scope);
  ForceElement read_slide_damper(const YAML::Node& spec, const System& system, const Scope& scope);
  ForceElement read_torsion(const std::string& kind, const YAML::Node& spec, const System& system,
                            const Scope& scope);
  ForceElement read_gravitation(const YAML::Node& spec, const System& system, const Scope& scope);
  std::pair<ForcePoint, ForcePoint> force_ends(const YAML::Node& spec, const std::string& kind,
                                               const System& system, const Scope& scope);
  ForcePoint force_point(const YAML::Node& node, const System& system, const Scope& scope);
  std::pair<std::size_t, std::vector<AngleTorque>> torsion_angle(
      const YAML::Node& spec, const System& system, const std::string& what,
      const std::string& required, const std::set<std::string>& optional = {});
  void read_constraints(const YAML::Node& node, System& system);
  Friction read_friction(const YAML::Node& f, const Constraint& c, const System& system);
  // The with: of each rough constraint (index, its friction: node) names other position
  // constraints, each in one contact, and each normal can be found.
  void check_friction(const std::vector<std::pair<std::size_t, YAML::Node>>& rough,
                      const System& system) const;
  void read_joint(const YAML::Node& spec, const std::string& name, System& system);
  void read_rolling(const YAML::Node& spec, const std::string& name, System& system);
  void read_initial(const YAML::Node& node, System& system);
  void read_initial_omega(const std::pair<YAML::Node, YAML::Node>& item, const std::string& owner,
                          const std::string& member, System& system);
  void read_simulate(const YAML::Node& node, System& system);
  std::vector<Output> read_outputs(const YAML::Node& node, const System& system,
                                   const std::string& what);
  void read_stop_when(const YAML::Node& node, System& system);
  void read_impulses(const YAML::Node& node, System& system);
  // Checks with the parameters' values (model_checks.cpp).
  void expect_positive_mass(const YAML::Node& node, const Expr& mass, const System& system) const;
  void expect_realisable_inertia(const YAML::Node& node, const GiNaC::matrix& J,
                                 const System& system) const;
  void expect_inertia_about_rotation_axes(const YAML::Node& node, std::size_t b,
                                          const System& system) const;
  void expect_every_coordinate_moves(const System& system) const;

  std::string file_;
  std::string_view source_;
  std::set<std::string> columns_;              // names of the CSV columns taken so far
  Expr shape_mass_;                            // the mass of the body whose inertia is being read
  std::vector<SourcePosition> coordinate_at_;  // where each coordinate is named
  // the expression read so far with the largest expansion, and where
  mutable double largest_terms_ = 0;
  mutable SourcePosition largest_at_;
};

}  // namespace unidyn::model_reading
