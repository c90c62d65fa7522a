// The simulation loop: constrained dynamics, projection, output rows, run summary.
#include "unidyn/integrate/simulation.hpp"

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "unidyn/equations/kane.hpp"
#include "unidyn/integrate/applied_impulses.hpp"
#include "unidyn/integrate/contacts.hpp"
#include "unidyn/integrate/cvode.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/dormand_prince_853.hpp"
#include "unidyn/integrate/driver.hpp"
#include "unidyn/integrate/friction_phases.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/rattle.hpp"
#include "unidyn/integrate/rk4.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// The caller's row callback failed at time t (its exception's message).
struct RowRefused : std::runtime_error {
  RowRefused(double time, const std::string& why) : std::runtime_error(why), t(time) {}
  double t;
};

bool has_energy_column(const System& system) {
  for (const auto& f : system.forces) {
    if (!f.conservative) return false;
  }
  return true;
}

// "L2 = 6 from 2*L"
std::string fmt_parameter(const std::string& name, double value, const Expr& definition) {
  std::ostringstream text;
  text.precision(17);
  text << name << " = " << value << " from " << definition;
  return text.str();
}

// What changes T + U whatever happens in a run, or "" (the forces all have potentials: see
// has_energy_column): a model driven by t, impulses applied. Friction and impacts count only when
// they do work in the run (dissipation_in_run).
std::string energy_changed_by(const System& system) {
  const Expr& t = system.time();
  const auto on_t = [&](const VectorExpr& v) { return v[0].has(t) || v[1].has(t) || v[2].has(t); };
  bool driven = false;
  for (const auto& f : system.forces) {
    driven = driven || f.potential.has(t);
    for (const auto& force : f.forces) driven = driven || on_t(force.force);
    for (const auto& force : f.body_forces) driven = driven || on_t(force.force);
    for (const auto& moment : f.moments) driven = driven || on_t(moment.moment);
  }
  for (const auto& p : system.particles) driven = driven || on_t(p.position);
  for (const auto& b : system.bodies) {
    driven = driven || on_t(b.center) || Expr(b.rotation).has(t);
  }
  for (const auto& c : system.constraints) driven = driven || c.expression.has(t);
  std::string why = driven ? "driven by t" : "";
  if (!system.impulses.empty()) why += (why.empty() ? "" : "; ") + std::string("impulses applied");
  return why;
}

// What took energy away during the run: friction (−∫ R_t · v_slip dt, its power integrated
// over the rows by the trapezoidal rule, beyond 1e-10 of the energy's scale) and the impulses of
// impacts that were not elastic.
std::string dissipation_in_run(double friction_work, double energy_scale,
                               std::size_t dissipative_impacts) {
  std::string why;
  if (std::abs(friction_work) > 1e-10 * energy_scale) {
    std::ostringstream taken;
    taken.precision(3);
    taken << -friction_work;
    why = "dissipative: friction took " + taken.str() + " (over the rows)";
  }
  if (dissipative_impacts > 0) {
    why += (why.empty() ? "" : "; ") + std::string("dissipative: ") +
           std::to_string(dissipative_impacts) +
           (dissipative_impacts == 1 ? " impact" : " impacts") + " with restitution < 1";
  }
  return why;
}

double to_double(const Expr& e, const GiNaC::exmap& values) {
  const std::optional<double> v = real_value(e, values);
  if (!v) {
    std::ostringstream text;
    text << e;
    throw std::invalid_argument("cannot evaluate the initial value '" + text.str() +
                                "' to a real number");
  }
  return *v;
}

// Holds the state on the constraint manifolds: Newton steps Δq = −M⁻¹A_Ψᵀ (A_Ψ M⁻¹ A_Ψᵀ)⁻¹ Ψ on
// the position constraints, then Δq̇ = −M⁻¹Aᵀ (A M⁻¹ Aᵀ)⁻¹ (A q̇ + e) on all of them (the
// corrections of least kinetic-energy norm).
class Projector {
 public:
  Projector(const CompiledSystem& compiled, std::span<const double> parameters)
      : compiled_(compiled), parameters_(parameters), data_(compiled.make_data()) {
    set_active({});
  }

  // The constraints that hold now (unilateral ones come and go).
  void set_active(const std::vector<bool>& active) {
    data_.active = active;
    position_rows_.clear();
    velocity_rows_.clear();
    for (std::size_t k = 0; k < compiled_.constraint_count(); ++k) {
      if (!active.empty() && !active[k]) continue;
      if (compiled_.is_position_constraint()[k])
        position_rows_.push_back(static_cast<Eigen::Index>(k));
      velocity_rows_.push_back(static_cast<Eigen::Index>(k));
    }
  }

  // Projects (q, q̇) in place; returns the size of the correction.
  double project(double t, Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
    if (velocity_rows_.empty()) return 0.0;
    double moved = 0.0;
    Eigen::VectorXd qddot, lambda;
    for (int iteration = 0; iteration < 4 && !position_rows_.empty(); ++iteration) {
      compiled_.constraints(t, q, qdot, parameters_, data_);
      const Eigen::VectorXd psi = data_.constraint_position(position_rows_);
      if (psi.cwiseAbs().maxCoeff() <= 1e-14 * (1.0 + q.cwiseAbs().maxCoeff())) break;
      const Eigen::MatrixXd A = data_.constraint_matrix(position_rows_, Eigen::all);
      const Eigen::VectorXd dq = correction(t, q, qdot, A, psi);
      q -= dq;
      moved = std::max(moved, dq.cwiseAbs().maxCoeff());
    }
    compiled_.constraints(t, q, qdot, parameters_, data_);
    const Eigen::MatrixXd A = data_.constraint_matrix(velocity_rows_, Eigen::all);
    const Eigen::VectorXd residual = A * qdot + data_.constraint_velocity_term(velocity_rows_);
    const Eigen::VectorXd dqdot = correction(t, q, qdot, A, residual);
    qdot -= dqdot;
    return std::max(moved, dqdot.cwiseAbs().maxCoeff());
  }

 private:
  Eigen::VectorXd correction(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                             const Eigen::MatrixXd& A, const Eigen::VectorXd& r) {
    Eigen::VectorXd qddot, lambda;
    compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);  // fills the mass matrix
    const Eigen::LLT<Eigen::MatrixXd> llt(data_.mass_matrix);
    // a semi-definite M (redundant coordinates) has no kinetic-energy norm: the Euclidean one then
    const Eigen::MatrixXd MinvAt =
        llt.info() == Eigen::Success ? Eigen::MatrixXd(llt.solve(A.transpose())) : A.transpose();
    return MinvAt * (A * MinvAt).ldlt().solve(r);
  }

  const CompiledSystem& compiled_;
  std::span<const double> parameters_;
  CompiledSystemData data_;
  std::vector<Eigen::Index> position_rows_, velocity_rows_;
};

// What stops a run at the gimbal lock of `body`'s Euler angles, with the advice.
std::string gimbal_lock_stop(const Body& body, double volume, const Vec3& angles) {
  return "the " + body.chart->set.name() + " Euler angles of body '" + body.name +
         "' reached gimbal lock (|[g1, g2, g3]| = " + std::to_string(volume) + ", second angle " +
         std::to_string(angles[1]) +
         " rad): describe its rotation with a quaternion, or with an Euler set whose singular "
         "angle this motion avoids";
}

// The Euler angles of the bodies in state y nearest gimbal lock: |[g1, g2, g3]| and the body.
std::pair<double, const Body*> nearest_gimbal_lock(const System& system, const Eigen::VectorXd& y,
                                                   Vec3& angles) {
  std::pair<double, const Body*> nearest{std::numeric_limits<double>::infinity(), nullptr};
  for (const Body& body : system.bodies) {
    if (!body.chart) continue;
    const auto& c = body.chart->coordinates;
    const Vec3 a(y[static_cast<Eigen::Index>(c[0])], y[static_cast<Eigen::Index>(c[1])],
                 y[static_cast<Eigen::Index>(c[2])]);
    const double volume = std::abs(euler_basis_volume(body.chart->set, a));
    if (volume < nearest.first) {
      nearest = {volume, &body};
      angles = a;
    }
  }
  return nearest;
}

// (§6.8) The Euler-angle charts of the bodies: the closest approach to gimbal lock goes into the
// summary, and a run that reaches it stops with a message that says what to do instead.
void watch_euler_charts(const System& system, double t, const Eigen::VectorXd& y,
                        SimulationSummary& summary) {
  Vec3 angles;
  const auto [volume, body] = nearest_gimbal_lock(system, y, angles);
  if (!body) return;
  if (volume < summary.closest_gimbal_lock) {
    summary.closest_gimbal_lock = volume;
    summary.closest_gimbal_lock_time = t;
  }
  if (volume <= kGimbalLockStop) throw std::runtime_error(gimbal_lock_stop(*body, volume, angles));
}

// A run that failed (its step size collapsed) where Euler angles are near gimbal lock failed
// because of it: the rates of the angles grow like 1/|[g1, g2, g3]| there. The lock and the
// advice, then what the integrator said; the integrator's message alone elsewhere.
std::string failure_near_gimbal_lock(const System& system, const Eigen::VectorXd& y,
                                     const std::string& message) {
  Vec3 angles;
  const auto [volume, body] = nearest_gimbal_lock(system, y, angles);
  if (!body || volume > kGimbalLockNear) return message;
  if (message.find("reached gimbal lock") != std::string::npos) return message;  // the watch's
  return gimbal_lock_stop(*body, volume, angles) + " (" + message + ")";
}

// The step of a fixed-step method: `step`, else output_step / 10, made a whole number of steps
// per output interval.
double fixed_step(const SimulationOptions& options) {
  const double h = options.step > 0 ? options.step : options.output_step / 10;
  return options.output_step / std::ceil(options.output_step / h - 1e-9);
}

// The integrator the options ask for. A given projection goes inside CVODE's step; the explicit
// methods are projected by the driver's post-step hook instead.
std::unique_ptr<Stepper> make_stepper(const SimulationOptions& options, OdeFunction rhs,
                                      std::function<void(double, Eigen::VectorXd&)> projection) {
  if (options.method == "rk4") return std::make_unique<Rk4>(std::move(rhs), fixed_step(options));
  if (options.method == "dopri5" || options.method == "dop853") {
    DormandPrinceOptions o =
        options.method == "dop853" ? DormandPrinceOptions::dop853() : DormandPrinceOptions{};
    o.rtol = options.rtol;
    o.atol = options.atol;
    o.max_steps = options.max_steps;
    if (options.method == "dop853") return std::make_unique<DormandPrince853>(std::move(rhs), o);
    return std::make_unique<DormandPrince54>(std::move(rhs), o);
  }
  if (options.method == "cvode") {
    CvodeOptions o;
    o.rtol = options.rtol;
    o.atol = options.atol;
    o.max_steps = options.max_steps;
    o.projection = std::move(projection);
    return std::make_unique<CvodeBdf>(std::move(rhs), o);
  }
  throw std::invalid_argument("unknown method '" + options.method + "' (expected " +
                              integration_methods() + ")");
}

}  // namespace

void expect_no_gimbal_lock(const System& system, const Eigen::VectorXd& q, const std::string& state,
                           const std::string& advice, const std::vector<bool>& given) {
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const Body& body = system.bodies[b];
    if (!body.chart) continue;
    const auto& c = body.chart->coordinates;
    // angles left to be computed from the constraints are checked once they are (unless an
    // angular velocity given for the body needs them now)
    const bool omega_given =
        std::any_of(system.initial_omegas.begin(), system.initial_omegas.end(),
                    [&](const InitialOmega& omega) { return omega.body == b; });
    if (!given.empty() && !omega_given && !(given[c[0]] && given[c[1]] && given[c[2]])) {
      continue;
    }
    const Vec3 angles(q[static_cast<Eigen::Index>(c[0])], q[static_cast<Eigen::Index>(c[1])],
                      q[static_cast<Eigen::Index>(c[2])]);
    if (std::abs(euler_basis_volume(body.chart->set, angles)) > kGimbalLockStop) continue;
    const Tensor Q = rotation_tensor(body.chart->set, angles);
    const EulerSet* best = &all_euler_sets().front();
    double best_volume = -1;
    for (const EulerSet& set : all_euler_sets()) {
      const double volume = std::abs(euler_angles(set, Q).volume);
      if (volume > best_volume) {
        best_volume = volume;
        best = &set;
      }
    }
    const auto& names = system.coordinates();
    throw std::invalid_argument(
        "body '" + body.name + "' " + state + " at the gimbal lock of its " +
        body.chart->set.name() + " Euler angles (" + names[c[1]].name + " = " +
        detail::to_short_text(angles[1]) + ", where only the sum or difference of " +
        names[c[0]].name + " and " + names[c[2]].name +
        " is defined and the mass matrix is singular): " + advice +
        ", or describe its "
        "rotation with {euler: " +
        best->name() + ", ...}, regular there, or with {quaternion: [e0, e1, e2, e3]}");
  }
}

SimulationOptions simulation_options(const SimulationSettings& settings) {
  SimulationOptions o;
  o.t_end = settings.t_end;
  o.output_step = settings.output_step;
  o.method = settings.method;
  o.rtol = settings.rtol;
  o.atol = std::min(settings.atol, settings.rtol * 1e-2);
  o.step = settings.step;
  return o;
}

SimulationOptions simulation_options(const SimulationSettings& settings,
                                     const SimulationOverrides& overrides) {
  SimulationOptions o = simulation_options(settings);
  if (overrides.t_end > 0) o.t_end = overrides.t_end;
  if (overrides.output_step > 0) o.output_step = overrides.output_step;
  if (!overrides.method.empty()) o.method = overrides.method;
  if (overrides.rtol > 0) {
    o.rtol = overrides.rtol;
    o.atol = std::min(settings.atol, o.rtol * 1e-2);
  }
  // a run asked for more rows than anyone can use would fill the disk
  if ((o.t_end / o.output_step) > 1e8) {
    throw std::invalid_argument("--t-end / --output-step asks for more than 10^8 rows");
  }
  if (!is_integration_method(o.method)) {
    throw std::invalid_argument("--method must be " + integration_methods());
  }
  return o;
}

std::vector<std::string> simulation_columns(const System& system) {
  std::vector<std::string> columns{"t"};
  for (const auto& q : system.coordinates()) columns.push_back(q.name);
  for (const auto& q : system.coordinates()) columns.push_back("der(" + q.name + ")");
  if (has_energy_column(system)) columns.push_back("energy");
  for (const auto& c : system.constraints) columns.push_back("lambda(" + c.name + ")");
  for (const auto& o : system.outputs) columns.push_back(o.name);
  for (const auto& o : system.conserved) columns.push_back(o.name);
  return columns;
}

SimulationStart initial_state(const System& system,
                              const std::vector<std::pair<std::string, double>>& overrides) {
  SimulationStart start;
  for (const auto& p : system.parameters) start.parameters.push_back(p.value);
  const std::size_t n = system.coordinates().size();
  std::vector<std::optional<double>> q_override(n), qdot_override(n);
  for (const auto& [name, value] : overrides) {
    if (const auto p = system.find_parameter(name)) {
      start.parameters[*p] = value;
    } else if (const auto q = system.find_coordinate(name)) {
      q_override[*q] = value;
    } else if (name.starts_with("der(") && name.ends_with(")") &&
               system.find_coordinate(name.substr(4, name.size() - 5))) {
      qdot_override[*system.find_coordinate(name.substr(4, name.size() - 5))] = value;
    } else {
      throw std::invalid_argument("--set " + name +
                                  ": not a parameter, coordinate or der(coordinate)");
    }
  }
  // the parameters defined by expressions of others, anew from the values given, in order
  GiNaC::exmap values;
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    const Parameter& p = system.parameters[k];
    const bool overridden = std::any_of(overrides.begin(), overrides.end(),
                                        [&](const auto& o) { return o.first == p.name; });
    if (p.derived && !overridden) {
      const auto value = real_value(p.definition, values);
      if (!value) {
        throw std::invalid_argument("parameter " + p.name + " = " + to_text(p.definition) +
                                    " has no real value with the values given");
      }
      if (*value != start.parameters[k]) {
        start.computed.push_back(fmt_parameter(p.name, *value, p.definition));
      }
      start.parameters[k] = *value;
    }
    values[p.symbol] = start.parameters[k];
  }
  start.q.resize(static_cast<Eigen::Index>(n));
  start.qdot.resize(static_cast<Eigen::Index>(n));
  // given in the model (a System made without a model file gives every value) or with --set
  const auto given = [](const std::vector<bool>& flags, std::size_t i) {
    return i >= flags.size() || flags[i];
  };
  for (std::size_t i = 0; i < n; ++i) {
    start.q_given.push_back(given(system.initial_value_given, i) || q_override[i].has_value());
    start.qdot_given.push_back(given(system.initial_rate_given, i) || qdot_override[i].has_value());
  }
  for (std::size_t i = 0; i < n; ++i) {
    const auto I = static_cast<Eigen::Index>(i);
    start.q[I] = q_override[i] ? *q_override[i] : to_double(system.initial_values[i], values);
    start.qdot[I] =
        qdot_override[i] ? *qdot_override[i] : to_double(system.initial_rates[i], values);
  }
  expect_no_gimbal_lock(system, start.q, "starts", "start it elsewhere", start.q_given);
  for (const InitialOmega& omega : system.initial_omegas) {
    for (const std::size_t j : omega.coordinates) {
      if (qdot_override[j]) {
        throw std::invalid_argument("--set der(" + system.coordinates()[j].name +
                                    ") conflicts with the angular velocity of '" +
                                    system.bodies[omega.body].name + "' given in the model");
      }
    }
  }
  apply_initial_angular_velocities(system, start);
  return start;
}

SimulationSummary simulate(const System& system, const CompiledSystem& compiled,
                           const SimulationStart& start, const SimulationOptions& options,
                           const std::function<void(const std::vector<double>&)>& on_row) {
  SimulationSummary summary;
  const auto n = static_cast<Eigen::Index>(compiled.coordinate_count());
  const std::span<const double> parameters(start.parameters);
  CompiledSystemData data = compiled.make_data();
  Projector projector(compiled, parameters);
  Contacts contacts(system, compiled, parameters);
  summary.has_energy = has_energy_column(system);
  for (const auto& c : system.constraints) summary.multipliers.push_back({c.name});

  // y = (q, q̇), y' = (q̇, q̈). Equations that are not finite at a state the integrator tries give
  // a derivative that is not finite: a Runge–Kutta step is rejected and shrunk, CVODE takes it as a
  // recoverable error and retries with a smaller step; why is said if the run fails all the same.
  Eigen::VectorXd qddot, lambda;
  std::string not_finite;
  const OdeFunction rhs = [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    try {
      compiled.solve(t, y.head(n), y.tail(n), parameters, qddot, lambda, data);
    } catch (const NotFiniteState& e) {
      not_finite = e.what();
      dydt.setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    }
    dydt.head(n) = y.tail(n);
    dydt.tail(n) = qddot;
  };

  std::vector<double> observed(compiled.observation_count());
  std::vector<double> row;
  // observed: T, U, the outputs, the conserved quantities, the stop_when expressions
  const std::size_t outputs_begin = 2;
  const std::size_t n_conserved = system.conserved.size();
  const std::size_t conserved_begin = outputs_begin + system.outputs.size();
  const std::size_t stops_begin = conserved_begin + n_conserved;
  std::vector<double> conserved_initial(n_conserved);
  double energy_scale = 0.0, max_energy_error = 0.0;
  double friction_work = 0.0, last_friction_power = 0.0;
  double previous_row_time = start.t0;

  // One output row at (t, y): solve for q̈ and λ, observe, check residuals, hand it on.
  const auto emit = [&](double t, const Eigen::VectorXd& y) {
    const Eigen::VectorXd q = y.head(n), qdot = y.tail(n);
    try {
      compiled.solve(t, q, qdot, parameters, qddot, lambda, data);
    } catch (const NotFiniteState& e) {
      // the row's state, interpolated between steps, is off where the equations are finite
      throw RowRefused(t, std::string(e.what()) +
                              " (the state the integrator gives for this row is outside where the "
                              "equations are finite: a tighter --rtol keeps it inside)");
    }
    compiled.observe(t, q, qdot, qddot, lambda, parameters, observed, data);
    row.assign(1, t);
    row.insert(row.end(), q.data(), q.data() + n);
    row.insert(row.end(), qdot.data(), qdot.data() + n);
    const double T = observed[0], U = observed[1], E = T + U;
    if (summary.has_energy) row.push_back(E);
    row.insert(row.end(), lambda.data(), lambda.data() + lambda.size());
    row.insert(row.end(), observed.begin() + outputs_begin, observed.begin() + stops_begin);
    if (summary.rows == 0) {
      summary.energy_initial = E;
      for (std::size_t c = 0; c < n_conserved; ++c) {
        conserved_initial[c] = observed[conserved_begin + c];
        summary.conserved_drift.push_back({system.conserved[c].name, conserved_initial[c], 0.0});
      }
    }
    summary.energy_final = E;
    summary.last_row_time = t;
    for (std::size_t k = 0; k < summary.multipliers.size(); ++k) {
      if (!contacts.active()[k]) continue;
      auto& range = summary.multipliers[k];
      const double value = lambda[static_cast<Eigen::Index>(k)];
      range.min = range.held ? std::min(range.min, value) : value;
      range.max = range.held ? std::max(range.max, value) : value;
      range.held = true;
    }
    energy_scale = std::max(energy_scale, T + std::abs(U));
    // the friction's power R_t . v_slip, integrated over the rows
    double friction_power = 0.0;
    for (std::size_t c = 0; c < data.friction.size(); ++c) {
      const FrictionValues& f = data.friction[c];
      friction_power += f.tangential_part(data.contact_force[c]).dot(f.slip);
    }
    if (summary.rows > 0) {
      friction_work += 0.5 * (friction_power + last_friction_power) * (t - previous_row_time);
    }
    last_friction_power = friction_power;
    previous_row_time = t;
    max_energy_error = std::max(max_energy_error, std::abs(E - summary.energy_initial));
    for (std::size_t c = 0; c < n_conserved; ++c) {
      const double c0 = conserved_initial[c];
      const double value = observed[conserved_begin + c];
      summary.conserved_drift[c].max_change =
          std::max(summary.conserved_drift[c].max_change, std::abs(value - c0));
    }
    if (compiled.constraint_count() > 0) {
      compiled.constraints(t, q, qdot, parameters, data);
      // the constraints that hold (a free unilateral one has Ψ > 0, its rate anything)
      const Eigen::VectorXd velocity_residual =
          data.constraint_matrix * qdot + data.constraint_velocity_term;
      for (std::size_t k = 0; k < compiled.constraint_count(); ++k) {
        const auto K = static_cast<Eigen::Index>(k);
        if (!contacts.active()[k]) continue;
        if (compiled.is_position_constraint()[k]) {
          summary.max_position_residual =
              std::max(summary.max_position_residual, std::abs(data.constraint_position[K]));
        }
        summary.max_velocity_residual =
            std::max(summary.max_velocity_residual, std::abs(velocity_residual[K]));
      }
    }
    // a row the caller cannot take (a full disk) ends the run there; the rows before it stay
    try {
      on_row(row);
    } catch (const std::exception& e) {
      throw RowRefused(t, e.what());
    }
    ++summary.rows;
  };

  // The phase of the unilateral constraints, in the solver and the projector.
  const auto use_phase = [&] {
    data.active = contacts.active();
    projector.set_active(contacts.active());
  };
  // Event functions: the unilateral contacts', the rough contacts', the applied impulses' (at
  // their times), then each stop_when expression times its sign at the start.
  FrictionPhases friction(system, compiled, parameters);
  AppliedImpulses impulses(system, compiled, parameters, start.t0);
  const std::size_t U = contacts.event_count(), F = friction.event_count(),
                    I = impulses.event_count(), UFI = U + F + I;
  std::vector<double> stop_sign(system.stop_when.size(), 1.0);
  const auto events = [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& g) {
    g.resize(static_cast<Eigen::Index>(UFI + stop_sign.size()));
    const Eigen::VectorXd q = y.head(n), qdot = y.tail(n);
    if (U > 0) contacts.events(t, q, qdot, std::span(g.data(), U));
    if (F > 0) friction.events(t, q, qdot, data, std::span(g.data() + U, F));
    if (I > 0) impulses.events(t, std::span(g.data() + U + F, I));
    if (stop_sign.empty()) return;
    compiled.solve(t, q, qdot, parameters, qddot, lambda, data);
    compiled.observe(t, q, qdot, qddot, lambda, parameters, observed, data);
    for (std::size_t s = 0; s < stop_sign.size(); ++s) {
      g[static_cast<Eigen::Index>(UFI + s)] = stop_sign[s] * observed[stops_begin + s];
    }
  };
  // An event: a contact made or lost, a rough contact sticking or slipping, an impulse, or a stop.
  const auto on_event = [&](double t, Eigen::VectorXd& y, std::size_t which) {
    Eigen::VectorXd yq = y.head(n), yv = y.tail(n);
    if (which < U) {
      summary.phases.push_back({t, contacts.handle(t, yq, yv, which)});
      use_phase();
      y << yq, yv;
    } else if (which < U + F) {
      // a slip that only turned re-arms its event: a new start (the steps past it assumed the
      // old direction), without a row of its own
      std::vector<std::string> what = friction.handle(t, yq, yv, which - U, data);
      if (what.empty()) return AfterEvent::restart_quietly;
      for (auto& line : what) summary.phases.push_back({t, std::move(line)});
    } else if (which < UFI) {
      // the rates jump; the rough contacts stick or slide from the new rates
      summary.phases.push_back({t, impulses.apply(t, yq, yv, which - U - F, contacts.active())});
      for (auto& line : friction.start(t, yq, yv, data)) {
        summary.phases.push_back({t, std::move(line)});
      }
      y << yq, yv;
    } else {
      summary.phases.push_back(
          {t, "stop_when '" + system.stop_when[which - UFI].name + "' reached 0"});
      return AfterEvent::stop;
    }
    return AfterEvent::restart;
  };

  // Integrate with the projection after every step; rows come through `emit`. The stepper
  // outlives the attempt: a run its rows stop (Ctrl-C, a full disk) still counts its steps.
  std::optional<CompiledNaturalSystem> natural;
  std::unique_ptr<Stepper> stepper;
  try {
    const bool project = options.project && compiled.constraint_count() > 0;
    const std::function<void(double, Eigen::VectorXd&)> projection = [&](double t,
                                                                         Eigen::VectorXd& y) {
      Eigen::VectorXd yq = y.head(n), yv = y.tail(n);
      projector.project(t, yq, yv);
      y << yq, yv;
    };
    const bool inside = options.method == "cvode";
    // RATTLE keeps the constraints itself (a projection would spoil its symplecticity)
    const bool symplectic = options.method.starts_with("rattle");
    if (symplectic) {
      natural.emplace(system, kane_equations(system));
      RattleOptions o;
      o.step = fixed_step(options);
      o.order = options.method == "rattle6" ? 6 : options.method == "rattle4" ? 4 : 2;
      stepper = std::make_unique<Rattle>(*natural, start.parameters, o);
    } else {
      stepper = make_stepper(options, rhs, project && inside ? projection : nullptr);
    }
    Eigen::VectorXd q = start.q, qdot = start.qdot;
    if (contacts.any()) {
      // the contacts that hold at the start, then onto their manifolds with the rest
      projector.set_active(contacts.active());
      for (auto& line : contacts.start(start.t0, q, qdot)) {
        summary.phases.push_back({start.t0, std::move(line)});
      }
      use_phase();
    }
    if (options.project) summary.initial_projection = projector.project(start.t0, q, qdot);
    if (F > 0) {
      for (auto& line : friction.start(start.t0, q, qdot, data)) {
        summary.phases.push_back({start.t0, std::move(line)});
      }
    }
    Eigen::VectorXd y0(2 * n);
    y0 << q, qdot;
    IntegrationCallbacks callbacks;
    callbacks.output = emit;
    if (UFI + stop_sign.size() > 0) {
      Eigen::VectorXd g0;
      events(start.t0, y0, g0);
      for (std::size_t s = 0; s < stop_sign.size(); ++s) {
        const double value = g0[static_cast<Eigen::Index>(UFI + s)];
        if (value == 0.0) {
          throw std::invalid_argument("stop_when '" + system.stop_when[s].name +
                                      "' is 0 at the start");
        }
        stop_sign[s] = value > 0 ? 1.0 : -1.0;
      }
      callbacks.events = events;
      callbacks.on_event = on_event;
    }
    callbacks.post_step = [&](double t, Eigen::VectorXd& y) {
      // a stiff run may take seconds between rows: a signal is looked at every step
      if (options.interrupted && options.interrupted()) {
        throw std::runtime_error("interrupted (a signal)");
      }
      watch_euler_charts(system, t, y, summary);
      if (project && !inside && !symplectic) projection(t, y);
    };
    const IntegrationResult result =
        integrate(*stepper, start.t0, y0, options.t_end, options.output_step, callbacks);
    summary.ok = result.ok;
    summary.stopped = result.stopped;
    summary.event_rows = result.event_rows;
    summary.message =
        result.ok ? result.message : failure_near_gimbal_lock(system, result.y, result.message);
    if (!result.ok && !not_finite.empty()) {
      summary.message +=
          " (the equations were not finite at a state the integrator tried: " + not_finite + ")";
    }
    summary.failure_time = result.t_failure;
    summary.stats = result.stats;
  } catch (const RowRefused& e) {
    summary.ok = false;
    summary.message = e.what();
    summary.failure_time = e.t;
    if (stepper) summary.stats = stepper->stats();
  } catch (const std::exception& e) {
    // the initial state itself cannot be solved (or its output row failed)
    summary.ok = false;
    summary.message = e.what();
    summary.failure_time = start.t0;
  }
  summary.energy_relative_drift = max_energy_error / std::max(energy_scale, 1e-300);
  // what changed the energy: the model's drive and impulses, the run's friction and impacts
  summary.energy_not_conserved = energy_changed_by(system);
  const std::string dissipated =
      dissipation_in_run(friction_work, energy_scale, contacts.dissipative_impacts());
  if (!dissipated.empty()) {
    summary.energy_not_conserved += (summary.energy_not_conserved.empty() ? "" : "; ") + dissipated;
  }
  return summary;
}

}  // namespace unidyn
