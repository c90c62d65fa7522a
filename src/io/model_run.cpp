// The model file's initial state, simulate: settings, outputs, conserved quantities and stop_when.
#include "model_reader.hpp"

namespace unidyn::model_reading {

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

}  // namespace

void ModelReader::read_initial(const YAML::Node& node, System& system) {
  expect_map(node, "initial");
  const SystemScope scope(system);
  std::set<std::string> given;
  for (const auto& item : node) {
    std::string key = scalar(item.first, "an initial value's name");
    if (const std::size_t dot = key.find('.'); dot != std::string::npos) {
      read_initial_omega(item, key.substr(0, dot), key.substr(dot + 1), system);
      continue;
    }
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
    if (is_rate && system.initial_rate_given[*q]) {
      fail(item.first, "der(" + key + ") is given twice (also by a body's omega)");
    }
    (is_rate ? system.initial_rates : system.initial_values)[*q] = value;
    (is_rate ? system.initial_rate_given : system.initial_value_given)[*q] = true;
  }
}

// B.omega: [w1, w2, w3] (on E1, E2, E3) or B.omega_body: (on e1, e2, e3): the rates of the
// coordinates B's angular velocity depends on are then given by it.
void ModelReader::read_initial_omega(const std::pair<YAML::Node, YAML::Node>& item,
                                     const std::string& owner, const std::string& member,
                                     System& system) {
  const auto b = system.find_body(owner);
  if (!b || (member != "omega" && member != "omega_body")) {
    fail(item.first, "'" + owner + "." + member +
                         "' is not a coordinate, der(coordinate), B.omega or B.omega_body");
  }
  InitialOmega omega{*b, member == "omega_body", {}, {}, at(item.first)};
  omega.omega = vector_expr(item.second, SystemScope(system), member);
  for (int i = 0; i < 3; ++i) {
    if (!real_value(omega.omega[i], system.parameter_values())) {
      fail(item.second,
           "an angular velocity's components are real numbers, from numbers and "
           "parameters only");
    }
  }
  const VectorExpr w = system.angular_velocity(*b);
  const auto& q = system.coordinates();
  for (std::size_t j = 0; j < q.size(); ++j) {
    if (!w[0].has(q[j].rate) && !w[1].has(q[j].rate) && !w[2].has(q[j].rate)) continue;
    if (system.initial_rate_given[j]) {
      fail(item.first,
           "der(" + q[j].name + ") is given twice (also by " + owner + "." + member + ")");
    }
    system.initial_rate_given[j] = true;
    omega.coordinates.push_back(j);
  }
  if (omega.coordinates.empty()) fail(item.first, "body '" + owner + "' does not turn");
  system.initial_omegas.push_back(std::move(omega));
}

void ModelReader::read_simulate(const YAML::Node& node, System& system) {
  expect_map(node, "simulate");
  // (its stop_when is read with the outputs, whose names it may use)
  expect_keys(node, {"t_end", "output_step", "method", "rtol", "atol", "step", "stop_when"},
              "simulate");
  SimulationSettings& s = system.simulate;
  if (node["t_end"]) s.t_end = number(node["t_end"], "t_end");
  if (node["output_step"]) s.output_step = number(node["output_step"], "output_step");
  if (node["method"]) {
    s.method = scalar(node["method"], "method");
    s.method_chosen = true;
  }
  if (node["rtol"]) s.rtol = number(node["rtol"], "rtol");
  if (node["atol"]) s.atol = number(node["atol"], "atol");
  if (node["step"]) s.step = number(node["step"], "step");
  if (!(s.t_end > 0)) fail(node["t_end"], "t_end must be positive");
  if (!(s.output_step > 0)) fail(node["output_step"], "output_step must be positive");
  if (!is_integration_method(s.method)) {
    fail(node["method"], "method must be " + integration_methods());
  }
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
    // a scalar is one column; a vector three, name.x, name.y, name.z (components on E1, E2, E3)
    const Value value = item.second.IsSequence() ? Value::of(vector_expr(item.second, scope, name))
                                                 : any_expr(item.second, scope, name);
    std::vector<std::pair<std::string, Expr>> columns;
    if (value.is_vector()) {
      for (int i = 0; i < 3; ++i) columns.emplace_back(name + "." + "xyz"[i], value.vector[i]);
    } else {
      columns.emplace_back(name, value.scalar);
    }
    for (auto& [column, expression] : columns) {
      // one CSV column each: not t, q, der(q), energy, lambda(c), nor another output's name
      if (!columns_.insert(column).second) {
        fail(item.first, "'" + column + "' is already the name of a CSV column");
      }
      outputs.push_back({column, expression, at(item.first)});
    }
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

}  // namespace unidyn::model_reading
