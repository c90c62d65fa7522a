// Bases, metrics and Christoffel symbols of curvilinear coordinates.
#include "unidyn/kinematics/curvilinear.hpp"

#include <stdexcept>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

const GiNaC::symbol& as_symbol(const Expr& q) {
  if (!GiNaC::is_a<GiNaC::symbol>(q)) throw std::invalid_argument("a coordinate must be a symbol");
  return GiNaC::ex_to<GiNaC::symbol>(q);
}

}  // namespace

CurvilinearCoordinates curvilinear_coordinates(const VectorExpr& r, const std::vector<Expr>& q) {
  const std::size_t n = q.size();
  CurvilinearCoordinates c;
  // a_i = ∂r/∂q^i
  for (const auto& qi : q) c.covariant_basis.push_back(diff(r, as_symbol(qi)));
  // a_ik = a_i · a_k
  c.metric = ExprMatrix(n, n);
  GiNaC::matrix metric(static_cast<unsigned>(n), static_cast<unsigned>(n));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < n; ++k) {
      c.metric(i, k) = simplify(dot(c.covariant_basis[i], c.covariant_basis[k]));
      metric(static_cast<unsigned>(i), static_cast<unsigned>(k)) = c.metric(i, k);
    }
  }
  // a^ik, then a^i = Σ a^ik a_k
  if (simplify(metric.determinant()).is_zero()) {
    throw std::invalid_argument("the metric is singular: the coordinates are not independent");
  }
  const GiNaC::matrix inverse = metric.inverse();
  c.inverse_metric = ExprMatrix(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    VectorExpr dual;
    for (std::size_t k = 0; k < n; ++k) {
      c.inverse_metric(i, k) =
          simplify(inverse(static_cast<unsigned>(i), static_cast<unsigned>(k)));
      dual = dual + c.inverse_metric(i, k) * c.covariant_basis[k];
    }
    c.contravariant_basis.push_back(dual);
  }
  return c;
}

std::vector<std::vector<std::vector<Expr>>> christoffel_first_kind(const ExprMatrix& a,
                                                                   const std::vector<Expr>& q) {
  const std::size_t n = q.size();
  std::vector<std::vector<std::vector<Expr>>> symbol(n, std::vector(n, std::vector<Expr>(n)));
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      for (std::size_t k = 0; k < n; ++k) {
        // [ij, k] = ½ (∂a_ik/∂q^j + ∂a_jk/∂q^i − ∂a_ij/∂q^k)
        symbol[i][j][k] = normal_within_budget(
            (derivative(a(i, k), as_symbol(q[j])) + derivative(a(j, k), as_symbol(q[i])) -
             derivative(a(i, j), as_symbol(q[k]))) /
                2,
            "the Christoffel symbols");
      }
    }
  }
  return symbol;
}

std::vector<std::vector<std::vector<Expr>>> christoffel_second_kind(const CurvilinearCoordinates& c,
                                                                    const std::vector<Expr>& q) {
  const std::size_t n = q.size();
  const auto first = christoffel_first_kind(c.metric, q);
  std::vector<std::vector<std::vector<Expr>>> symbol(n, std::vector(n, std::vector<Expr>(n)));
  for (std::size_t k = 0; k < n; ++k) {
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        // Γ^k_ij = Σ_l a^kl [ij, l]
        Expr sum = 0;
        for (std::size_t l = 0; l < n; ++l) sum += c.inverse_metric(k, l) * first[i][j][l];
        symbol[k][i][j] = simplify(sum);
      }
    }
  }
  return symbol;
}

}  // namespace unidyn
