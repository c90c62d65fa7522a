// Jacobi's and Frobenius' tests of integrability.
#include "unidyn/kinematics/integrability.hpp"

#include <algorithm>
#include <stdexcept>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// The variables U = (q^1..q^n, t) and their names.
struct Variables {
  std::vector<Expr> U;
  std::vector<std::string> names;
};

Variables variables(const System& system) {
  Variables v;
  for (const auto& q : system.coordinates()) {
    v.U.push_back(q.value);
    v.names.push_back(q.name);
  }
  v.U.push_back(system.time());
  v.names.push_back("t");
  return v;
}

// W = (a_1..a_n, e) of constraint k: its velocity form's coefficients and remainder.
std::vector<Expr> pfaffian(const System& system, std::size_t k) {
  const Constraint& c = system.constraints.at(k);
  const Expr form = c.kind == Constraint::Kind::position
                        ? system.configuration.total_derivative(c.expression)
                        : c.expression;
  std::vector<Expr> W;
  GiNaC::exmap at_rest;
  for (const auto& q : system.coordinates()) {
    W.push_back(derivative(form, q.rate));
    at_rest[q.rate] = 0;
  }
  W.push_back(form.subs(at_rest));
  return W;
}

// S_LK = ∂W_L/∂U^K − ∂W_K/∂U^L
Expr S(const std::vector<Expr>& W, const Variables& v, std::size_t L, std::size_t K) {
  return derivative(W[L], GiNaC::ex_to<GiNaC::symbol>(v.U[K])) -
         derivative(W[K], GiNaC::ex_to<GiNaC::symbol>(v.U[L]));
}

// A basis of ker W (rows W_A) scaled free of denominators: pick R pivot columns with a non-zero
// minor P, then for each other column f: x = det(P) e_f − adj(P) W_f on the pivots.
std::vector<std::vector<Expr>> kernel(const std::vector<std::vector<Expr>>& W) {
  const std::size_t R = W.size(), N = W[0].size();
  std::vector<std::size_t> pivots;
  // greedy: a column joins the pivots when it raises the rank of the chosen minor
  for (std::size_t col = 0; col < N && pivots.size() < R; ++col) {
    std::vector<std::size_t> trial = pivots;
    trial.push_back(col);
    const auto r = static_cast<unsigned>(trial.size());
    // rank test: some r×r minor of the rows on these columns is non-zero
    bool full = false;
    std::vector<bool> pick(R, false);
    std::fill(pick.begin(), pick.begin() + r, true);
    do {
      GiNaC::matrix M(r, r);
      unsigned row = 0;
      for (std::size_t a = 0; a < R; ++a) {
        if (!pick[a]) continue;
        for (unsigned j = 0; j < r; ++j) M(row, j) = W[a][trial[j]];
        ++row;
      }
      full = !simplify(M.determinant()).is_zero();
    } while (!full && std::prev_permutation(pick.begin(), pick.end()));
    if (full) pivots = trial;
  }
  if (pivots.size() < R) throw std::invalid_argument("the constraints are not independent");
  const auto r = static_cast<unsigned>(R);
  GiNaC::matrix P(r, r);
  for (unsigned a = 0; a < r; ++a) {
    for (unsigned j = 0; j < r; ++j) P(a, j) = W[a][pivots[j]];
  }
  const Expr det = P.determinant();
  const GiNaC::matrix adjugate = P.inverse().mul_scalar(det);
  std::vector<std::vector<Expr>> basis;
  for (std::size_t f = 0; f < N; ++f) {
    if (std::find(pivots.begin(), pivots.end(), f) != pivots.end()) continue;
    std::vector<Expr> x(N, 0);
    x[f] = det;
    for (unsigned j = 0; j < r; ++j) {
      Expr sum = 0;
      for (unsigned a = 0; a < r; ++a) sum += adjugate(j, a) * W[a][f];
      x[pivots[j]] = normal_within_budget(-sum, "the integrability test");
    }
    basis.push_back(std::move(x));
  }
  return basis;
}

}  // namespace

Integrability constraint_integrability(const System& system, std::size_t k) {
  Integrability result;
  if (system.constraints.at(k).kind == Constraint::Kind::position) return result;
  const Variables v = variables(system);
  const std::vector<Expr> W = pfaffian(system, k);
  const std::size_t N = W.size();
  for (std::size_t J = 0; J < N; ++J) {
    for (std::size_t K = J + 1; K < N; ++K) {
      for (std::size_t L = K + 1; L < N; ++L) {
        // (1.21) I_JKL = W_J S_LK + W_K S_JL + W_L S_KJ
        const Expr I = simplify(W[J] * S(W, v, L, K) + W[K] * S(W, v, J, L) + W[L] * S(W, v, K, J));
        if (!I.is_zero()) {
          return {false, "I(" + v.names[J] + ", " + v.names[K] + ", " + v.names[L] + ")", I};
        }
      }
    }
  }
  return result;
}

Integrability set_integrability(const System& system, const std::vector<std::size_t>& ks) {
  const Variables v = variables(system);
  std::vector<std::vector<Expr>> W;
  std::size_t size = 0;
  for (const std::size_t k : ks) {
    W.push_back(pfaffian(system, k));
    for (const Expr& w : W.back()) size += expression_size(w);
  }
  // the kernel is normalised entry by entry, a rational function of the rows' entries: past this
  // size it takes minutes (the bicycle's four rolling constraints: 2.6e3 nodes; a sphere rolling
  // in a pipe: 8e2)
  if (size > kLargestSetIntegrabilityTest) {
    throw std::invalid_argument("not tested (Frobenius (8.18) needs the kernel of rows of " +
                                std::to_string(size) + " nodes, past the " +
                                std::to_string(kLargestSetIntegrabilityTest) + " tested)");
  }
  const auto basis = kernel(W);
  const std::size_t N = v.U.size();
  for (std::size_t A = 0; A < W.size(); ++A) {
    for (std::size_t i = 0; i < basis.size(); ++i) {
      for (std::size_t j = i + 1; j < basis.size(); ++j) {
        // (8.18) aᵀ S^A b
        Expr sum = 0;
        for (std::size_t L = 0; L < N; ++L) {
          if (basis[i][L].is_zero()) continue;
          for (std::size_t K = 0; K < N; ++K) {
            if (K != L && !basis[j][K].is_zero())
              sum += basis[i][L] * S(W[A], v, L, K) * basis[j][K];
          }
        }
        const Expr value = simplify(sum);
        if (!value.is_zero()) {
          return {false,
                  "a^T S b of " + system.constraints[ks[A]].name + " on kernel vectors " +
                      std::to_string(i + 1) + ", " + std::to_string(j + 1),
                  value};
        }
      }
    }
  }
  return {};
}

}  // namespace unidyn
