// M = L D Lᵀ without square roots, and the solve with it.
#include "unidyn/numeric/ldlt.hpp"

namespace unidyn {

bool ldlt_factor(double* m, std::size_t n) {
  // Column k at step k; below the diagonal a row i > k holds c_il until its own step.
  for (std::size_t k = 0; k < n; ++k) {
    double* row_k = m + k * n;
    // row k's c_kl become L_kl = c_kl / d_l, and d_k = M_kk − Σ_{l<k} L_kl c_kl
    double pivot = row_k[k];
    for (std::size_t l = 0; l < k; ++l) {
      const double l_kl = row_k[l] * m[l * n + l];
      pivot -= l_kl * row_k[l];
      row_k[l] = l_kl;
    }
    if (!(pivot > 0)) return false;
    row_k[k] = 1.0 / pivot;
    // c_ik = M_ik − Σ_{l<k} c_il L_kl below the diagonal: dot products of two rows, independent
    for (std::size_t i = k + 1; i < n; ++i) {
      double* row_i = m + i * n;
      double c = row_i[k];
      for (std::size_t l = 0; l < k; ++l) c -= row_i[l] * row_k[l];
      row_i[k] = c;
    }
  }
  return true;
}

void ldlt_solve(const double* factor, std::size_t n, double* x, std::size_t stride) {
  // L y = x, forward (unit diagonal)
  for (std::size_t i = 0; i < n; ++i) {
    const double* row_i = factor + i * n;
    double sum = x[i * stride];
    for (std::size_t k = 0; k < i; ++k) sum -= row_i[k] * x[k * stride];
    x[i * stride] = sum;
  }
  // Lᵀ x = D⁻¹ y, backward (column i of L is Lᵀ's row i)
  for (std::size_t i = n; i-- > 0;) {
    double sum = x[i * stride] * factor[i * n + i];
    for (std::size_t k = i + 1; k < n; ++k) sum -= factor[k * n + i] * x[k * stride];
    x[i * stride] = sum;
  }
}

}  // namespace unidyn
