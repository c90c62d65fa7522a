// Completing the initial state from the constraints: Newton on the free coordinates, then the
// free rates, each least-norm.
#include "unidyn/integrate/initial_state.hpp"

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "unidyn/integrate/simulation.hpp"
#include "unidyn/numeric/dependent_constraints.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// The coordinates that constraint row k involves (non-zero entries of its row of A), with a mark
// on those given.
std::string involved(const System& system, const Eigen::MatrixXd& A, Eigen::Index k,
                     const std::vector<bool>& given, const char* prefix, const char* suffix) {
  std::string list;
  for (Eigen::Index j = 0; j < A.cols(); ++j) {
    if (A(k, j) == 0.0) continue;
    list += (list.empty() ? "" : ", ") + std::string(prefix) +
            system.coordinates()[static_cast<std::size_t>(j)].name + suffix +
            (given[static_cast<std::size_t>(j)] ? " (given)" : "");
  }
  return list.empty() ? "none" : list;
}

// The indices where flags are false.
std::vector<Eigen::Index> free_indices(const std::vector<bool>& given) {
  std::vector<Eigen::Index> free;
  for (std::size_t i = 0; i < given.size(); ++i) {
    if (!given[i]) free.push_back(static_cast<Eigen::Index>(i));
  }
  return free;
}

// The worst row of `residual` over `rows` as relative_residual measures it (gradients the rows of
// A, sizes from `values`): its index and that fraction.
std::pair<Eigen::Index, double> worst_relative(const Eigen::VectorXd& residual,
                                               const Eigen::MatrixXd& A,
                                               const std::vector<Eigen::Index>& rows,
                                               const Eigen::VectorXd& values) {
  std::pair<Eigen::Index, double> w{-1, 0.0};
  for (const Eigen::Index k : rows) {
    const double r = relative_residual(residual[k], A.row(k), values);
    if (r > w.second) w = {k, r};
  }
  return w;
}

// The worst row of `residual` over `rows`: its index and |value|.
std::pair<Eigen::Index, double> worst(const Eigen::VectorXd& residual,
                                      const std::vector<Eigen::Index>& rows) {
  std::pair<Eigen::Index, double> w{-1, 0.0};
  for (const Eigen::Index k : rows) {
    if (std::abs(residual[k]) > w.second) w = {k, std::abs(residual[k])};
  }
  return w;
}

// The position constraints' residuals beyond the tolerance over `rows`: "'rope1' (Psi = 0.05),
// 'rope2' (Psi = -0.05)".
std::string residuals_text(const System& system, const Eigen::VectorXd& psi,
                           const Eigen::MatrixXd& A, const std::vector<Eigen::Index>& rows,
                           const Eigen::VectorXd& q) {
  std::string out;
  for (const Eigen::Index k : rows) {
    if (relative_residual(psi[k], A.row(k), q) <= kConstraintTolerance) continue;
    out += (out.empty() ? "'" : ", '") + system.constraints[static_cast<std::size_t>(k)].name +
           "' (Psi = " + detail::to_short_text(psi[k]) + ")";
  }
  return out;
}

// Newton's method on Ψ_P(q) = 0 over the free coordinates, least-norm (Gauss–Newton) steps, into
// start.q; data holds the constraints there. Throws InitialStateError: the values given violate a
// constraint with nothing free to change it; they contradict the constraints (the steps reach the
// best fit, Jᵀ Ψ = 0, with Ψ ≠ 0: every constraint left unsatisfied named); the free coordinates
// cannot change it (gradient 0); Newton does not converge.
void complete_positions(const System& system, const CompiledSystem& compiled,
                        SimulationStart& start, const std::vector<Eigen::Index>& position_rows,
                        const std::vector<Eigen::Index>& free_q, CompiledSystemData& data) {
  const std::span<const double> p(start.parameters);
  const auto position_failure = [&](const std::string& why) {
    const auto [k, r] = worst(data.constraint_position, position_rows);
    throw InitialStateError(
        "the initial state cannot satisfy constraint '" +
        system.constraints[static_cast<std::size_t>(k)].name +
        "' (Psi = " + detail::to_short_text(data.constraint_position[k]) + ", coordinates " +
        involved(system, data.constraint_matrix, k, start.q_given, "", "") + "): " + why);
  };
  for (int iteration = 0;; ++iteration) {
    // the residual as the one tolerance measures it (a distance, relative to the state's size):
    // at round-off Newton is done; within the tolerance the values typed are taken as they are
    const double relative =
        worst_relative(data.constraint_position, data.constraint_matrix, position_rows, start.q)
            .second;
    if (relative <= 1e-15) break;
    const bool holds = relative <= kConstraintTolerance;
    if (free_q.empty()) {
      if (holds) break;
      position_failure(
          "the values given violate it; leave a coordinate it involves out of "
          "initial: (and --set) to have it computed, or use --project");
    }
    const Eigen::MatrixXd J = data.constraint_matrix(position_rows, free_q);
    const Eigen::VectorXd psi = data.constraint_position(position_rows);
    // the best fit reached, and it leaves residuals: the values given contradict the constraints
    if (!holds && iteration > 0 && (J.transpose() * psi).norm() <= 1e-10 * J.norm() * psi.norm()) {
      throw InitialStateError(
          "the values given contradict the constraints: no values of the coordinates not given "
          "satisfy " +
          residuals_text(system, data.constraint_position, data.constraint_matrix, position_rows,
                         start.q) +
          " together (the residuals of the best fit); change or leave out one of the values "
          "given that they involve");
    }
    if (iteration == 50) {
      if (holds) break;
      position_failure("Newton's method over the coordinates not given does not converge");
    }
    const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> decomposition(J);
    const Eigen::VectorXd step = decomposition.solve(psi);
    if (!step.allFinite() || step.norm() == 0.0) {
      if (holds) break;
      position_failure(
          "the coordinates not given cannot change it here (its gradient in them "
          "is 0); give them values");
    }
    for (std::size_t j = 0; j < free_q.size(); ++j) {
      start.q[free_q[j]] -= step[static_cast<Eigen::Index>(j)];
    }
    compiled.constraints(start.t0, start.q, start.qdot, p, data);
  }
}

// Whether the compiled equations and constraints are the same at q and at q with coordinate j
// moved by `shift` (to 1e-9 of their size): an angle moved by whole turns.
bool same_after_shift(const CompiledSystem& compiled, const SimulationStart& start, Eigen::Index j,
                      double shift) {
  std::vector<double> inputs{start.t0};
  inputs.insert(inputs.end(), start.q.begin(), start.q.end());
  inputs.insert(inputs.end(), start.qdot.begin(), start.qdot.end());
  inputs.insert(inputs.end(), start.parameters.begin(), start.parameters.end());
  for (const Tape* tape : {&compiled.dynamics(), &compiled.constraint_tape()}) {
    const std::vector<double> here = tape->evaluate(inputs);
    std::vector<double> moved_inputs = inputs;
    moved_inputs[static_cast<std::size_t>(1 + j)] += shift;
    const std::vector<double> there = tape->evaluate(moved_inputs);
    double scale = 1.0;
    for (const double v : here) scale = std::max(scale, std::abs(v));
    for (std::size_t k = 0; k < here.size(); ++k) {
      if (!(std::abs(here[k] - there[k]) <= 1e-9 * scale)) return false;
    }
  }
  return true;
}

// The free coordinates Newton took more than half a turn from where they started (the model's
// value, or 0) moved back by whole turns to the value nearest it, where the equations and the
// constraints repeat after 2π in them (angles): a closed loop's angles computed from far away come
// out in the configuration found, not 31 turns on. data holds the constraints at start.q. Returns
// whether any moved.
bool nearest_turns(const CompiledSystem& compiled, SimulationStart& start,
                   const std::vector<Eigen::Index>& free_q, const Eigen::VectorXd& from,
                   CompiledSystemData& data) {
  constexpr double turn = 2.0 * std::numbers::pi;
  bool moved = false;
  for (const Eigen::Index j : free_q) {
    const double turns = std::round((start.q[j] - from[j]) / turn);
    if (turns == 0.0 || !same_after_shift(compiled, start, j, -turns * turn)) continue;
    start.q[j] -= turns * turn;
    moved = true;
  }
  if (moved) compiled.constraints(start.t0, start.q, start.qdot, start.parameters, data);
  return moved;
}

// The rates: A_R q̇ + e_R = 0 over the free rates, least norm, into start.qdot (data holds the
// constraints at start.q). Throws InitialStateError: the rates given violate a constraint.
void complete_rates(const System& system, SimulationStart& start,
                    const std::vector<Eigen::Index>& rows, const std::vector<Eigen::Index>& free_v,
                    const CompiledSystemData& data) {
  Eigen::VectorXd velocity = data.constraint_matrix * start.qdot + data.constraint_velocity_term;
  const double scale = 1.0 + start.qdot.cwiseAbs().maxCoeff();
  // (a residual at round-off needs no correction)
  if (!free_v.empty() && worst(velocity, rows).second > 1e-14 * scale) {
    const Eigen::MatrixXd A = data.constraint_matrix(rows, free_v);
    const Eigen::VectorXd step =
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(A).solve(velocity(rows));
    for (std::size_t j = 0; j < free_v.size(); ++j) {
      start.qdot[free_v[j]] -= step[static_cast<Eigen::Index>(j)];
    }
    velocity = data.constraint_matrix * start.qdot + data.constraint_velocity_term;
  }
  if (const auto [k, r] = worst_relative(velocity, data.constraint_matrix, rows, start.qdot);
      r > kConstraintTolerance) {
    throw InitialStateError(
        "the initial rates cannot satisfy constraint '" +
        system.constraints[static_cast<std::size_t>(k)].name +
        "' (A q' + e = " + detail::to_short_text(velocity[k]) + ", rates " +
        involved(system, data.constraint_matrix, k, start.qdot_given, "der(", ")") +
        "): the rates given violate it; leave one of them out of initial: (and --set) to have it "
        "computed, or use --project");
  }
}

// The rows that hold and depend on those before them there (a redundant constraint, or a singular
// configuration), by name. Accepted — the accelerations are unique and the multipliers the
// minimum-norm ones (numeric/dependent_constraints.hpp) — and said.
std::vector<std::string> dependent_constraints(const System& system,
                                               const std::vector<Eigen::Index>& rows,
                                               const CompiledSystemData& data) {
  std::vector<std::string> dependent;
  for (const Eigen::Index k : dependent_rows(data.constraint_matrix(rows, Eigen::all))) {
    dependent.push_back(system.constraints[static_cast<std::size_t>(rows[k])].name);
  }
  return dependent;
}

// Unilateral contacts: apart or touching, not inside.
void expect_not_inside(const System& system, const Eigen::VectorXd& q,
                       const CompiledSystemData& data) {
  for (Eigen::Index K = 0; K < data.constraint_position.size(); ++K) {
    const auto k = static_cast<std::size_t>(K);
    if (!system.constraints[k].unilateral) continue;
    if (data.constraint_position[K] < 0.0 &&
        relative_residual(data.constraint_position[K], data.constraint_matrix.row(K), q) >
            kConstraintTolerance) {
      throw InitialStateError("the initial state is inside the unilateral contact '" +
                              system.constraints[k].name +
                              "' (Psi = " + detail::to_short_text(data.constraint_position[K]) +
                              " < 0): start it apart or touching");
    }
  }
}

// What was computed: "x = 0.5", "der(y) = -1".
std::vector<std::string> computed_values(const System& system, const SimulationStart& start,
                                         const std::vector<Eigen::Index>& free_q,
                                         const std::vector<Eigen::Index>& free_v,
                                         const Eigen::VectorXd& q_given_values) {
  std::vector<std::string> computed;
  const auto& q = system.coordinates();
  for (const Eigen::Index j : free_q) {
    if (start.q[j] != q_given_values[j]) {
      computed.push_back(q[j].name + " = " + detail::to_short_text(start.q[j]));
    }
  }
  for (const Eigen::Index j : free_v) {
    if (start.qdot[j] != 0.0) {
      computed.push_back("der(" + q[j].name + ") = " + detail::to_short_text(start.qdot[j]));
    }
  }
  return computed;
}

}  // namespace

double relative_residual(double residual, const Eigen::Ref<const Eigen::RowVectorXd>& gradient,
                         const Eigen::VectorXd& values) {
  const double size = values.size() == 0 ? 0.0 : values.cwiseAbs().maxCoeff();
  const double length = gradient.norm();
  return std::abs(residual) / (length > 0.0 ? length : 1.0) / (size > 0.0 ? size : 1.0);
}

void apply_initial_angular_velocities(const System& system, SimulationStart& start) {
  if (system.initial_omegas.empty()) return;
  // the state: parameters, t0, q; rates 0 (ω is linear in them)
  GiNaC::exmap state;
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    state[system.parameters[k].symbol] = start.parameters[k];
  }
  state[system.time()] = start.t0;
  const auto& q = system.coordinates();
  for (std::size_t j = 0; j < q.size(); ++j) {
    state[q[j].value] = start.q[static_cast<Eigen::Index>(j)];
    state[q[j].rate] = 0;
  }
  const auto value = [&](const Expr& e, const std::string& body) {
    const auto v = real_value(e, state);
    if (!v) throw InitialStateError("cannot evaluate the angular velocity of '" + body + "'");
    return *v;
  };
  for (const InitialOmega& given : system.initial_omegas) {
    const Body& body = system.bodies[given.body];
    const VectorExpr w = given.body_frame ? system.body_angular_velocity(given.body)
                                          : system.angular_velocity(given.body);
    const auto n = static_cast<Eigen::Index>(given.coordinates.size());
    Eigen::MatrixXd W(3, n);
    Eigen::Vector3d target;
    for (int i = 0; i < 3; ++i) {
      for (Eigen::Index j = 0; j < n; ++j) {
        W(i, j) = value(derivative(w[i], q[given.coordinates[static_cast<std::size_t>(j)]].rate),
                        body.name);
      }
      target[i] = value(given.omega[i], body.name) - value(w[i], body.name);
    }
    const Eigen::VectorXd rates =
        Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd>(W).solve(target);
    if ((W * rates - target).norm() > 1e-10 * (1.0 + target.norm())) {
      throw InitialStateError("the rates of body '" + body.name +
                              "' cannot give it the angular velocity asked for at its start (at "
                              "the gimbal lock of its Euler angles?)");
    }
    for (Eigen::Index j = 0; j < n; ++j) {
      start.qdot[static_cast<Eigen::Index>(given.coordinates[static_cast<std::size_t>(j)])] =
          rates[j];
    }
  }
}

std::vector<std::string> complete_initial_state(const System& system,
                                                const CompiledSystem& compiled,
                                                SimulationStart& start) {
  const std::size_t m = compiled.constraint_count();
  if (m == 0) {
    expect_no_gimbal_lock(system, start.q, "starts", "start it elsewhere");
    return {};
  }
  const std::span<const double> p(start.parameters);
  CompiledSystemData data = compiled.make_data();
  const Eigen::VectorXd q_given_values = start.q;
  compiled.constraints(start.t0, start.q, start.qdot, p, data);

  // The rows that hold: the bilateral position constraints (for q), and every bilateral one
  // (for q̇); a unilateral contact must not start inside.
  std::vector<Eigen::Index> position_rows, rows;
  for (std::size_t k = 0; k < m; ++k) {
    const auto K = static_cast<Eigen::Index>(k);
    if (system.constraints[k].unilateral) continue;
    rows.push_back(K);
    if (compiled.is_position_constraint()[k]) position_rows.push_back(K);
  }

  // Positions: Newton's method on Ψ_P(q) = 0 over the free coordinates, least-norm steps; angles
  // computed then taken the whole turns back to the value they started from.
  const std::vector<Eigen::Index> free_q = free_indices(start.q_given);
  complete_positions(system, compiled, start, position_rows, free_q, data);
  if (nearest_turns(compiled, start, free_q, q_given_values, data)) {
    // converged again where the turns put it (far out, the angle kept only 1e-10 of a turn)
    complete_positions(system, compiled, start, position_rows, free_q, data);
  }

  // Rates: A_R q̇ + e_R = 0 over the free rates, least norm.
  const std::vector<Eigen::Index> free_v = free_indices(start.qdot_given);
  complete_rates(system, start, rows, free_v, data);

  // The state reached: the rows that depend on the others named, no contact inside, clear of
  // gimbal lock.
  start.dependent_constraints = dependent_constraints(system, rows, data);
  expect_not_inside(system, start.q, data);
  std::vector<std::string> computed =
      computed_values(system, start, free_q, free_v, q_given_values);
  // the Euler angles computed too must be clear of gimbal lock
  expect_no_gimbal_lock(system, start.q, "starts", "start it elsewhere");
  return computed;
}

bool gives_eliminated_values(const System& full, const SimulationStart& full_start,
                             const System& reduced) {
  const auto& q = full.coordinates();
  for (std::size_t j = 0; j < q.size(); ++j) {
    const bool eliminated = !reduced.find_coordinate(q[j].name);
    if (eliminated && (full_start.q_given[j] || full_start.qdot_given[j])) return true;
  }
  return false;
}

SimulationStart restricted_start(const System& full, const SimulationStart& full_start,
                                 const System& reduced) {
  SimulationStart start;
  start.parameters = full_start.parameters;
  start.computed = full_start.computed;
  start.t0 = full_start.t0;
  const auto& q = reduced.coordinates();
  start.q.resize(static_cast<Eigen::Index>(q.size()));
  start.qdot.resize(static_cast<Eigen::Index>(q.size()));
  for (std::size_t j = 0; j < q.size(); ++j) {
    const auto from = static_cast<Eigen::Index>(*full.find_coordinate(q[j].name));
    start.q[static_cast<Eigen::Index>(j)] = full_start.q[from];
    start.qdot[static_cast<Eigen::Index>(j)] = full_start.qdot[from];
  }
  start.q_given.assign(q.size(), true);
  start.qdot_given.assign(q.size(), true);
  return start;
}

}  // namespace unidyn
