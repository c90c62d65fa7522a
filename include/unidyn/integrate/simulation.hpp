// Simulating a system: integrate M q̈ = f + Aᵀλ, A q̈ + b = 0 with drift held by projection onto the
// position and velocity constraint manifolds after every step (DESIGN.md "Equations and numerics").
#pragma once

#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "unidyn/integrate/ode.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

struct SimulationOptions {
  double t_end = 10.0;
  double output_step = 0.01;
  // one of integration_method_names: dopri5 or dop853 (Dormand–Prince 5(4) or 8(5,3)), rk4, cvode
  // (BDF, for stiff models), rattle, rattle4, rattle6 (symplectic, natural conservative models) or
  // alf (index 3: position constraints through singular positions)
  std::string method = "dopri5";
  double rtol = 1e-10;
  double atol = 1e-12;
  double step = 0.0;  // rk4's, rattle's and alf's step; 0: output_step / 10
  // The method was not chosen (dopri5 by default): a run of a model with position constraints
  // that meets a singular position passes it with alf (integrate/hand_over.hpp), and says so.
  bool hand_over = false;
  bool project = true;
  std::size_t max_steps = 100000000;
  // Asked after every step (not only at rows): true ends the run there, "interrupted" (Ctrl-C).
  std::function<bool()> interrupted;
};

// The options a model file's `simulate:` asks for (atol no larger than rtol / 100).
SimulationOptions simulation_options(const SimulationSettings& settings);

// What a user sets for a run instead of the model's `simulate:` (0 or "": the model's own).
struct SimulationOverrides {
  double t_end = 0, output_step = 0, rtol = 0;
  std::string method;
};
// The model's options with the overrides (a tolerance given brings atol down to rtol / 100 at
// most). Throws std::invalid_argument for an unknown method or a run of more than 10^8 rows.
SimulationOptions simulation_options(const SimulationSettings& settings,
                                     const SimulationOverrides& overrides);

// The state of a system: parameters' values, q, q̇ at t0.
struct SimulationStart {
  std::vector<double> parameters;
  // Parameters defined by expressions that were computed anew from values given with --set
  // ("L2 = 6 from 2*L"), for the summary.
  std::vector<std::string> computed;
  Eigen::VectorXd q;
  Eigen::VectorXd qdot;
  double t0 = 0.0;
  // The constraints that depend on the others at the start (complete_initial_state: redundant
  // rows, or a singular configuration), by name.
  std::vector<std::string> dependent_constraints;
  // Which values were given (in initial: or with --set); the others may be computed from the
  // constraints (integrate/initial_state.hpp).
  std::vector<bool> q_given;
  std::vector<bool> qdot_given;
};

struct SimulationSummary {
  bool ok = true;
  std::string message;        // why a failed run stopped
  double failure_time = 0.0;  // where
  std::size_t rows = 0;
  // Of the rows, those at events between two output times.
  std::size_t event_rows = 0;
  bool has_energy = false;
  double energy_initial = 0.0;
  // E and t at the last row
  double energy_final = 0.0;
  double last_row_time = 0.0;
  // Why E = T + U is not a constant of the motion ("" when it is): "driven by t" (forces,
  // constraints or positions that depend on time), "dissipative: friction", "dissipative:
  // impacts with restitution < 1", "impulses applied" (joined by "; ").
  std::string energy_not_conserved;
  // max |E − E0| / max over the run of (T + |U|)
  double energy_relative_drift = 0.0;
  // max over rows of |Ψ| and of |A q̇ + e|
  double max_position_residual = 0.0;
  double max_velocity_residual = 0.0;
  // how far the given initial state was moved onto the constraint manifolds
  double initial_projection = 0.0;
  // the constraints that depend on the others at the start (SimulationStart), and how many
  // right-hand sides found the rows dependent (there: the minimum-norm multipliers)
  std::vector<std::string> dependent_constraints;
  std::size_t dependent_solves = 0;
  // The default method met singular positions and alf took the run through them (hand_overs
  // times): why and where the first time ("" when it did not).
  std::string hand_over;
  double hand_over_time = 0.0;
  std::size_t hand_overs = 0;
  bool handed_back = false;  // the default method took the run back after the last of them
  // per conserved quantity: its initial value c0 and max |c − c0| over the rows
  struct Drift {
    std::string name;
    double initial = 0.0;
    double max_change = 0.0;
  };
  std::vector<Drift> conserved_drift;
  // bodies described by Euler angles: the smallest |[g1, g2, g3]| met after a step, and when
  double closest_gimbal_lock = 1.0;
  double closest_gimbal_lock_time = 0.0;
  StepperStats stats;
  // Each constraint's multiplier over the rows where the constraint holds (a contact that
  // pulls, λ < 0, shows here).
  struct MultiplierRange {
    std::string name;
    double min = 0.0;
    double max = 0.0;
    bool held = false;  // whether it held at any row
  };
  std::vector<MultiplierRange> multipliers;
  // The phases: each contact's state at the start, then every event (contact lost or made, an
  // impact, a stop_when reached) at its time, in order.
  struct Phase {
    double t = 0.0;
    std::string what;
  };
  std::vector<Phase> phases;
  // stop_when ended the run (successfully) before t_end
  bool stopped = false;
};

// A run whose Euler angles come this close to gimbal lock (|[g1, g2, g3]| = |cos γ²| or |sin γ²|)
// stops, and a start this close is refused: the angles' rates grow like 1/|[g1, g2, g3]|, and a
// loose tolerance steps past the lock with a wrong motion (the falling bicycle at rtol 1e-6 came
// within 1.9e-6 and bounced back, its energy off by 2.5 %); a tight one stalls there. A motion
// that only passes near (the torque-free body's 3-2-1 angles, within 0.009) goes on.
inline constexpr double kGimbalLockStop = 1e-4;
// A run that fails (its step size collapsing) this close to gimbal lock is said to fail there.
inline constexpr double kGimbalLockNear = 1e-3;

// The CSV header: t, each q, each der(q), energy (when every force has a potential), one
// lambda(<constraint>) per constraint, then the model's outputs and conserved quantities.
std::vector<std::string> simulation_columns(const System& system);

// Runs the simulation; every row is handed to `on_row` as soon as it is computed (so a failed run
// keeps everything before the failure). Never throws for a failure of the run itself: the summary
// says why it stopped.
SimulationSummary simulate(const System& system, const CompiledSystem& compiled,
                           const SimulationStart& start, const SimulationOptions& options,
                           const std::function<void(const std::vector<double>&)>& on_row);

// Values of the parameters and the initial state of a model, with NAME=VALUE overrides applied to
// parameters, coordinates (q) and rates (der(q)). Throws std::invalid_argument for an unknown name.
// A body described by Euler angles must not be at their gimbal lock in q, where the angle rates of
// a given ω do not exist and the mass matrix is singular: std::invalid_argument (bad input)
// "body 'B' <state> at the gimbal lock of its ... Euler angles (...): <advice>, or describe its
// rotation with" the Euler set most regular at that rotation, or with Euler parameters. With
// `given` (which coordinates were given), a body whose angles are not all given is left for the
// check after they are computed from the constraints (complete_initial_state).
void expect_no_gimbal_lock(const System& system, const Eigen::VectorXd& q, const std::string& state,
                           const std::string& advice, const std::vector<bool>& given = {});

SimulationStart initial_state(const System& system,
                              const std::vector<std::pair<std::string, double>>& overrides);

}  // namespace unidyn
