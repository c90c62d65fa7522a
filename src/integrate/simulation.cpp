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
#include "unidyn/integrate/augmented_lagrangian.hpp"
#include "unidyn/integrate/contacts.hpp"
#include "unidyn/integrate/cvode.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/dormand_prince_853.hpp"
#include "unidyn/integrate/driver.hpp"
#include "unidyn/integrate/friction_phases.hpp"
#include "unidyn/integrate/hand_over.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/rattle.hpp"
#include "unidyn/integrate/rk4.hpp"
#include "unidyn/numeric/dependent_constraints.hpp"
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
    // a semi-definite M (redundant coordinates) has no kinetic-energy norm: the Euclidean one
    // then — and for a tree the recursive algorithms solve, which form no M: its only
    // constraints are the unit norms of Euler parameters, whose M is semi-definite
    if (compiled_.recursive()) return A.transpose() * (A * A.transpose()).ldlt().solve(r);
    compiled_.mass_and_forcing(t, q, qdot, parameters_, data_);
    const Eigen::LLT<Eigen::MatrixXd> llt(data_.mass_matrix);
    if (llt.info() != Eigen::Success) {
      return A.transpose() * (A * A.transpose()).completeOrthogonalDecomposition().solve(r);
    }
    const Eigen::MatrixXd MinvAt = llt.solve(A.transpose());
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(A * MinvAt);
    const double scale = ldlt.rows() ? ldlt.vectorD().cwiseAbs().maxCoeff() : 0.0;
    if (ldlt.info() == Eigen::Success && ldlt.vectorD().cwiseAbs().minCoeff() > 1e-12 * scale) {
      return MinvAt * ldlt.solve(r);
    }
    // dependent rows (redundant, a singular position): the least kinetic-energy correction with
    // A Δ = r by Gauss's principle with no forces, the minimum-norm multipliers
    return minimum_norm_solve(data_.mass_matrix, Eigen::VectorXd::Zero(q.size()), A, -r).qddot;
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

// The default method hands a run over to alf where A M⁻¹ Aᵀ's smallest pivot falls below this
// fraction of its diagonal (about 1e-3 rad from an N four-bar's aligned position).
constexpr double kNearSingularPosition = 1e-6;
// ... and takes it back where the pivot has risen above this on the other side.
constexpr double kSingularPositionPassed = 1e-4;

// What an index-1 method stopped at a singular position advises.
constexpr const char* kIndex3Advice =
    " (--method alf, which holds the positions themselves, passes it)";

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
  o.hand_over = !settings.method_chosen;
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
  if (!overrides.method.empty()) {
    o.method = overrides.method;
    o.hand_over = false;
  }
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

namespace {

// observed: T, U, the outputs, the conserved quantities, the stop_when expressions
constexpr std::size_t kOutputsBegin = 2;

// One run of simulate(): the state that its rows, its events and its summary share, and a
// member for each job — the start, the step loop, a row, an event, the summary.
class SimulationRun {
 public:
  SimulationRun(const System& system, const CompiledSystem& compiled, const SimulationStart& start,
                const SimulationOptions& options,
                const std::function<void(const std::vector<double>&)>& on_row)
      : system_(system),
        compiled_(compiled),
        start_(start),
        options_(options),
        on_row_(on_row),
        n_(static_cast<Eigen::Index>(compiled.coordinate_count())),
        parameters_(start.parameters),
        data_(compiled.make_data()),
        projector_(compiled, parameters_),
        contacts_(system, compiled, parameters_),
        observed_(compiled.observation_count()),
        conserved_begin_(kOutputsBegin + system.outputs.size()),
        stops_begin_(conserved_begin_ + system.conserved.size()),
        conserved_initial_(system.conserved.size()),
        previous_row_time_(start.t0),
        friction_(system, compiled, parameters_),
        impulses_(system, compiled, parameters_, start.t0),
        contact_events_(contacts_.event_count()),
        friction_events_(friction_.event_count()),
        impulse_events_(impulses_.event_count()),
        first_stop_(contact_events_ + friction_events_ + impulse_events_),
        stop_sign_(system.stop_when.size(), 1.0) {
    summary_.has_energy = has_energy_column(system);
    summary_.dependent_constraints = start.dependent_constraints;
    for (const auto& c : system.constraints) summary_.multipliers.push_back({c.name});
  }

  // The run: the integrator, the start, the step loop; then the summary, whatever stopped it.
  SimulationSummary run() {
    try {
      make_run_stepper();
      Eigen::VectorXd y0 = start_state();
      const IntegrationCallbacks callbacks = integration_callbacks(y0);
      const IntegrationResult result =
          integrate(*stepper_, start_.t0, y0, options_.t_end, options_.output_step, callbacks);
      take_result(result);
    } catch (const RowRefused& e) {
      summary_.ok = false;
      summary_.message = e.what();
      summary_.failure_time = e.t;
      if (stepper_) summary_.stats = stepper_->stats();
    } catch (const std::exception& e) {
      // the initial state itself cannot be solved (or its output row failed)
      summary_.ok = false;
      summary_.message = e.what();
      summary_.failure_time = start_.t0;
    }
    summarize_energy();
    summary_.dependent_solves = data_.dependent_solves;
    if (hand_over_ && hand_over_->hand_overs() > 0) {
      summary_.hand_over_time = hand_over_->hand_over_time();
      summary_.hand_over = hand_over_->reason();
      summary_.hand_overs = static_cast<std::size_t>(hand_over_->hand_overs());
      summary_.handed_back = hand_over_->hand_backs() == hand_over_->hand_overs();
    }
    return std::move(summary_);
  }

 private:
  // y = (q, q̇), y' = (q̇, q̈). Equations that are not finite at a state the integrator tries give
  // a derivative that is not finite: a Runge–Kutta step is rejected and shrunk, CVODE takes it as
  // a recoverable error and retries with a smaller step; why is said if the run fails all the
  // same.
  void derivative(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    const std::size_t dependent_before = data_.dependent_solves;
    try {
      compiled_.solve(t, y.head(n_), y.tail(n_), parameters_, qddot_, lambda_, data_);
    } catch (const NotFiniteState& e) {
      not_finite_ = e.what();
      dydt.setConstant(std::numeric_limits<double>::quiet_NaN());
      return;
    } catch (const ConstraintRankLoss&) {
      throw SingularPosition(
          singular_position(t, false),
          ": the index-1 equations of " + options_.method + " cannot go on there" + kIndex3Advice,
          t);
    }
    // the default method hands over before the last steps toward a singular position, where its
    // step shrinks and its accelerations lose their digits (dopri5 took 70 000 evaluations in
    // the last 1e-4 s before one of the N four-bar's)
    if (hand_over_ && start_.dependent_constraints.empty() &&
        data_.pivot_ratio < kNearSingularPosition) {
      throw SingularPosition("the constraints come near a singular position at t = " +
                                 detail::to_text(t) + " (A M⁻¹ Aᵀ's pivots " +
                                 detail::to_short_text(data_.pivot_ratio) + " of its diagonal)",
                             "", t);
    }
    // more rows dependent than at the start, or rows independent at the start within round-off of
    // losing rank (CVODE spent minutes there at N = 40, each evaluation on the SVD's path): a
    // singular position, whose branch the index-1 equations cannot tell
    const std::size_t dependent_at_start = start_.dependent_constraints.size();
    if (data_.dependent_solves != dependent_before &&
        (data_.rank_deficiency > dependent_at_start || dependent_at_start == 0)) {
      throw SingularPosition(singular_position(t, true),
                             ": the index-1 equations of " + options_.method +
                                 " cannot tell which branch the motion takes there" + kIndex3Advice,
                             t);
    }
    dydt.head(n_) = y.tail(n_);
    dydt.tail(n_) = qddot_;
  }

  // The projection onto the constraint manifolds of the constraints that hold.
  void project(double t, Eigen::VectorXd& y) {
    Eigen::VectorXd yq = y.head(n_), yv = y.tail(n_);
    projector_.project(t, yq, yv);
    y << yq, yv;
  }

  // The rank the constraints lost at t (a singular position), or their dependent rows'
  // disagreement, described.
  std::string singular_position(double t, bool consistent) const {
    const std::size_t rows = compiled_.constraint_count();
    const std::size_t independent = rows - data_.rank_deficiency;
    const std::size_t at_start = rows - start_.dependent_constraints.size();
    std::string what =
        independent == rows
            ? "the constraints come within round-off of losing rank at t = " + detail::to_text(t) +
                  " (A M⁻¹ Aᵀ's smallest pivot below 1e-12 of its diagonal: a singular position)"
        : independent < at_start
            ? "the constraints lose rank at t = " + detail::to_text(t) +
                  " (a singular position: " + std::to_string(independent) + " of their " +
                  std::to_string(rows) + " rows independent there, " + std::to_string(at_start) +
                  " at the start)"
            : "the constraints' dependent rows stop agreeing at t = " + detail::to_text(t) + " (" +
                  std::to_string(independent) + " of their " + std::to_string(rows) +
                  " rows independent, as at the start)";
    return consistent ? what : what + ", and no acceleration satisfies them all";
  }

  // The index-3 augmented Lagrangian method: position constraints that always hold only.
  std::unique_ptr<Stepper> make_index3_stepper() const {
    if (contacts_.any() || friction_events_ + impulse_events_ > 0) {
      throw std::invalid_argument(
          "--method alf holds bilateral position constraints; this model has contacts, rough "
          "contacts or impulses");
    }
    AugmentedLagrangianOptions o;
    o.step = fixed_step(options_);
    return std::make_unique<AugmentedLagrangian>(compiled_, start_.parameters, o);
  }

  // Whether alf, after `steps` steps since it took the run over, has passed the singular
  // position: A M⁻¹ Aᵀ's smallest pivot back above kSingularPositionPassed of its diagonal and
  // rising (not still on the way in), four steps at least.
  bool singular_position_passed(double t, const Eigen::VectorXd& y, int steps) {
    if (steps == 1) pivot_ratio_before_ = 0.0;
    try {
      compiled_.solve(t, y.head(n_), y.tail(n_), parameters_, qddot_, lambda_, data_);
    } catch (const std::exception&) {
      return false;
    }
    const double ratio = data_.pivot_ratio, before = std::exchange(pivot_ratio_before_, ratio);
    return steps >= 4 && ratio > kSingularPositionPassed && ratio > before;
  }

  // Whether the default method hands the run over to alf at a singular position: the method was
  // not chosen, and alf covers the model.
  bool hands_over() const {
    const auto& position = compiled_.is_position_constraint();
    return options_.hand_over && options_.method == "dopri5" && !position.empty() &&
           std::find(position.begin(), position.end(), false) == position.end() &&
           !contacts_.any() && friction_events_ + impulse_events_ == 0;
  }

  // The integrator the options ask for. RATTLE and alf keep the constraints themselves (a
  // projection would spoil RATTLE's symplecticity); CVODE projects inside its step; the others
  // after each step.
  void make_run_stepper() {
    project_ = options_.project && compiled_.constraint_count() > 0;
    inside_ = options_.method == "cvode";
    symplectic_ = options_.method.starts_with("rattle");
    if (options_.method == "alf") {
      stepper_ = make_index3_stepper();
      return;
    }
    if (symplectic_) {
      natural_.emplace(system_, kane_equations(system_));
      RattleOptions o;
      o.step = fixed_step(options_);
      o.order = options_.method == "rattle6" ? 6 : options_.method == "rattle4" ? 4 : 2;
      stepper_ = std::make_unique<Rattle>(*natural_, start_.parameters, o);
      return;
    }
    const OdeFunction rhs = [this](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
      derivative(t, y, dydt);
    };
    std::function<void(double, Eigen::VectorXd&)> projection;
    if (project_ && inside_) projection = [this](double t, Eigen::VectorXd& y) { project(t, y); };
    stepper_ = make_stepper(options_, rhs, projection);
    if (hands_over()) {
      auto hand_over = std::make_unique<HandOver>(
          std::move(stepper_), [this] { return make_index3_stepper(); },
          [this](double t, const Eigen::VectorXd& y, int steps) {
            return singular_position_passed(t, y, steps);
          });
      hand_over_ = hand_over.get();
      stepper_ = std::move(hand_over);
    }
  }

  // The start y0 = (q, q̇): the contacts that hold, onto the constraint manifolds, the rough
  // contacts sticking or slipping.
  Eigen::VectorXd start_state() {
    Eigen::VectorXd q = start_.q, qdot = start_.qdot;
    if (contacts_.any()) {
      // the contacts that hold at the start, then onto their manifolds with the rest
      projector_.set_active(contacts_.active());
      add_phases(start_.t0, contacts_.start(start_.t0, q, qdot));
      use_phase();
    }
    if (options_.project) summary_.initial_projection = projector_.project(start_.t0, q, qdot);
    if (friction_events_ > 0) add_phases(start_.t0, friction_.start(start_.t0, q, qdot, data_));
    Eigen::VectorXd y0(2 * n_);
    y0 << q, qdot;
    return y0;
  }

  // The step loop's callbacks: a row at each output time, the events (each stop_when armed by
  // its sign at the start), and after each step the signal, the Euler charts, the projection.
  IntegrationCallbacks integration_callbacks(const Eigen::VectorXd& y0) {
    IntegrationCallbacks callbacks;
    callbacks.output = [this](double t, const Eigen::VectorXd& y) { emit(t, y); };
    if (first_stop_ + stop_sign_.size() > 0) {
      arm_stops(y0);
      callbacks.events = [this](double t, const Eigen::VectorXd& y, Eigen::VectorXd& g) {
        event_values(t, y, g);
      };
      callbacks.on_event = [this](double t, Eigen::VectorXd& y, std::size_t which) {
        return on_event(t, y, which);
      };
    }
    callbacks.post_step = [this](double t, Eigen::VectorXd& y) {
      // a stiff run may take seconds between rows: a signal is looked at every step
      if (options_.interrupted && options_.interrupted()) {
        throw std::runtime_error("interrupted (a signal)");
      }
      watch_euler_charts(system_, t, y, summary_);
      if (project_ && !inside_ && !symplectic_ && stepper_->name() != "alf") project(t, y);
    };
    return callbacks;
  }

  // Each stop_when expression's sign at the start, so that its event is its crossing of 0.
  void arm_stops(const Eigen::VectorXd& y0) {
    Eigen::VectorXd g0;
    event_values(start_.t0, y0, g0);
    for (std::size_t s = 0; s < stop_sign_.size(); ++s) {
      const double value = g0[static_cast<Eigen::Index>(first_stop_ + s)];
      if (value == 0.0) {
        throw std::invalid_argument("stop_when '" + system_.stop_when[s].name +
                                    "' is 0 at the start");
      }
      stop_sign_[s] = value > 0 ? 1.0 : -1.0;
    }
  }

  // One output row at (t, y): solve for q̈ and λ, observe, account, check residuals, hand it on.
  void emit(double t, const Eigen::VectorXd& y) {
    const Eigen::VectorXd q = y.head(n_), qdot = y.tail(n_);
    solve_row(t, q, qdot);
    const double T = observed_[0], U = observed_[1], E = T + U;
    fill_row(t, q, qdot, E);
    if (summary_.rows == 0) record_first_row(E);
    summary_.energy_final = E;
    summary_.last_row_time = t;
    record_multipliers();
    energy_scale_ = std::max(energy_scale_, T + std::abs(U));
    add_friction_work(t);
    max_energy_error_ = std::max(max_energy_error_, std::abs(E - summary_.energy_initial));
    for (std::size_t c = 0; c < conserved_initial_.size(); ++c) {
      const double value = observed_[conserved_begin_ + c];
      summary_.conserved_drift[c].max_change =
          std::max(summary_.conserved_drift[c].max_change, std::abs(value - conserved_initial_[c]));
    }
    if (compiled_.constraint_count() > 0) record_residuals(t, q, qdot);
    // a row the caller cannot take (a full disk) ends the run there; the rows before it stay
    try {
      on_row_(row_);
    } catch (const std::exception& e) {
      throw RowRefused(t, e.what());
    }
    ++summary_.rows;
  }

  // q̈ and λ at a row, and what is observed there.
  void solve_row(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
    try {
      compiled_.solve(t, q, qdot, parameters_, qddot_, lambda_, data_);
    } catch (const NotFiniteState& e) {
      // the row's state, interpolated between steps, is off where the equations are finite
      throw RowRefused(t, std::string(e.what()) +
                              " (the state the integrator gives for this row is outside where the "
                              "equations are finite: a tighter --rtol keeps it inside)");
    }
    compiled_.observe(t, q, qdot, qddot_, lambda_, parameters_, observed_, data_);
  }

  // The row's columns: t, q, q̇, E (when the forces all have potentials), λ, the outputs and the
  // conserved quantities.
  void fill_row(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, double E) {
    row_.assign(1, t);
    row_.insert(row_.end(), q.data(), q.data() + n_);
    row_.insert(row_.end(), qdot.data(), qdot.data() + n_);
    if (summary_.has_energy) row_.push_back(E);
    row_.insert(row_.end(), lambda_.data(), lambda_.data() + lambda_.size());
    row_.insert(row_.end(), observed_.begin() + kOutputsBegin, observed_.begin() + stops_begin_);
  }

  // The first row's E0 and conserved values c0, from which the drifts are measured.
  void record_first_row(double E) {
    summary_.energy_initial = E;
    for (std::size_t c = 0; c < conserved_initial_.size(); ++c) {
      conserved_initial_[c] = observed_[conserved_begin_ + c];
      summary_.conserved_drift.push_back({system_.conserved[c].name, conserved_initial_[c], 0.0});
    }
  }

  // Each multiplier's range over the rows where its constraint holds.
  void record_multipliers() {
    for (std::size_t k = 0; k < summary_.multipliers.size(); ++k) {
      if (!contacts_.active()[k]) continue;
      auto& range = summary_.multipliers[k];
      const double value = lambda_[static_cast<Eigen::Index>(k)];
      range.min = range.held ? std::min(range.min, value) : value;
      range.max = range.held ? std::max(range.max, value) : value;
      range.held = true;
    }
  }

  // The friction's power R_t · v_slip, integrated over the rows by the trapezoidal rule.
  void add_friction_work(double t) {
    double friction_power = 0.0;
    for (std::size_t c = 0; c < data_.friction.size(); ++c) {
      const FrictionValues& f = data_.friction[c];
      friction_power += f.tangential_part(data_.contact_force[c]).dot(f.slip);
    }
    if (summary_.rows > 0) {
      friction_work_ += 0.5 * (friction_power + last_friction_power_) * (t - previous_row_time_);
    }
    last_friction_power_ = friction_power;
    previous_row_time_ = t;
  }

  // max |Ψ| and max |A q̇ + e| over the constraints that hold (a free unilateral one has Ψ > 0,
  // its rate anything).
  void record_residuals(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
    compiled_.constraints(t, q, qdot, parameters_, data_);
    const Eigen::VectorXd velocity_residual =
        data_.constraint_matrix * qdot + data_.constraint_velocity_term;
    for (std::size_t k = 0; k < compiled_.constraint_count(); ++k) {
      const auto K = static_cast<Eigen::Index>(k);
      if (!contacts_.active()[k]) continue;
      if (compiled_.is_position_constraint()[k]) {
        summary_.max_position_residual =
            std::max(summary_.max_position_residual, std::abs(data_.constraint_position[K]));
      }
      summary_.max_velocity_residual =
          std::max(summary_.max_velocity_residual, std::abs(velocity_residual[K]));
    }
  }

  // Event functions: the unilateral contacts', the rough contacts', the applied impulses' (at
  // their times), then each stop_when expression times its sign at the start.
  void event_values(double t, const Eigen::VectorXd& y, Eigen::VectorXd& g) {
    g.resize(static_cast<Eigen::Index>(first_stop_ + stop_sign_.size()));
    const Eigen::VectorXd q = y.head(n_), qdot = y.tail(n_);
    const std::size_t U = contact_events_, F = friction_events_, I = impulse_events_;
    if (U > 0) contacts_.events(t, q, qdot, std::span(g.data(), U));
    if (F > 0) friction_.events(t, q, qdot, data_, std::span(g.data() + U, F));
    if (I > 0) impulses_.events(t, std::span(g.data() + U + F, I));
    if (stop_sign_.empty()) return;
    compiled_.solve(t, q, qdot, parameters_, qddot_, lambda_, data_);
    compiled_.observe(t, q, qdot, qddot_, lambda_, parameters_, observed_, data_);
    for (std::size_t s = 0; s < stop_sign_.size(); ++s) {
      g[static_cast<Eigen::Index>(first_stop_ + s)] = stop_sign_[s] * observed_[stops_begin_ + s];
    }
  }

  // An event: a contact made or lost, a rough contact sticking or slipping, an impulse, or a stop.
  AfterEvent on_event(double t, Eigen::VectorXd& y, std::size_t which) {
    const std::size_t U = contact_events_, F = friction_events_;
    Eigen::VectorXd yq = y.head(n_), yv = y.tail(n_);
    if (which < U) {
      summary_.phases.push_back({t, contacts_.handle(t, yq, yv, which)});
      use_phase();
      y << yq, yv;
    } else if (which < U + F) {
      // a slip that only turned re-arms its event: a new start (the steps past it assumed the
      // old direction), without a row of its own
      std::vector<std::string> what = friction_.handle(t, yq, yv, which - U, data_);
      if (what.empty()) return AfterEvent::restart_quietly;
      add_phases(t, std::move(what));
    } else if (which < first_stop_) {
      // the rates jump; the rough contacts stick or slide from the new rates
      summary_.phases.push_back({t, impulses_.apply(t, yq, yv, which - U - F, contacts_.active())});
      add_phases(t, friction_.start(t, yq, yv, data_));
      y << yq, yv;
    } else {
      summary_.phases.push_back(
          {t, "stop_when '" + system_.stop_when[which - first_stop_].name + "' reached 0"});
      return AfterEvent::stop;
    }
    return AfterEvent::restart;
  }

  // The phase of the unilateral constraints, in the solver and the projector.
  void use_phase() {
    data_.active = contacts_.active();
    projector_.set_active(contacts_.active());
  }

  // Lines of what happened at t, into the summary's phases.
  void add_phases(double t, std::vector<std::string> lines) {
    for (auto& line : lines) summary_.phases.push_back({t, std::move(line)});
  }

  // What the step loop ended with: success, a stop, or a failure and why (near gimbal lock, or
  // where the equations were not finite).
  void take_result(const IntegrationResult& result) {
    summary_.ok = result.ok;
    summary_.stopped = result.stopped;
    summary_.event_rows = result.event_rows;
    summary_.message =
        result.ok ? result.message : failure_near_gimbal_lock(system_, result.y, result.message);
    if (!result.ok && !not_finite_.empty()) {
      summary_.message +=
          " (the equations were not finite at a state the integrator tried: " + not_finite_ + ")";
    }
    summary_.failure_time = result.t_failure;
    summary_.stats = result.stats;
  }

  // The energy's drift, and what changed it: the model's drive and impulses, the run's friction
  // and impacts.
  void summarize_energy() {
    summary_.energy_relative_drift = max_energy_error_ / std::max(energy_scale_, 1e-300);
    summary_.energy_not_conserved = energy_changed_by(system_);
    const std::string dissipated =
        dissipation_in_run(friction_work_, energy_scale_, contacts_.dissipative_impacts());
    if (!dissipated.empty()) {
      summary_.energy_not_conserved +=
          (summary_.energy_not_conserved.empty() ? "" : "; ") + dissipated;
    }
  }

  const System& system_;
  const CompiledSystem& compiled_;
  const SimulationStart& start_;
  const SimulationOptions& options_;
  const std::function<void(const std::vector<double>&)>& on_row_;
  const Eigen::Index n_;
  const std::span<const double> parameters_;
  SimulationSummary summary_;
  CompiledSystemData data_;
  Projector projector_;
  Contacts contacts_;
  // the solver's q̈ and λ, the observed values, the row handed on
  Eigen::VectorXd qddot_, lambda_;
  std::string not_finite_;
  std::vector<double> observed_;
  std::vector<double> row_;
  const std::size_t conserved_begin_, stops_begin_;
  // the rows' accounts: c0, E's scale and largest change, the friction's work
  std::vector<double> conserved_initial_;
  double energy_scale_ = 0.0, max_energy_error_ = 0.0;
  double friction_work_ = 0.0, last_friction_power_ = 0.0;
  double previous_row_time_;
  FrictionPhases friction_;
  AppliedImpulses impulses_;
  // the event functions: contacts, rough contacts, impulses, then the stop_when expressions
  const std::size_t contact_events_, friction_events_, impulse_events_, first_stop_;
  std::vector<double> stop_sign_;
  // how the run integrates: the stepper (with RATTLE's natural system), where it projects
  bool project_ = false, inside_ = false, symplectic_ = false;
  std::optional<CompiledNaturalSystem> natural_;
  std::unique_ptr<Stepper> stepper_;
  // the default method's hand-over to alf (in stepper_), when it may take place
  const HandOver* hand_over_ = nullptr;
  double pivot_ratio_before_ = 0.0;
};

}  // namespace

SimulationSummary simulate(const System& system, const CompiledSystem& compiled,
                           const SimulationStart& start, const SimulationOptions& options,
                           const std::function<void(const std::vector<double>&)>& on_row) {
  return SimulationRun(system, compiled, start, options, on_row).run();
}

}  // namespace unidyn
