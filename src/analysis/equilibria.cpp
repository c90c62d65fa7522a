// Equilibria and steady motions by multi-start Gauss–Newton, deduplicated and classified.
#include "unidyn/analysis/equilibria.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>

#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

constexpr double kTwoPi = 2 * std::numbers::pi;

// The residual r = [f(q, q̇) + Aᵀλ; Ψ(q)] over the constraints that hold, and its Jacobian in the
// free coordinates and λ.
struct Balance {
  const CompiledSystem& compiled;
  double t;
  VectorXd qdot;
  std::vector<double> parameters;
  std::vector<Index> free;  // the coordinates solved for

  // r at (q, λ); with J, its Jacobian in (q_free, λ).
  VectorXd residual(const VectorXd& q, const VectorXd& lambda, MatrixXd* J = nullptr) const {
    const auto n = static_cast<Index>(compiled.coordinate_count());
    const auto m = static_cast<Index>(compiled.constraint_count());
    const Tape& dynamics = compiled.dynamics();
    const Tape& constraints = compiled.constraint_tape();
    std::vector<double> inputs{t};
    inputs.insert(inputs.end(), q.begin(), q.end());
    inputs.insert(inputs.end(), qdot.begin(), qdot.end());
    inputs.insert(inputs.end(), parameters.begin(), parameters.end());
    std::vector<double> seed(inputs.size(), 0.0), dyn(dynamics.output_count()), d_dyn(dyn.size()),
        con(constraints.output_count()), d_con(con.size());
    TapeWorkspace workspace;
    const auto unpack = [&](const std::vector<double>& d, const std::vector<double>& c) {
      const Eigen::Map<const VectorXd> f(d.data() + n * n, n);
      const Eigen::Map<const Eigen::Matrix<double, -1, -1, Eigen::RowMajor>> A(d.data() + n * n + n,
                                                                               m, n);
      VectorXd r(n + m);
      r.head(n) = f + A.transpose() * lambda;
      for (Index k = 0; k < m; ++k) {
        r[n + k] = compiled.is_position_constraint()[static_cast<std::size_t>(k)]
                       ? c[static_cast<std::size_t>(m * n + m + k)]
                       : 0.0;
      }
      return std::pair{r, MatrixXd(A)};
    };
    dynamics.evaluate_tangent(inputs, seed, dyn, d_dyn, workspace);
    constraints.evaluate_tangent(inputs, seed, con, d_con, workspace);
    const auto [r, A] = unpack(dyn, con);
    if (J) {
      J->resize(n + m, static_cast<Index>(free.size()) + m);
      for (std::size_t j = 0; j < free.size(); ++j) {
        seed[static_cast<std::size_t>(1 + free[j])] = 1.0;
        dynamics.evaluate_tangent(inputs, seed, dyn, d_dyn, workspace);
        constraints.evaluate_tangent(inputs, seed, con, d_con, workspace);
        seed[static_cast<std::size_t>(1 + free[j])] = 0.0;
        // the derivative of r along q_j: r's formula applied to the tangents, λ fixed
        VectorXd dr = unpack(d_dyn, d_con).first;
        J->col(static_cast<Index>(j)) = dr;
      }
      J->rightCols(m).setZero();
      J->topRightCorner(n, m) = A.transpose();
    }
    return r;
  }
};

// The residual's size relative to the forces at play: f's and Aᵀλ's, and Ψ's own.
double scaled_norm(const VectorXd& r, double scale) {
  return r.cwiseAbs().maxCoeff() / scale;
}

// Gauss–Newton from q (free coordinates moved) and λ = 0; the solution, if it converges: a
// residual below 1e-10 of `scale` (the forces at the model's own initial state, at least 1) and a
// Newton step there below 1e-8 of the coordinates. A force that only fades, as gravitation does far
// away, gives steps that grow instead: no equilibrium at infinity.
std::optional<std::pair<VectorXd, VectorXd>> solve_from(const Balance& balance, VectorXd q,
                                                        double scale) {
  const auto m = static_cast<Index>(balance.compiled.constraint_count());
  VectorXd lambda = VectorXd::Zero(m);
  MatrixXd J;
  VectorXd r = balance.residual(q, lambda, &J);
  for (int iteration = 0; iteration < 100; ++iteration) {
    if (!r.allFinite()) return std::nullopt;
    const VectorXd step = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(J).solve(-r);
    if (!step.allFinite()) return std::nullopt;
    const auto free = static_cast<Index>(balance.free.size());
    if (r.cwiseAbs().maxCoeff() <= 1e-10 * scale &&
        (free == 0 ||
         step.head(free).cwiseAbs().maxCoeff() <= 1e-8 * (1.0 + q.cwiseAbs().maxCoeff()))) {
      // polished to round-off: full steps while they make the residual smaller
      VectorXd step_here = step;
      for (int polish = 0; polish < 3; ++polish) {
        VectorXd q_next = q;
        for (std::size_t j = 0; j < balance.free.size(); ++j) {
          q_next[balance.free[j]] += step_here[static_cast<Index>(j)];
        }
        const VectorXd lambda_next = lambda + step_here.tail(m);
        const VectorXd r_next = balance.residual(q_next, lambda_next, &J);
        if (!r_next.allFinite() || !(r_next.cwiseAbs().maxCoeff() < r.cwiseAbs().maxCoeff())) break;
        q = q_next;
        lambda = lambda_next;
        r = r_next;
        step_here = Eigen::CompleteOrthogonalDecomposition<MatrixXd>(J).solve(-r);
      }
      return std::pair{q, lambda};
    }
    // backtracking: halve the step until the residual shrinks
    double size = 1.0;
    for (;; size /= 2) {
      if (size < 1e-6) return std::nullopt;
      VectorXd q_try = q;
      for (std::size_t j = 0; j < balance.free.size(); ++j) {
        q_try[balance.free[j]] += size * step[static_cast<Index>(j)];
      }
      const VectorXd lambda_try = lambda + size * step.tail(m);
      const VectorXd r_try = balance.residual(q_try, lambda_try);
      if (r_try.allFinite() && scaled_norm(r_try, scale) < scaled_norm(r, scale)) {
        q = q_try;
        lambda = lambda_try;
        break;
      }
    }
    r = balance.residual(q, lambda, &J);
  }
  return std::nullopt;
}

// x in (−π, π] (−π and what the solution's accuracy leaves next to it as π).
double wrapped(double x) {
  const double w = std::remainder(x, kTwoPi);
  return w <= -std::numbers::pi + 1e-9 ? w + kTwoPi : w;
}

// Whether the balance is 2π-periodic in coordinate k (at a point, to round-off): an angle.
bool is_angle(const Balance& balance, VectorXd q, Index k) {
  const VectorXd lambda = VectorXd::Zero(static_cast<Index>(balance.compiled.constraint_count()));
  const VectorXd r = balance.residual(q, lambda);
  q[k] += kTwoPi;
  const VectorXd shifted = balance.residual(q, lambda);
  return (r - shifted).cwiseAbs().maxCoeff() <= 1e-9 * (1.0 + r.cwiseAbs().maxCoeff());
}

}  // namespace

EquilibriumSearchResult find_equilibria(const System& system, const CompiledSystem& compiled,
                                        const std::vector<GivenValue>& given,
                                        const std::vector<double>& parameters,
                                        const EquilibriumSearch& search) {
  const auto n = static_cast<Index>(compiled.coordinate_count());
  // The values given (rates 0 when not) at the parameters' values.
  GiNaC::exmap values;
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    values[system.parameters[k].symbol] = parameters[k];
  }
  OperatingPoint template_point;
  template_point.q = VectorXd::Zero(n);
  template_point.qdot = VectorXd::Zero(n);
  template_point.q_given.assign(static_cast<std::size_t>(n), false);
  for (const GivenValue& g : given) {
    const auto [coordinate, rate] = *state_value(system, g.name);
    const auto i = static_cast<Index>(coordinate);
    const std::optional<double> v = real_value(g.value, values);
    if (!v) throw std::invalid_argument("--at " + g.name + ": not a real number");
    (rate ? template_point.qdot : template_point.q)[i] = *v;
    if (!rate) template_point.q_given[static_cast<std::size_t>(i)] = true;
  }
  Balance balance{compiled, 0.0, template_point.qdot, parameters, {}};
  for (Index i = 0; i < n; ++i) {
    if (!template_point.q_given[static_cast<std::size_t>(i)]) balance.free.push_back(i);
  }
  // Where each free coordinate starts: angles anywhere on the circle, others near the model's
  // value.
  VectorXd initial = template_point.q, spread = VectorXd::Zero(n);
  std::vector<bool> angle(static_cast<std::size_t>(n), false);
  for (const Index i : balance.free) {
    const auto value = real_value(system.initial_values[static_cast<std::size_t>(i)], values);
    initial[i] = value.value_or(0.0);
    angle[static_cast<std::size_t>(i)] = is_angle(balance, initial, i);
    spread[i] = 2.0 * (1.0 + std::abs(initial[i]));
  }
  const double at_initial =
      balance.residual(initial, VectorXd::Zero(static_cast<Index>(system.constraints.size())))
          .cwiseAbs()
          .maxCoeff();
  const double scale = std::max(1.0, at_initial);
  std::mt19937 random(search.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::normal_distribution<double> normal(0.0, 1.0);
  // the coordinates of each body's Euler parameters (their unit-norm constraint)
  std::vector<std::vector<Index>> quaternions;
  for (const Constraint& c : system.constraints) {
    if (!c.parametrisation) continue;
    quaternions.emplace_back();
    for (Index i = 0; i < n; ++i) {
      if (c.expression.has(system.coordinates()[static_cast<std::size_t>(i)].value)) {
        quaternions.back().push_back(i);
      }
    }
  }
  EquilibriumSearchResult result;
  std::vector<Equilibrium>& found = result.equilibria;
  for (std::size_t start = 0; start < search.starts; ++start) {
    VectorXd q = initial;
    for (const Index i : balance.free) {
      q[i] = angle[static_cast<std::size_t>(i)] ? std::numbers::pi * unit(random)
                                                : initial[i] + spread[i] * unit(random);
    }
    // Euler parameters: a rotation drawn uniformly (a normal 4-vector, normalised), where free
    for (const std::vector<Index>& group : quaternions) {
      double norm = 0.0;
      for (const Index i : group) {
        q[i] = normal(random);
        norm += q[i] * q[i];
      }
      for (const Index i : group) {
        if (!template_point.q_given[static_cast<std::size_t>(i)])
          q[i] /= std::sqrt(norm);
        else
          q[i] = template_point.q[i];
      }
    }
    const auto solution = solve_from(balance, q, scale);
    if (!solution) continue;
    VectorXd x = solution->first;
    for (const Index i : balance.free) {
      if (angle[static_cast<std::size_t>(i)]) x[i] = wrapped(x[i]);
    }
    // Euler parameters e and −e are one rotation: the first that is not 0 made positive
    for (const std::vector<Index>& group : quaternions) {
      const auto first =
          std::find_if(group.begin(), group.end(), [&](Index i) { return std::abs(x[i]) > 1e-6; });
      if (first != group.end() && x[*first] < 0) {
        for (const Index i : group) x[i] = -x[i];
      }
    }
    // linearised there: every coordinate given, the rates as given
    std::vector<GivenValue> at;
    for (Index i = 0; i < n; ++i) {
      const std::string& name = system.coordinates()[static_cast<std::size_t>(i)].name;
      at.push_back({name, given_number(x[i])});
    }
    for (const GivenValue& g : given) {
      if (state_value(system, g.name)->rate) at.push_back(g);
    }
    Equilibrium e;
    try {
      e.point = operating_point(system, compiled, at, parameters);
      e.linearization = linearize(system, compiled, e.point);
    } catch (const NotAnOperatingPoint&) {
      ++result.not_steady;
      continue;
    } catch (const std::exception&) {
      ++result.singular;  // gimbal lock, singular equations
      continue;
    }
    // the same as one found already? angles modulo 2π, ignorable coordinates aside
    const auto same = [&](const Equilibrium& other) {
      for (const Index i : balance.free) {
        const std::string& name = system.coordinates()[static_cast<std::size_t>(i)].name;
        const auto& ignorable = e.linearization.ignorable;
        if (std::find(ignorable.begin(), ignorable.end(), name) != ignorable.end()) continue;
        double d = e.point.q[i] - other.point.q[i];
        if (angle[static_cast<std::size_t>(i)]) d = wrapped(d);
        if (std::abs(d) > 1e-6 * (1.0 + std::abs(e.point.q[i]))) return false;
      }
      return true;
    };
    if (std::any_of(found.begin(), found.end(), same)) continue;
    e.modes = analyse_modes(e.linearization);
    // the balance's Jacobian: directions along which it does not change, ignorable ones aside
    {
      MatrixXd J;
      balance.residual(x, solution->second, &J);
      Eigen::FullPivLU<MatrixXd> lu(J);
      lu.setThreshold(1e-9);
      std::size_t ignorable_free = 0;
      for (const Index i : balance.free) {
        const std::string& name = system.coordinates()[static_cast<std::size_t>(i)].name;
        const auto& ignorable = e.linearization.ignorable;
        ignorable_free += std::find(ignorable.begin(), ignorable.end(), name) != ignorable.end();
      }
      const auto nullity = static_cast<std::size_t>(J.cols() - lu.rank());
      e.continuum = nullity > ignorable_free ? nullity - ignorable_free : 0;
    }
    // Lagrange–Dirichlet at rest with a symmetric stiffness and no velocity constraints
    const Linearization& L = e.linearization;
    if (e.point.qdot.cwiseAbs().maxCoeff() == 0.0 && !L.velocity_constraints) {
      std::vector<Index> kept_positions;
      for (std::size_t j = 0; j < L.kept.size(); ++j) {
        if (!L.state[j].starts_with("der(")) kept_positions.push_back(L.kept[j]);
      }
      const MatrixXd P = L.to_coordinates.topRows(n)(Eigen::all, kept_positions);
      const MatrixXd K = P.transpose() * L.all_coordinates.K * P;
      const double size = K.size() ? K.cwiseAbs().maxCoeff() : 0.0;
      if (K.size() && (K - K.transpose()).cwiseAbs().maxCoeff() <= 1e-9 * size) {
        const Eigen::SelfAdjointEigenSolver<MatrixXd> eigen(0.5 * (K + K.transpose()));
        e.potential_minimum = eigen.eigenvalues().minCoeff() > 1e-9 * size;
      }
    }
    found.push_back(std::move(e));
  }
  std::sort(found.begin(), found.end(), [&](const Equilibrium& a, const Equilibrium& b) {
    for (Index i = 0; i < n; ++i) {
      if (std::abs(a.point.q[i] - b.point.q[i]) > 1e-9) return a.point.q[i] < b.point.q[i];
    }
    return false;
  });
  return result;
}

}  // namespace unidyn
