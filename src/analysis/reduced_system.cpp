// The equations reduced to independent coordinates and speeds at a state.
#include "reduced_system.hpp"

#include <algorithm>
#include <cmath>

#include "tape_derivatives.hpp"
#include "unidyn/integrate/initial_state.hpp"

namespace unidyn::detail {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// A column is preferred as dependent only while it is this independent of the ones chosen.
constexpr double kPreferredEnough = 1e-6;

// A rows × cols matrix stored row by row in v from `offset`.
MatrixXd row_major(const VectorXd& v, Index offset, Index rows, Index cols) {
  MatrixXd out(rows, cols);
  for (Index i = 0; i < rows; ++i) {
    for (Index j = 0; j < cols; ++j) out(i, j) = v[offset + i * cols + j];
  }
  return out;
}

// J.rows() columns of J that are independent, chosen greedily: each time the column with the most
// left after taking out the span of those chosen, from the preferred columns while one is
// independent enough, else from all (ties to the first). Throws std::runtime_error when J's rows
// are dependent.
std::vector<Index> pivot_columns(const MatrixXd& J, const std::vector<bool>& preferred) {
  const double scale = std::max(largest(J), 1e-300);
  MatrixXd basis(J.rows(), 0);
  std::vector<Index> chosen;
  for (Index step = 0; step < J.rows(); ++step) {
    Index best = -1;
    double most = 0.0;
    VectorXd best_rest;
    for (const bool tier : {true, false}) {
      for (Index c = 0; c < J.cols(); ++c) {
        if (preferred[static_cast<std::size_t>(c)] != tier ||
            std::find(chosen.begin(), chosen.end(), c) != chosen.end()) {
          continue;
        }
        const VectorXd rest = J.col(c) - basis * (basis.transpose() * J.col(c));
        if (rest.norm() > most) {
          most = rest.norm();
          best = c;
          best_rest = rest;
        }
      }
      if (tier && most > kPreferredEnough * scale) break;
    }
    if (best < 0 || most <= kNegligible * scale) {
      throw std::runtime_error(
          "the constraints are not independent at the operating point (a singular "
          "configuration)");
    }
    chosen.push_back(best);
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = best_rest / most;
  }
  return chosen;
}

// The indices 0..n−1 not in `dependent`, in order.
std::vector<Index> complement(Index n, const std::vector<Index>& dependent) {
  std::vector<Index> out;
  for (Index i = 0; i < n; ++i) {
    if (std::find(dependent.begin(), dependent.end(), i) == dependent.end()) out.push_back(i);
  }
  return out;
}

// The n × |independent| map from independent values to all: the independent ones themselves, the
// dependent ones from J δ = 0 (J's dependent columns square).
MatrixXd null_space_map(const MatrixXd& J, const std::vector<Index>& dependent,
                        const std::vector<Index>& independent) {
  const Index n = J.cols();
  MatrixXd P = MatrixXd::Zero(n, static_cast<Index>(independent.size()));
  for (std::size_t c = 0; c < independent.size(); ++c)
    P(independent[c], static_cast<Index>(c)) = 1.0;
  if (dependent.empty()) return P;
  const Eigen::PartialPivLU<MatrixXd> Jd(J(Eigen::all, dependent));
  const MatrixXd solved = Jd.solve(J(Eigen::all, independent));
  P(dependent, Eigen::all) = -solved;
  return P;
}

}  // namespace

std::string rate_name(const std::string& coordinate) {
  return "der(" + coordinate + ")";
}

ReducedSystem reduced_system(const CompiledSystem& compiled, const OperatingPoint& point,
                             const Choice* given) {
  const auto n = static_cast<Index>(compiled.coordinate_count());
  const auto m = static_cast<Index>(compiled.constraint_count());
  ReducedSystem out;

  // 1. Values and derivatives along t, each coordinate and each rate.
  const std::vector<double> inputs = tape_inputs_at(point.t, point.q, point.qdot, point.parameters);
  const Index directions = 1 + 2 * n;
  const TapeDerivatives dynamics = derivatives(compiled.dynamics(), inputs, 0, directions);
  const TapeDerivatives constraints =
      derivatives(compiled.constraint_tape(), inputs, 0, directions);
  out.M = row_major(dynamics.value, 0, n, n);
  out.f = dynamics.value.segment(n * n, n);
  out.A_all = row_major(dynamics.value, n * n + n, m, n);
  const MatrixXd& M = out.M;
  const MatrixXd& A_all = out.A_all;
  // The constraints that hold, and the position constraints among them.
  std::vector<Index> rows, position_rows;
  for (Index k = 0; k < m; ++k) {
    if (!point.active[static_cast<std::size_t>(k)]) continue;
    rows.push_back(k);
    if (compiled.is_position_constraint()[static_cast<std::size_t>(k)]) position_rows.push_back(k);
  }
  const MatrixXd A = A_all(rows, Eigen::all);

  // Per direction d: ∂(M q̈ − f − Aᵀλ), ∂(A q̈ + b) over the rows that hold, ∂(A q̇ + e).
  MatrixXd& balance = out.balance;
  balance.resize(n, directions);
  MatrixXd acceleration_rows(static_cast<Index>(rows.size()), directions),
      velocity_rows(static_cast<Index>(rows.size()), directions);
  for (Index d = 0; d < directions; ++d) {
    const VectorXd& dd = dynamics.derivative.col(d);
    const MatrixXd dM = row_major(dd, 0, n, n), dA = row_major(dd, n * n + n, m, n);
    const VectorXd df = dd.segment(n * n, n), db = dd.segment(n * n + n + m * n, m);
    balance.col(d) = dM * point.qddot - df - dA.transpose() * point.lambda;
    acceleration_rows.col(d) = (dA * point.qddot + db)(rows);
    const VectorXd& dc = constraints.derivative.col(d);
    velocity_rows.col(d) = (row_major(dc, 0, m, n) * point.qdot + dc.segment(m * n, m))(rows);
  }

  // 3. δq̈ = D [δt; δq; δq̇] from the differentiated system [M −Aᵀ; A 0].
  const Index r = static_cast<Index>(rows.size());
  MatrixXd kkt = MatrixXd::Zero(n + r, n + r);
  kkt.topLeftCorner(n, n) = M;
  kkt.topRightCorner(n, r) = -A.transpose();
  kkt.bottomLeftCorner(r, n) = A;
  const Eigen::FullPivLU<MatrixXd> lu(kkt);
  if (!lu.isInvertible()) {
    throw std::runtime_error(
        "the equations cannot be solved for the accelerations at the operating point (the mass "
        "matrix and the constraints are singular there)");
  }
  MatrixXd right(n + r, directions);
  right << balance, acceleration_rows;
  out.D = -lu.solve(right).topRows(n);
  const MatrixXd& D = out.D;
  const MatrixXd D_q = D.middleCols(1, n), D_u = D.middleCols(1 + n, n);

  // 2. The dependent coordinates (position rows) and rates (all rows), and the maps from the
  // independent ones. Coordinates that appear nowhere (all derivatives along them 0) give their
  // rates first as dependent ones.
  std::vector<bool> no_preference(static_cast<std::size_t>(n), false),
      appears_nowhere = no_preference;
  for (Index j = 0; j < n; ++j) {
    const double along = std::max(largest(dynamics.derivative.col(1 + j)),
                                  largest(constraints.derivative.col(1 + j)));
    appears_nowhere[static_cast<std::size_t>(j)] = along == 0.0;
  }
  const MatrixXd psi_q = A_all(position_rows, Eigen::all);
  if (given) {
    out.choice = *given;
  } else {
    out.choice.dependent_q = pivot_columns(psi_q, no_preference);
    out.choice.independent_q = complement(n, out.choice.dependent_q);
    out.choice.dependent_u = pivot_columns(A, appears_nowhere);
    out.choice.independent_u = complement(n, out.choice.dependent_u);
  }
  const auto& [dependent_q, independent_q, dependent_u, independent_u] = out.choice;
  out.P_q = null_space_map(psi_q, dependent_q, independent_q);
  out.P_u = null_space_map(A, dependent_u, independent_u);
  const MatrixXd &P_q = out.P_q, &P_u = out.P_u;
  out.R = MatrixXd::Zero(n, P_q.cols());
  MatrixXd& R = out.R;
  if (!dependent_u.empty()) {
    const MatrixXd G = velocity_rows.middleCols(1, n);
    R(dependent_u, Eigen::all) =
        -Eigen::PartialPivLU<MatrixXd>(A(Eigen::all, dependent_u)).solve(G * P_q);
  }

  // 4. ẋ = F x: ξ̇ the independent coordinates' rows of δq̇, η̇ the independent rates' of δq̈.
  const Index s1 = P_q.cols(), s2 = P_u.cols();
  MatrixXd& F = out.F;
  F.resize(s1 + s2, s1 + s2);
  F.topLeftCorner(s1, s1) = R(independent_q, Eigen::all);
  F.topRightCorner(s1, s2) = P_u(independent_q, Eigen::all);
  F.bottomLeftCorner(s2, s1) = (D_q * P_q + D_u * R)(independent_u, Eigen::all);
  F.bottomRightCorner(s2, s2) = (D_u * P_u)(independent_u, Eigen::all);
  return out;
}

std::optional<OperatingPoint> nearby_state(const System& system, const CompiledSystem& compiled,
                                           const OperatingPoint& point, const ReducedSystem& at) {
  const Index s1 = at.P_q.cols(), s2 = at.P_u.cols();
  VectorXd xi(s1), eta(s2);
  // distinct, not small: an influence of order ε² shows above round-off
  for (Index k = 0; k < s1; ++k) xi[k] = 1e-3 * (1.0 + 0.37 * static_cast<double>(k));
  for (Index k = 0; k < s2; ++k) eta[k] = 1e-3 * (1.0 + 0.29 * static_cast<double>(k));
  const double rate_scale = 1.0 + largest(point.qdot);
  SimulationStart start;
  start.t0 = point.t;
  start.parameters = point.parameters;
  start.q = point.q + at.P_q * xi;
  start.qdot = point.qdot + rate_scale * (at.P_u * eta) + at.R * xi;
  const auto n = static_cast<std::size_t>(point.q.size());
  start.q_given.assign(n, false);
  start.qdot_given.assign(n, false);
  for (const Index i : at.choice.independent_q) start.q_given[static_cast<std::size_t>(i)] = true;
  for (const Index i : at.choice.independent_u)
    start.qdot_given[static_cast<std::size_t>(i)] = true;
  try {
    complete_initial_state(system, compiled, start);
    OperatingPoint near = point;
    near.q = start.q;
    near.qdot = start.qdot;
    CompiledSystemData data = compiled.make_data();
    data.active = point.active;
    compiled.solve(near.t, near.q, near.qdot, near.parameters, near.qddot, near.lambda, data);
    return near;
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

Linearization reduced_linearization(const System& system, const ReducedSystem& at,
                                    const std::vector<MatrixXd>& samples) {
  const auto n = static_cast<Index>(system.coordinates().size());
  std::vector<std::string> names;
  for (const auto& q : system.coordinates()) names.push_back(q.name);
  const auto& [dependent_q, independent_q, dependent_u, independent_u] = at.choice;
  const MatrixXd &P_q = at.P_q, &P_u = at.P_u, &R = at.R;

  // The state (ξ, η), its matrix and its map to every coordinate and rate.
  Linearization out;
  out.coordinates = names;
  const Index s1 = P_q.cols(), s2 = P_u.cols();
  out.to_coordinates = MatrixXd::Zero(2 * n, s1 + s2);
  out.to_coordinates.topLeftCorner(n, s1) = P_q;
  out.to_coordinates.bottomLeftCorner(n, s1) = R;
  out.to_coordinates.bottomRightCorner(n, s2) = P_u;
  out.full_A = at.F;
  const MatrixXd& F = out.full_A;

  // Ignorable coordinates: no other state's derivative depends on them in any sample.
  std::vector<double> scale;
  for (const MatrixXd& sample : samples) scale.push_back(largest(sample));
  std::vector<bool> gone(static_cast<std::size_t>(s1 + s2), false);
  const auto influences = [&](Index k) {
    for (std::size_t m = 0; m < samples.size(); ++m) {
      for (Index i = 0; i < s1 + s2; ++i) {
        if (i != k && !gone[static_cast<std::size_t>(i)] &&
            std::abs(samples[m](i, k)) > kNegligible * scale[m]) {
          return true;
        }
      }
    }
    return false;
  };
  for (bool dropped = !samples.empty(); dropped;) {
    dropped = false;
    for (Index k = 0; k < s1; ++k) {
      if (gone[static_cast<std::size_t>(k)] || influences(k)) continue;
      gone[static_cast<std::size_t>(k)] = true;
      out.dropped.push_back(k);
      out.ignorable.push_back(
          names[static_cast<std::size_t>(independent_q[static_cast<std::size_t>(k)])]);
      dropped = true;
    }
  }
  for (Index k = 0; k < s1 + s2; ++k) {
    if (gone[static_cast<std::size_t>(k)]) continue;
    out.kept.push_back(k);
    const std::string& name =
        names[static_cast<std::size_t>(k < s1 ? independent_q[static_cast<std::size_t>(k)]
                                              : independent_u[static_cast<std::size_t>(k - s1)])];
    out.state.push_back(k < s1 ? name : rate_name(name));
  }
  out.A = F(out.kept, out.kept);
  // the dependent coordinates and rates, in the coordinates' order
  std::vector<Index> by_order_q = dependent_q, by_order_u = dependent_u;
  std::sort(by_order_q.begin(), by_order_q.end());
  std::sort(by_order_u.begin(), by_order_u.end());
  for (const Index i : by_order_q) {
    out.dependent_coordinates.push_back(names[static_cast<std::size_t>(i)]);
  }
  for (const Index i : by_order_u) {
    out.dependent_rates.push_back(rate_name(names[static_cast<std::size_t>(i)]));
  }
  return out;
}

}  // namespace unidyn::detail
