// The operating point: the values given, the rest completed from the constraints, q̈ and λ solved.
#include "unidyn/analysis/operating_point.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>

#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/model/scope.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// A unilateral constraint is apart where Ψ > 0 beyond the one tolerance (integrate/
// initial_state.hpp: as a distance, relative to the state's size).
bool apart(double psi, const Eigen::Ref<const Eigen::RowVectorXd>& gradient,
           const Eigen::VectorXd& q) {
  return psi > 0.0 && relative_residual(psi, gradient, q) > kConstraintTolerance;
}

}  // namespace

std::optional<StateValue> state_value(const System& system, const std::string& name) {
  if (const auto q = system.find_coordinate(name)) return StateValue{*q, false};
  if (name.starts_with("der(") && name.ends_with(")")) {
    if (const auto q = system.find_coordinate(name.substr(4, name.size() - 5))) {
      return StateValue{*q, true};
    }
  }
  return std::nullopt;
}

std::optional<std::size_t> momentum_coordinate(const System& system, const std::string& name) {
  if (!name.starts_with("p(") || !name.ends_with(")")) return std::nullopt;
  return system.find_coordinate(name.substr(2, name.size() - 3));
}

Expr given_number(double x) {
  return std::abs(x) < std::numeric_limits<double>::min() ? Expr(0) : Expr(GiNaC::numeric(x));
}

std::vector<GivenValue> parse_given_values(const System& system,
                                           const std::vector<std::string>& texts, bool momenta) {
  std::vector<GivenValue> given;
  std::set<std::string> names;
  const SystemScope scope(system);
  for (const std::string& text : texts) {
    const std::size_t eq = text.find('=');
    const std::string name = text.substr(0, eq);
    if (eq != std::string::npos && !momenta && momentum_coordinate(system, name)) {
      throw std::invalid_argument("--at " + text +
                                  ": a momentum is given only for the steady motions of "
                                  "`unidyn equilibria --cyclic`; give the rate der(q) here");
    }
    if (eq == std::string::npos ||
        !(state_value(system, name) || (momenta && momentum_coordinate(system, name)))) {
      throw std::invalid_argument(
          "--at " + text + ": expected NAME=VALUE, NAME a coordinate" +
          (momenta ? ", der(coordinate) or p(coordinate)" : " or der(coordinate)"));
    }
    if (!names.insert(name).second) throw std::invalid_argument("--at gives " + name + " twice");
    Expr value;
    try {
      value = parse_scalar(std::string_view(text).substr(eq + 1), scope, {});
    } catch (const ModelError& e) {
      throw std::invalid_argument("--at " + text + ": " + e.what());
    }
    // a number, or an expression in the parameters alone
    for (const auto& q : system.coordinates()) {
      if (value.has(q.value) || value.has(q.rate) || value.has(q.acceleration)) {
        throw std::invalid_argument("--at " + text +
                                    ": the value must be a number or an expression in the "
                                    "parameters, not in coordinates or rates");
      }
    }
    if (value.has(system.time())) {
      throw std::invalid_argument("--at " + text + ": the value must not depend on t");
    }
    given.push_back({name, value});
  }
  return given;
}

std::vector<GivenValue> initial_values(const System& system,
                                       const std::vector<std::pair<std::string, double>>& sets) {
  const SimulationStart start = initial_state(system, sets);
  std::vector<GivenValue> out;
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (start.q_given[i]) {
      out.push_back({q[i].name, given_number(start.q[static_cast<Eigen::Index>(i)])});
    }
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    if (start.qdot_given[i]) {
      out.push_back(
          {"der(" + q[i].name + ")", given_number(start.qdot[static_cast<Eigen::Index>(i)])});
    }
  }
  return out;
}

void expect_smooth_contacts(const System& system, const std::vector<double>& parameters) {
  const GiNaC::exmap values = system.parameter_values(parameters);
  for (const Constraint& c : system.constraints) {
    if (!c.friction) continue;
    for (const Expr& mu : {c.friction->dynamic_coefficient, c.friction->static_coefficient}) {
      const std::optional<double> value = real_value(mu, values);
      if (value && *value == 0.0) continue;
      throw std::invalid_argument(
          "constraint '" + c.name + "' has friction (coefficient " + to_text(mu) +
          "): a rough contact's stick and slip are not smooth, and its motion is not linearised "
          "here; with the coefficients 0 (--set) the contact is smooth");
    }
  }
}

OperatingPoint operating_point(const System& system, const CompiledSystem& compiled,
                               const std::vector<GivenValue>& given,
                               const std::vector<double>& parameters) {
  const std::size_t n = system.coordinates().size(), m = system.constraints.size();
  expect_smooth_contacts(system, parameters);
  // The values given, at the parameters' values.
  const GiNaC::exmap values = system.parameter_values(parameters);
  SimulationStart start;
  start.parameters = parameters;
  start.q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  start.qdot = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
  start.q_given.assign(n, false);
  start.qdot_given.assign(n, false);
  for (const GivenValue& g : given) {
    const auto [i, rate] = *state_value(system, g.name);
    const std::optional<double> v = real_value(g.value, values);
    if (!v) {
      throw std::invalid_argument("--at " + g.name + "=" + to_text(g.value) +
                                  ": not a real number at the parameters' values");
    }
    (rate ? start.qdot : start.q)[static_cast<Eigen::Index>(i)] = *v;
    (rate ? start.qdot_given : start.q_given)[i] = true;
  }
  // The rest from the constraints; then no Euler angles at gimbal lock.
  OperatingPoint point;
  point.computed = complete_initial_state(system, compiled, start);
  expect_no_gimbal_lock(system, start.q, "is",
                        "linearise about another rotation of it (another value of the angles)");
  point.t = start.t0;
  point.parameters = std::move(start.parameters);
  point.q = std::move(start.q);
  point.qdot = std::move(start.qdot);
  point.q_given = std::move(start.q_given);
  point.qdot_given = std::move(start.qdot_given);
  // Unilateral constraints apart there exert nothing; the others hold.
  CompiledSystemData data = compiled.make_data();
  compiled.constraints(point.t, point.q, point.qdot, point.parameters, data);
  point.active.assign(m, true);
  for (std::size_t k = 0; k < m; ++k) {
    if (system.constraints[k].unilateral &&
        apart(data.constraint_position[static_cast<Eigen::Index>(k)],
              data.constraint_matrix.row(static_cast<Eigen::Index>(k)), point.q)) {
      point.active[k] = false;
    }
  }
  data.active = point.active;
  compiled.solve(point.t, point.q, point.qdot, point.parameters, point.qddot, point.lambda, data);
  return point;
}

}  // namespace unidyn
