#include "unidyn/numeric/cholesky.hpp"

#include <cmath>

namespace unidyn {

bool cholesky_factor(double* m, std::size_t n) {
  for (std::size_t j = 0; j < n; ++j) {
    double* row_j = m + j * n;
    // L_jj² = M_jj − Σ_{k<j} L_jk²
    double pivot = row_j[j];
    for (std::size_t k = 0; k < j; ++k) pivot -= row_j[k] * row_j[k];
    if (!(pivot > 0)) return false;
    const double inverse = 1.0 / std::sqrt(pivot);
    row_j[j] = inverse;
    // L_ij = (M_ij − Σ_{k<j} L_ik L_jk) / L_jj below the diagonal
    for (std::size_t i = j + 1; i < n; ++i) {
      double* row_i = m + i * n;
      double sum = row_i[j];
      for (std::size_t k = 0; k < j; ++k) sum -= row_i[k] * row_j[k];
      row_i[j] = sum * inverse;
    }
  }
  return true;
}

void cholesky_solve(const double* factor, std::size_t n, double* x, std::size_t stride) {
  // L y = x, forward
  for (std::size_t i = 0; i < n; ++i) {
    const double* row_i = factor + i * n;
    double sum = x[i * stride];
    for (std::size_t k = 0; k < i; ++k) sum -= row_i[k] * x[k * stride];
    x[i * stride] = sum * row_i[i];
  }
  // Lᵀ x = y, backward (column i of L is Lᵀ's row i)
  for (std::size_t i = n; i-- > 0;) {
    double sum = x[i * stride];
    for (std::size_t k = i + 1; k < n; ++k) sum -= factor[k * n + i] * x[k * stride];
    x[i * stride] = sum * factor[i * n + i];
  }
}

}  // namespace unidyn
