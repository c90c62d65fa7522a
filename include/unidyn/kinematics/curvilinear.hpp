// Curvilinear coordinates: the bases, metric tensors and Christoffel symbols of a coordinate map
// r(q) (book §1.5–1.6, §3.2, §4.10).
#pragma once

#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

struct CurvilinearCoordinates {
  // a_i = ∂r/∂q^i (covariant basis)
  std::vector<VectorExpr> covariant_basis;
  // a_ik = a_i · a_k and its inverse a^ik
  ExprMatrix metric;
  ExprMatrix inverse_metric;
  // a^i = Σ_k a^ik a_k (contravariant basis, a^i · a_k = δ^i_k); for three coordinates a^i = grad
  // q^i
  std::vector<VectorExpr> contravariant_basis;
};

// The bases and metrics of r(q). Throws std::invalid_argument when the metric is singular
// (dependent coordinates).
CurvilinearCoordinates curvilinear_coordinates(const VectorExpr& r, const std::vector<Expr>& q);

// Christoffel symbols of the first kind (Ex. 3.2, (4.30)):
//   [ij, k] = ½ (∂a_ik/∂q^j + ∂a_jk/∂q^i − ∂a_ij/∂q^k), indexed [i][j][k].
std::vector<std::vector<std::vector<Expr>>> christoffel_first_kind(const ExprMatrix& metric,
                                                                   const std::vector<Expr>& q);

// Christoffel symbols of the second kind (4.32): Γ^k_ij = Σ_l a^kl [ij, l], indexed [k][i][j].
std::vector<std::vector<std::vector<Expr>>> christoffel_second_kind(const CurvilinearCoordinates& c,
                                                                    const std::vector<Expr>& q);

}  // namespace unidyn
