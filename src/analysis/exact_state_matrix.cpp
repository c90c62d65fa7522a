// ẋ = A x in closed form for a constrained system at an exact operating point.
#include "unidyn/analysis/exact_state_matrix.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include "unidyn/analysis/exact_linearization.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

using GiNaC::matrix;

// The largest saddle-point system [M −Aᵀ; A 0] solved symbolically: unknowns, expression nodes.
constexpr std::size_t kMostUnknowns = 10, kMostNodes = 400;

// The numbers of a matrix (rows × cols) of expressions built by `entry`.
template <class Entry>
matrix make_matrix(std::size_t rows, std::size_t cols, Entry entry) {
  matrix out(static_cast<unsigned>(rows), static_cast<unsigned>(cols));
  for (std::size_t i = 0; i < rows; ++i) {
    for (std::size_t j = 0; j < cols; ++j) {
      out(static_cast<unsigned>(i), static_cast<unsigned>(j)) = entry(i, j);
    }
  }
  return out;
}

// X with K X = B (K square and regular; its entries expressions).
matrix solved(const matrix& K, const matrix& B) {
  matrix unknowns(K.cols(), B.cols());
  for (unsigned i = 0; i < K.cols(); ++i) {
    for (unsigned j = 0; j < B.cols(); ++j) unknowns(i, j) = GiNaC::symbol();
  }
  return K.solve(unknowns, B);
}

// The columns (or rows) of m at `indices`.
matrix columns(const matrix& m, const std::vector<std::size_t>& indices) {
  return make_matrix(m.rows(), indices.size(), [&](std::size_t i, std::size_t j) {
    return m(static_cast<unsigned>(i), static_cast<unsigned>(indices[j]));
  });
}
matrix rows(const matrix& m, const std::vector<std::size_t>& indices) {
  return make_matrix(indices.size(), m.cols(), [&](std::size_t i, std::size_t j) {
    return m(static_cast<unsigned>(indices[i]), static_cast<unsigned>(j));
  });
}

// The n × |independent| map from independent values to all (J δ = 0 gives the dependent ones).
matrix null_space_map(const matrix& J, const std::vector<std::size_t>& dependent,
                      const std::vector<std::size_t>& independent) {
  matrix P(J.cols(), static_cast<unsigned>(independent.size()));
  for (std::size_t c = 0; c < independent.size(); ++c) {
    P(static_cast<unsigned>(independent[c]), static_cast<unsigned>(c)) = 1;
  }
  if (dependent.empty()) return P;
  const matrix solved_dependent = solved(columns(J, dependent), columns(J, independent));
  for (std::size_t r = 0; r < dependent.size(); ++r) {
    for (std::size_t c = 0; c < independent.size(); ++c) {
      P(static_cast<unsigned>(dependent[r]), static_cast<unsigned>(c)) =
          -solved_dependent(static_cast<unsigned>(r), static_cast<unsigned>(c));
    }
  }
  return P;
}

// The indices of the coordinates named (or whose rates are named, "der(q)").
std::vector<std::size_t> indices_of(const System& system, const std::vector<std::string>& names) {
  std::vector<std::size_t> out;
  for (const std::string& name : names) out.push_back(state_value(system, name)->coordinate);
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::size_t> others(std::size_t n, const std::vector<std::size_t>& these) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < n; ++i) {
    if (std::find(these.begin(), these.end(), i) == these.end()) out.push_back(i);
  }
  return out;
}

// Whether x is y at the parameters' values (to 1e-9 of its size).
bool agrees(const Expr& x, double y, const GiNaC::exmap& values) {
  const std::optional<double> v = real_value(x, values);
  return v && std::abs(*v - y) <= 1e-9 * (1.0 + std::abs(y));
}

// Step 0: the point exactly — the values given, the ones the completion computed, 0 elsewhere.
std::optional<GiNaC::exmap> exact_point(const System& system, const EquationsOfMotion& eq,
                                        const std::vector<GivenValue>& given,
                                        const OperatingPoint& point, const GiNaC::exmap& values) {
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  GiNaC::exmap at{{system.time(), GiNaC::numeric(0)}};
  if (point.t != 0.0) return std::nullopt;
  std::vector<bool> known_q(n, false), known_u(n, false);
  for (const GivenValue& g : given) {
    if (has_float(g.value)) return std::nullopt;
    const auto [i, rate] = *state_value(system, g.name);
    at[rate ? q[i].rate : q[i].value] = g.value;
    (rate ? known_u : known_q)[i] = true;
  }
  const double size_q = 1.0 + point.q.cwiseAbs().maxCoeff();
  const double size_u = 1.0 + point.qdot.cwiseAbs().maxCoeff();
  std::vector<std::size_t> unknown_q, unknown_u;
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (!known_q[i] && std::abs(point.q[k]) <= 1e-12 * size_q) at[q[i].value] = 0;
    if (!known_q[i] && std::abs(point.q[k]) > 1e-12 * size_q) unknown_q.push_back(i);
    if (!known_u[i] && std::abs(point.qdot[k]) <= 1e-12 * size_u) at[q[i].rate] = 0;
    if (!known_u[i] && std::abs(point.qdot[k]) > 1e-12 * size_u) unknown_u.push_back(i);
  }
  // coordinates from position constraints linear in them with a constant coefficient
  for (bool progress = true; progress && !unknown_q.empty();) {
    progress = false;
    for (std::size_t k = 0; k < eq.constraint_position.size() && !progress; ++k) {
      const Expr& psi = eq.constraint_position[k];
      if (psi.is_zero() || !point.active[k]) continue;
      for (auto u = unknown_q.begin(); u != unknown_q.end(); ++u) {
        const GiNaC::symbol& x = q[*u].value;
        const Expr coefficient = derivative(psi, x).expand();
        bool constant = !coefficient.is_zero();
        for (const auto& c : q) constant = constant && !coefficient.has(c.value);
        // the rest of Ψ known already: all its other coordinates are in `at`
        const Expr rest = psi.subs(x == 0).subs(at);
        bool known = true;
        for (const auto& c : q) known = known && !rest.has(c.value);
        if (!constant || !known) continue;
        const Expr value = -rest / coefficient.subs(at);
        if (!normal_affordable(value)) return std::nullopt;  // past normal()'s budget
        at[x] = value.normal();
        unknown_q.erase(u);
        progress = true;
        break;
      }
    }
  }
  if (!unknown_q.empty()) return std::nullopt;
  // rates from the velocity rows, linear in them
  if (!unknown_u.empty()) {
    GiNaC::lst equations, unknowns;
    for (const std::size_t i : unknown_u) unknowns.append(q[i].rate);
    for (std::size_t k = 0; k < eq.constraint_velocity_term.size(); ++k) {
      if (!point.active[k]) continue;
      Expr row = eq.constraint_velocity_term[k];
      for (std::size_t j = 0; j < n; ++j) row += eq.constraint_matrix(k, j) * q[j].rate;
      GiNaC::exmap known = at;
      for (const std::size_t i : unknown_u) known.erase(q[i].rate);
      equations.append(row.subs(known) == 0);
    }
    Expr solution;
    try {
      solution = GiNaC::lsolve(equations, unknowns);
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (solution.nops() != unknown_u.size()) return std::nullopt;
    for (std::size_t k = 0; k < unknown_u.size(); ++k) {
      if (!normal_affordable(solution.op(k).rhs())) return std::nullopt;
      const Expr value = solution.op(k).rhs().normal();
      for (const auto& c : q) {
        if (value.has(c.rate)) return std::nullopt;  // not determined by the rows
      }
      at[q[unknown_u[k]].rate] = value;
    }
  }
  // the same point as the numeric one
  for (std::size_t i = 0; i < n; ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (!agrees(q[i].value.subs(at), point.q[k], values) ||
        !agrees(q[i].rate.subs(at), point.qdot[k], values)) {
      return std::nullopt;
    }
  }
  return at;
}

}  // namespace

std::optional<ExprMatrix> exact_state_matrix(const System& system, const EquationsOfMotion& eq,
                                             const std::vector<GivenValue>& given,
                                             const OperatingPoint& point, const Linearization& L) {
  if (system.constraints.empty()) return std::nullopt;
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  const GiNaC::exmap values = system.parameter_values(point.parameters);
  const std::optional<GiNaC::exmap> at_point = exact_point(system, eq, given, point, values);
  if (!at_point) return std::nullopt;
  const GiNaC::exmap& at = *at_point;
  // the constraints that hold, and the position constraints among them
  std::vector<std::size_t> active, position;
  for (std::size_t k = 0; k < eq.constraint_position.size(); ++k) {
    if (!point.active[k]) continue;
    active.push_back(k);
    if (system.constraints[k].kind == Constraint::Kind::position)
      position.push_back(active.size() - 1);
  }
  const std::size_t r = active.size();
  const auto A_of = [&](std::size_t k, std::size_t j) {
    return eq.constraint_matrix(active[k], j);
  };
  // q̈ and λ at the point
  const matrix M0 = make_matrix(
      n, n, [&](std::size_t i, std::size_t j) { return eq.mass_matrix(i, j).subs(at); });
  const matrix A0 =
      make_matrix(r, n, [&](std::size_t k, std::size_t j) { return A_of(k, j).subs(at); });
  const matrix kkt = make_matrix(n + r, n + r, [&](std::size_t i, std::size_t j) -> Expr {
    if (i < n && j < n) return M0(static_cast<unsigned>(i), static_cast<unsigned>(j));
    if (i < n) return -A0(static_cast<unsigned>(j - n), static_cast<unsigned>(i));
    if (j < n) return A0(static_cast<unsigned>(i - n), static_cast<unsigned>(j));
    return 0;
  });
  // Elimination with symbolic entries grows fast: a larger saddle-point system is left numeric
  // (the bicycle's, 13 × 13, takes minutes).
  std::size_t size = 0;
  for (unsigned i = 0; i < kkt.rows(); ++i) {
    for (unsigned j = 0; j < kkt.cols(); ++j) size += expression_size(kkt(i, j));
  }
  if (n + r > kMostUnknowns || size > kMostNodes) return std::nullopt;
  const matrix state =
      solved(kkt, make_matrix(n + r, 1, [&](std::size_t i, std::size_t) -> Expr {
               return i < n ? eq.forcing[i].subs(at) : -eq.constraint_bias[active[i - n]].subs(at);
             }));
  const auto qddot = [&](std::size_t j) { return state(static_cast<unsigned>(j), 0); };
  const auto lambda = [&](std::size_t k) { return state(static_cast<unsigned>(n + k), 0); };
  // 1. Per direction (q_j, then q̇_j): the differentiated balance and acceleration rows, and G.
  matrix right(static_cast<unsigned>(n + r), static_cast<unsigned>(2 * n));
  matrix G(static_cast<unsigned>(r), static_cast<unsigned>(n));
  for (std::size_t d = 0; d < 2 * n; ++d) {
    // (a reference to the coordinate's own symbol: through an ex it would be a temporary's)
    const GiNaC::symbol& x = d < n ? q[d].value : q[d - n].rate;
    for (std::size_t i = 0; i < n; ++i) {
      Expr balance = -derivative(eq.forcing[i], x);
      for (std::size_t j = 0; j < n; ++j) balance += derivative(eq.mass_matrix(i, j), x) * qddot(j);
      for (std::size_t k = 0; k < r; ++k) balance -= derivative(A_of(k, i), x) * lambda(k);
      right(static_cast<unsigned>(i), static_cast<unsigned>(d)) = balance.subs(at);
    }
    for (std::size_t k = 0; k < r; ++k) {
      Expr acceleration = derivative(eq.constraint_bias[active[k]], x);
      for (std::size_t j = 0; j < n; ++j) acceleration += derivative(A_of(k, j), x) * qddot(j);
      right(static_cast<unsigned>(n + k), static_cast<unsigned>(d)) = acceleration.subs(at);
      if (d >= n) continue;
      Expr velocity = derivative(eq.constraint_velocity_term[active[k]], x);
      for (std::size_t j = 0; j < n; ++j) velocity += derivative(A_of(k, j), x) * q[j].rate;
      G(static_cast<unsigned>(k), static_cast<unsigned>(d)) = velocity.subs(at);
    }
  }
  // 3. δq̈ = D [δq; δq̇]
  const matrix D = solved(kkt, right).mul_scalar(-1);
  const auto block = [&](std::size_t first_column) {
    return make_matrix(n, n, [&](std::size_t i, std::size_t j) {
      return D(static_cast<unsigned>(i), static_cast<unsigned>(first_column + j));
    });
  };
  const matrix D_q = block(0), D_u = block(n);
  // 2. P_q, P_u and R with the numeric linearisation's dependent coordinates and rates
  const std::vector<std::size_t> dependent_q = indices_of(system, L.dependent_coordinates),
                                 dependent_u = indices_of(system, L.dependent_rates);
  const std::vector<std::size_t> independent_q = others(n, dependent_q),
                                 independent_u = others(n, dependent_u);
  const matrix P_q = null_space_map(rows(A0, position), dependent_q, independent_q);
  const matrix P_u = null_space_map(A0, dependent_u, independent_u);
  matrix R(static_cast<unsigned>(n), P_q.cols());
  if (!dependent_u.empty()) {
    const matrix dependent = solved(columns(A0, dependent_u), G.mul(P_q)).mul_scalar(-1);
    for (std::size_t i = 0; i < dependent_u.size(); ++i) {
      for (unsigned c = 0; c < P_q.cols(); ++c) {
        R(static_cast<unsigned>(dependent_u[i]), c) = dependent(static_cast<unsigned>(i), c);
      }
    }
  }
  // 4. F and its kept rows and columns
  const matrix lower_left = D_q.mul(P_q).add(D_u.mul(R)), lower_right = D_u.mul(P_u);
  const std::size_t s1 = independent_q.size();
  const auto F = [&](std::size_t i, std::size_t j) -> Expr {
    const auto row = i < s1 ? independent_q[i] : independent_u[i - s1];
    const auto c = static_cast<unsigned>(j < s1 ? j : j - s1);
    const auto rr = static_cast<unsigned>(row);
    if (i < s1) return j < s1 ? R(rr, c) : P_u(rr, c);
    return j < s1 ? lower_left(rr, c) : lower_right(rr, c);
  };
  const std::size_t kept = L.kept.size();
  std::vector<Expr> entries;
  for (std::size_t i = 0; i < kept; ++i) {
    for (std::size_t j = 0; j < kept; ++j) {
      entries.push_back(
          F(static_cast<std::size_t>(L.kept[i]), static_cast<std::size_t>(L.kept[j])));
    }
  }
  const std::vector<Expr> simplified = simplify_all(entries);
  ExprMatrix out(kept, kept);
  out.data = simplified;
  return out;
}

}  // namespace unidyn
