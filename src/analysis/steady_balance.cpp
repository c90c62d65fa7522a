// The balance of a steady motion and its Jacobian.
#include "steady_balance.hpp"

#include "tape_derivatives.hpp"

namespace unidyn {
namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using RowMajor = Eigen::Matrix<double, -1, -1, Eigen::RowMajor>;

// The tapes' outputs (or their derivatives along one direction) at a point.
struct Outputs {
  std::vector<double> dynamics, constraints, momentum;
};

}  // namespace

Index SteadyBalance::motion_unknowns() const {
  return static_cast<Index>(free_q.size() + free_rate.size() + free_acceleration.size());
}

Index SteadyBalance::unknowns() const {
  return motion_unknowns() + static_cast<Index>(compiled.constraint_count());
}

SteadyBalance::State SteadyBalance::state(const VectorXd& x) const {
  State s{q, qdot, VectorXd::Zero(q.size()),
          x.tail(static_cast<Index>(compiled.constraint_count()))};
  Index k = 0;
  for (const Index i : free_q) s.q[i] = x[k++];
  for (const Index i : free_rate) s.qdot[i] = x[k++];
  for (const Index i : free_acceleration) s.qddot[i] = x[k++];
  return s;
}

VectorXd SteadyBalance::unknowns_at(const VectorXd& q_values) const {
  VectorXd x = VectorXd::Zero(unknowns());
  Index k = 0;
  for (const Index i : free_q) x[k++] = q_values[i];
  for (const Index i : free_rate) x[k++] = qdot[i];
  return x;
}

VectorXd SteadyBalance::residual(const VectorXd& x, MatrixXd* J) const {
  const auto n = static_cast<Index>(compiled.coordinate_count());
  const auto m = static_cast<Index>(compiled.constraint_count());
  const auto k = static_cast<Index>(momentum_given.size());
  const State s = state(x);
  const Tape& dynamics = compiled.dynamics();
  const Tape& constraints = compiled.constraint_tape();
  const std::vector<double> inputs = tape_inputs_at(t, s.q, s.qdot, parameters);
  std::vector<double> seed(inputs.size(), 0.0);
  Outputs value{std::vector<double>(dynamics.output_count()),
                std::vector<double>(constraints.output_count()),
                std::vector<double>(momentum ? momentum->output_count() : 0)};
  Outputs tangent = value;
  TapeWorkspace workspace;
  // The tapes' values and their derivatives along `seed`.
  const auto evaluate = [&] {
    dynamics.evaluate_tangent(inputs, seed, value.dynamics, tangent.dynamics, workspace);
    constraints.evaluate_tangent(inputs, seed, value.constraints, tangent.constraints, workspace);
    if (momentum) {
      momentum->evaluate_tangent(inputs, seed, value.momentum, tangent.momentum, workspace);
    }
  };
  // The residual's formula applied to outputs (q̇, q̈ and λ held): of the values, or of their
  // derivatives (the momenta given then not subtracted).
  const auto rows = [&](const Outputs& o, bool derivative) {
    const Eigen::Map<const RowMajor> M(o.dynamics.data(), n, n),
        A(o.dynamics.data() + n * n + n, m, n), A_c(o.constraints.data(), m, n);
    const Eigen::Map<const VectorXd> f(o.dynamics.data() + n * n, n),
        b(o.dynamics.data() + n * n + n + m * n, m), e(o.constraints.data() + m * n, m),
        psi(o.constraints.data() + m * n + m, m);
    VectorXd r(n + 3 * m + k);
    r.head(n) = f + A.transpose() * s.lambda - M * s.qddot;
    for (Index c = 0; c < m; ++c) {
      r[n + c] = compiled.is_position_constraint()[static_cast<std::size_t>(c)] ? psi[c] : 0.0;
    }
    r.segment(n + m, m) = A_c * s.qdot + e;
    r.segment(n + 2 * m, m) = A * s.qddot + b;
    for (Index c = 0; c < k; ++c) {
      r[n + 3 * m + c] =
          o.momentum[static_cast<std::size_t>(momentum_given[static_cast<std::size_t>(c)])] -
          (derivative ? 0.0 : momentum_value[c]);
    }
    return r;
  };
  evaluate();
  const VectorXd r = rows(value, false);
  if (!J) return r;
  const Eigen::Map<const RowMajor> M(value.dynamics.data(), n, n),
      A(value.dynamics.data() + n * n + n, m, n), A_c(value.constraints.data(), m, n);
  J->setZero(r.size(), unknowns());
  Index column = 0;
  // along the coordinates and rates solved for: the tapes' derivatives (and A's column in A q̇)
  const auto along = [&](Index input, Index coordinate, bool rate) {
    seed[static_cast<std::size_t>(input)] = 1.0;
    evaluate();
    seed[static_cast<std::size_t>(input)] = 0.0;
    J->col(column) = rows(tangent, true);
    if (rate) J->col(column).segment(n + m, m) += A_c.col(coordinate);
    ++column;
  };
  for (const Index i : free_q) along(1 + i, i, false);
  for (const Index i : free_rate) along(1 + n + i, i, true);
  // along the accelerations solved for: −M's column in the balance, A's in A q̈
  for (const Index i : free_acceleration) {
    J->col(column).head(n) = -M.col(i);
    J->col(column).segment(n + 2 * m, m) = A.col(i);
    ++column;
  }
  // along λ: Aᵀ
  J->block(0, column, n, m) = A.transpose();
  return r;
}

}  // namespace unidyn
