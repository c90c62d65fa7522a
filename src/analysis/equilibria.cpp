// Equilibria and steady motions by multi-start Gauss–Newton, deduplicated and classified.
#include "unidyn/analysis/equilibria.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "configuration_key.hpp"
#include "energy_minimum.hpp"
#include "steady_balance.hpp"
#include "tape_derivatives.hpp"
#include "unidyn/analysis/time_dependence.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kTwoPi = 2 * std::numbers::pi;

// The residual's size relative to the forces at play: f's and Aᵀλ's, and Ψ's own.
double scaled_norm(const VectorXd& r, double scale) {
  return r.cwiseAbs().maxCoeff() / scale;
}

// Gauss–Newton from x (the unknowns, λ = 0); the solution, if it converges: a residual below
// 1e-10 of `scale` (the forces at the model's own initial state, at least 1) and a Newton step
// there below 1e-8 of the unknowns other than λ. A force that only fades, as gravitation does far
// away, gives steps that grow instead: no equilibrium at infinity.
std::optional<VectorXd> solve_from(const SteadyBalance& balance, VectorXd x, double scale) {
  const Index motion = balance.motion_unknowns();
  MatrixXd J;
  VectorXd r = balance.residual(x, &J);
  const auto largest = [](const VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; };
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (!r.allFinite()) return std::nullopt;
    const VectorXd step = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(J).solve(-r);
    if (!step.allFinite()) return std::nullopt;
    if (largest(r) <= 1e-10 * scale &&
        largest(step.head(motion)) <= 1e-8 * (1.0 + largest(x.head(motion)))) {
      // polished to round-off: full steps while they make the residual smaller
      VectorXd step_here = step;
      for (int polish = 0; polish < 3; ++polish) {
        const VectorXd x_next = x + step_here;
        const VectorXd r_next = balance.residual(x_next, &J);
        if (!r_next.allFinite() || !(largest(r_next) < largest(r))) break;
        x = x_next;
        r = r_next;
        step_here = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(J).solve(-r);
      }
      return x;
    }
    // backtracking: halve the step until the residual shrinks
    double size = 1.0;
    for (;; size /= 2) {
      if (size < 1e-6) return std::nullopt;
      const VectorXd x_try = x + size * step;
      const VectorXd r_try = balance.residual(x_try);
      if (r_try.allFinite() && scaled_norm(r_try, scale) < scaled_norm(r, scale)) {
        x = x_try;
        break;
      }
    }
    r = balance.residual(x, &J);
  }
  return std::nullopt;
}

// x in (−π, π] (−π and what the solution's accuracy leaves next to it as π).
double wrapped(double x) {
  const double w = std::remainder(x, kTwoPi);
  return w <= -std::numbers::pi + 1e-9 ? w + kTwoPi : w;
}

// Whether the balance is 2π-periodic in coordinate i (at a point, to round-off): an angle.
bool is_angle(const SteadyBalance& balance, VectorXd q, Index i) {
  const VectorXd r = balance.residual(balance.unknowns_at(q));
  q[i] += kTwoPi;
  const VectorXd shifted = balance.residual(balance.unknowns_at(q));
  return (r - shifted).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + r.cwiseAbs().maxCoeff());
}

// The momenta p = ∂T/∂q̇ of the cyclic coordinates, as a tape of inputs [t, q, q̇, p].
Tape momentum_tape(const System& system, const std::vector<Index>& cyclic) {
  const Expr T = system.kinetic_energy();
  std::vector<GiNaC::ex> momenta;
  for (const Index i : cyclic) {
    momenta.push_back(derivative(T, system.coordinates()[static_cast<std::size_t>(i)].rate));
  }
  return Tape::compile(momenta, tape_inputs(system, false));
}

// The values given, held during the search: coordinates and rates (0 when not given; a
// coordinate not given starts at the model's initial value), and the momenta of cyclic ones.
struct GivenState {
  VectorXd q, qdot;
  std::vector<bool> q_given, rate_given;
  std::vector<std::optional<double>> momentum;
};

GivenState given_state(const System& system, const std::vector<GivenValue>& given,
                       const std::vector<double>& parameters, const std::vector<Index>& cyclic) {
  const auto n = static_cast<Index>(system.coordinates().size());
  const auto name_of = [&](Index i) -> const std::string& {
    return system.coordinates()[static_cast<std::size_t>(i)].name;
  };
  const auto is_cyclic = [&](Index i) {
    return std::find(cyclic.begin(), cyclic.end(), i) != cyclic.end();
  };
  const GiNaC::exmap values = system.parameter_values(parameters);
  GivenState out{VectorXd::Zero(n), VectorXd::Zero(n),
                 std::vector<bool>(static_cast<std::size_t>(n), false),
                 std::vector<bool>(static_cast<std::size_t>(n), false),
                 std::vector<std::optional<double>>(static_cast<std::size_t>(n))};
  for (const GivenValue& g : given) {
    const std::optional<double> v = real_value(g.value, values);
    if (!v) throw std::invalid_argument("--at " + g.name + ": not a real number");
    if (const auto i = momentum_coordinate(system, g.name)) {
      if (!is_cyclic(static_cast<Index>(*i))) {
        throw std::invalid_argument("--at " + g.name +
                                    ": a momentum is given only for a cyclic coordinate (say "
                                    "--cyclic " +
                                    name_of(static_cast<Index>(*i)) + ")");
      }
      out.momentum[*i] = *v;
      continue;
    }
    const auto [coordinate, rate] = *state_value(system, g.name);
    (rate ? out.qdot : out.q)[static_cast<Index>(coordinate)] = *v;
    (rate ? out.rate_given : out.q_given)[coordinate] = true;
  }
  for (const Index i : cyclic) {
    if (out.momentum[static_cast<std::size_t>(i)] && out.rate_given[static_cast<std::size_t>(i)]) {
      throw std::invalid_argument("--at gives both der(" + name_of(i) + ") and p(" + name_of(i) +
                                  "): give one");
    }
  }
  for (Index i = 0; i < n; ++i) {
    if (!out.q_given[static_cast<std::size_t>(i)]) {
      out.q[i] =
          real_value(system.initial_values[static_cast<std::size_t>(i)], values).value_or(0.0);
    }
  }
  return out;
}

// The balance's unknowns: the coordinates neither given nor cyclic; a cyclic coordinate's rate
// when its momentum is given or, not given, when a constraint involves it (then its acceleration
// too, where it appears nowhere else); the other rates stay as given (0).
void choose_unknowns(SteadyBalance& balance, const GivenState& held,
                     const std::vector<Index>& cyclic) {
  const CompiledSystem& compiled = balance.compiled;
  const auto n = static_cast<Index>(compiled.coordinate_count());
  const auto m = static_cast<Index>(compiled.constraint_count());
  for (Index i = 0; i < n; ++i) {
    if (!held.q_given[static_cast<std::size_t>(i)] &&
        std::find(cyclic.begin(), cyclic.end(), i) == cyclic.end()) {
      balance.free_q.push_back(i);
    }
  }
  const std::vector<double> inputs0 = tape_inputs_at(0.0, held.q, held.qdot, balance.parameters);
  const std::vector<double> constraints0 = compiled.constraint_tape().evaluate(inputs0);
  std::vector<double> given_momenta;
  for (std::size_t k = 0; k < cyclic.size(); ++k) {
    const Index i = cyclic[k];
    if (const auto p = held.momentum[static_cast<std::size_t>(i)]) {
      balance.free_rate.push_back(i);
      balance.momentum_given.push_back(static_cast<Index>(k));
      given_momenta.push_back(*p);
      continue;
    }
    if (held.rate_given[static_cast<std::size_t>(i)]) continue;
    bool constrained = false;
    for (Index c = 0; c < m; ++c) constrained = constrained || constraints0[c * n + i] != 0.0;
    if (!constrained) continue;
    balance.free_rate.push_back(i);
    // whether the equations depend on the coordinate at the start
    const auto nowhere = [&](const Tape& tape) {
      return derivatives(tape, inputs0, 1 + i, 1).derivative.isZero(0.0);
    };
    if (nowhere(compiled.dynamics()) && nowhere(compiled.constraint_tape())) {
      balance.free_acceleration.push_back(i);
    }
  }
  balance.momentum_value =
      Eigen::Map<const VectorXd>(given_momenta.data(), static_cast<Index>(given_momenta.size()));
}

// The coordinates of each body's Euler parameters (those of a unit-norm constraint).
std::vector<std::vector<Index>> euler_parameter_groups(const System& system) {
  std::vector<std::vector<Index>> groups;
  for (const Constraint& c : system.constraints) {
    if (!c.parametrisation) continue;
    groups.emplace_back();
    for (std::size_t i = 0; i < system.coordinates().size(); ++i) {
      if (c.expression.has(system.coordinates()[i].value)) {
        groups.back().push_back(static_cast<Index>(i));
      }
    }
  }
  return groups;
}

// The coordinates --cyclic names, each once.
std::vector<Index> cyclic_coordinates(const System& system, const std::vector<std::string>& names) {
  std::vector<Index> cyclic;
  for (const std::string& name : names) {
    const auto i = system.find_coordinate(name);
    if (!i) throw std::invalid_argument("--cyclic " + name + ": not a coordinate");
    if (std::find(cyclic.begin(), cyclic.end(), static_cast<Index>(*i)) != cyclic.end()) {
      throw std::invalid_argument("--cyclic names " + name + " twice");
    }
    cyclic.push_back(static_cast<Index>(*i));
  }
  return cyclic;
}

// Where each start puts the free coordinates: angles anywhere on the circle, others near the
// model's value, Euler parameters a rotation drawn uniformly; and the form a solution is listed
// in (angles in (−π, π], Euler parameters with the first that is not 0 positive).
class StartingPoints {
 public:
  StartingPoints(const System& system, const SteadyBalance& balance, const VectorXd& initial,
                 unsigned seed)
      : balance_(balance),
        initial_(initial),
        spread_(VectorXd::Zero(initial.size())),
        angle_(static_cast<std::size_t>(initial.size()), false),
        quaternions_(euler_parameter_groups(system)),
        random_(seed) {
    for (const Index i : balance.free_q) {
      angle_[static_cast<std::size_t>(i)] = is_angle(balance, initial, i);
      spread_[i] = 2.0 * (1.0 + std::abs(initial[i]));
    }
  }

  // Whether free coordinate i is an angle.
  bool angle(Index i) const { return angle_[static_cast<std::size_t>(i)]; }

  // The next start's coordinates.
  VectorXd draw() {
    VectorXd q = initial_;
    for (const Index i : balance_.free_q) {
      q[i] =
          angle(i) ? std::numbers::pi * unit_(random_) : initial_[i] + spread_[i] * unit_(random_);
    }
    // Euler parameters: a rotation drawn uniformly (a normal 4-vector, normalised), where free
    for (const std::vector<Index>& group : quaternions_) {
      double norm = 0.0;
      for (const Index i : group) {
        q[i] = normal_(random_);
        norm += q[i] * q[i];
      }
      for (const Index i : group) q[i] = is_free(i) ? q[i] / std::sqrt(norm) : initial_[i];
    }
    return q;
  }

  // A solution in the form it is listed in.
  void canonical(SteadyBalance::State& x) const {
    for (const Index i : balance_.free_q) {
      if (angle(i)) x.q[i] = wrapped(x.q[i]);
    }
    // Euler parameters e and −e are one rotation: the first that is not 0 made positive
    for (const std::vector<Index>& group : quaternions_) {
      const auto first = std::find_if(group.begin(), group.end(),
                                      [&](Index i) { return std::abs(x.q[i]) > 1e-6; });
      if (first != group.end() && x.q[*first] < 0) {
        for (const Index i : group) x.q[i] = -x.q[i];
      }
    }
  }

 private:
  bool is_free(Index i) const {
    return std::find(balance_.free_q.begin(), balance_.free_q.end(), i) != balance_.free_q.end();
  }

  const SteadyBalance& balance_;
  const VectorXd& initial_;
  VectorXd spread_;
  std::vector<bool> angle_;
  std::vector<std::vector<Index>> quaternions_;
  std::mt19937 random_;
  std::uniform_real_distribution<double> unit_{-1.0, 1.0};
  std::normal_distribution<double> normal_{0.0, 1.0};
};

// The state a solution x stands for, as values for operating_point: every coordinate given, the
// rates as given or solved for.
std::vector<GivenValue> state_given(const System& system, const std::vector<GivenValue>& given,
                                    const SteadyBalance& balance, const SteadyBalance::State& x) {
  const auto name_of = [&](Index i) -> const std::string& {
    return system.coordinates()[static_cast<std::size_t>(i)].name;
  };
  std::vector<GivenValue> at;
  for (Index i = 0; i < x.q.size(); ++i) at.push_back({name_of(i), given_number(x.q[i])});
  for (const GivenValue& g : given) {
    const auto value = state_value(system, g.name);
    if (value && value->rate) at.push_back(g);
  }
  for (const Index i : balance.free_rate) {
    at.push_back({"der(" + name_of(i) + ")", given_number(x.qdot[i])});
  }
  return at;
}

// Whether coordinate i of e's is ignorable.
bool is_ignorable(const System& system, const Equilibrium& e, Index i) {
  const auto& ignorable = e.linearization.ignorable;
  return std::find(ignorable.begin(), ignorable.end(),
                   system.coordinates()[static_cast<std::size_t>(i)].name) != ignorable.end();
}

// Whether e is one found already: angles modulo 2π; ignorable coordinates, and the dependent ones
// that move with them (an unbalanced rotor's centre turning with it), aside.
bool found_already(const System& system, const SteadyBalance& balance, const StartingPoints& starts,
                   const Equilibrium& e, const std::vector<Equilibrium>& found) {
  const auto n = static_cast<Index>(balance.compiled.coordinate_count());
  const MatrixXd moves =
      e.linearization.to_coordinates.topRows(n)(Eigen::all, e.linearization.dropped);
  const auto aside = [&](Index i) {
    return is_ignorable(system, e, i) ||
           (moves.cols() > 0 && moves.row(i).cwiseAbs().maxCoeff() > 1e-9);
  };
  const auto same = [&](const Equilibrium& other) {
    for (const Index i : balance.free_q) {
      if (aside(i)) continue;
      double d = e.point.q[i] - other.point.q[i];
      if (starts.angle(i)) d = wrapped(d);
      if (std::abs(d) > 1e-6 * (1.0 + std::abs(e.point.q[i]))) return false;
    }
    for (const Index i : balance.free_rate) {
      const double d = e.point.qdot[i] - other.point.qdot[i];
      if (std::abs(d) > 1e-6 * (1.0 + std::abs(e.point.qdot[i]))) return false;
    }
    return true;
  };
  return std::any_of(found.begin(), found.end(), same);
}

// The dimension of the continuum of equilibria through solution x: the directions along which
// the balance's Jacobian does not change, ignorable ones aside.
std::size_t continuum(const System& system, const SteadyBalance& balance, const VectorXd& x,
                      const Equilibrium& e) {
  MatrixXd J;
  balance.residual(x, &J);
  Eigen::FullPivLU<MatrixXd> lu(J);
  lu.setThreshold(1e-9);
  const auto ignorable_free =
      static_cast<std::size_t>(std::count_if(balance.free_q.begin(), balance.free_q.end(),
                                             [&](Index i) { return is_ignorable(system, e, i); }));
  const auto nullity = static_cast<std::size_t>(J.cols() - lu.rank());
  return nullity > ignorable_free ? nullity - ignorable_free : 0;
}

// Lagrange–Dirichlet at rest, Routh with cyclic coordinates (their momenta's ∂p/∂q̇ there).
std::optional<bool> potential_minimum(const Equilibrium& e, const std::vector<Index>& cyclic,
                                      const Tape& momenta, Index n) {
  return energy_minimum(
      e.linearization, e.point, cyclic,
      cyclic.empty()
          ? MatrixXd(0, n)
          : derivatives(momenta,
                        tape_inputs_at(e.point.t, e.point.q, e.point.qdot, e.point.parameters), 1,
                        n)
                .derivative);
}

// In the order of the coordinates, then of the rates.
void sort_equilibria(std::vector<Equilibrium>& found, Index n) {
  std::sort(found.begin(), found.end(), [&](const Equilibrium& a, const Equilibrium& b) {
    for (Index i = 0; i < 2 * n; ++i) {
      const double x = i < n ? a.point.q[i] : a.point.qdot[i - n];
      const double y = i < n ? b.point.q[i] : b.point.qdot[i - n];
      if (std::abs(x - y) > 1e-9) return x < y;
    }
    return false;
  });
}

// Equations that change with t have no equilibria to find at one instant.
void expect_autonomous(const System& system, const CompiledSystem& compiled,
                       const std::vector<double>& parameters) {
  if (changes_with_t(compiled, parameters)) {
    throw std::invalid_argument(
        "the equations of motion of " + system.name +
        " depend on t (a moving support or a driving force), so a state at rest at one instant "
        "is not an equilibrium of the motion; the states the drive keeps at rest are periodic "
        "motions: analyse one with `unidyn modes MODEL --at NAME=VALUE` (Floquet multipliers "
        "over a period of the drive)");
  }
}

}  // namespace

EquilibriumSearchResult find_equilibria(const System& system, const CompiledSystem& compiled,
                                        const std::vector<GivenValue>& given,
                                        const std::vector<double>& parameters,
                                        const EquilibriumSearch& search) {
  expect_smooth_contacts(system, parameters);
  expect_autonomous(system, compiled, parameters);
  const auto n = static_cast<Index>(compiled.coordinate_count());
  // The balance: the unknowns other than the values given and the cyclic coordinates.
  const std::vector<Index> cyclic = cyclic_coordinates(system, search.cyclic);
  const GivenState held = given_state(system, given, parameters, cyclic);
  const Tape momenta = cyclic.empty() ? Tape() : momentum_tape(system, cyclic);
  SteadyBalance balance{compiled, 0.0,       parameters,
                        held.q,   held.qdot, {},
                        {},       {},        cyclic.empty() ? nullptr : &momenta,
                        {},       VectorXd()};
  choose_unknowns(balance, held, cyclic);
  StartingPoints starts(system, balance, held.q, search.seed);
  const double scale =
      std::max(1.0, balance.residual(balance.unknowns_at(held.q)).cwiseAbs().maxCoeff());
  // the configurations of the equilibria at rest found, to list one attitude once
  ConfigurationKey configuration(system, compiled);
  std::vector<std::vector<double>> at_rest;
  EquilibriumSearchResult result;
  for (const Index i : cyclic) {
    result.cyclic.push_back(system.coordinates()[static_cast<std::size_t>(i)].name);
  }
  std::vector<Equilibrium>& found = result.equilibria;
  for (std::size_t start = 0; start < search.starts; ++start) {
    // Gauss–Newton from a start drawn at random
    const auto solution = solve_from(balance, balance.unknowns_at(starts.draw()), scale);
    if (!solution) continue;
    SteadyBalance::State x = balance.state(*solution);
    starts.canonical(x);
    // linearised there (a state that is not steady, or singular equations, counted aside)
    Equilibrium e;
    try {
      e.point =
          operating_point(system, compiled, state_given(system, given, balance, x), parameters);
      e.linearization = linearize(system, compiled, e.point);
    } catch (const NotAnOperatingPoint&) {
      ++result.not_steady;
      continue;
    } catch (const std::exception&) {
      ++result.singular;  // gimbal lock, singular equations
      continue;
    }
    if (found_already(system, balance, starts, e, found)) continue;
    // at rest where one found already is, in other coordinates (the other Euler angles)
    const bool rests = e.point.qdot.isZero(0.0);
    const std::vector<double> key = rests ? configuration.at(e.point) : std::vector<double>{};
    if (rests && std::any_of(at_rest.begin(), at_rest.end(),
                             [&](const auto& other) { return configuration.same(key, other); })) {
      continue;
    }
    if (rests) at_rest.push_back(key);
    // classified: its modes, the continuum through it, the energy methods
    e.modes = analyse_modes(e.linearization);
    e.continuum = continuum(system, balance, *solution, e);
    e.potential_minimum = potential_minimum(e, cyclic, momenta, n);
    e.amended = !cyclic.empty();
    found.push_back(std::move(e));
  }
  sort_equilibria(found, n);
  return result;
}

}  // namespace unidyn
