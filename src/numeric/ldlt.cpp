// M = L D Lᵀ without square roots, and the solve with it.
#include "unidyn/numeric/ldlt.hpp"

#include <type_traits>

namespace unidyn {
namespace {

// The sizes whose loops are unrolled: the arithmetic is the same, in the same order, so results do
// not depend on it; small systems lose the loop overhead of their two- and three-term sums.
template <std::size_t N>
using Fixed = std::integral_constant<std::size_t, N>;

// f(Fixed<n>) for the unrolled sizes, else f(n).
template <class F>
decltype(auto) with_size(std::size_t n, F&& f) {
  switch (n) {
    case 1:
      return f(Fixed<1>{});
    case 2:
      return f(Fixed<2>{});
    case 3:
      return f(Fixed<3>{});
    case 4:
      return f(Fixed<4>{});
    case 5:
      return f(Fixed<5>{});
    case 6:
      return f(Fixed<6>{});
    default:
      return f(n);
  }
}

template <class Size>
bool factor(double* m, Size n) {
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

template <class Size>
void solve(const double* factor, Size n, double* x, std::size_t stride) {
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

}  // namespace

bool ldlt_factor(double* m, std::size_t n) {
  return with_size(n, [&](auto size) { return factor(m, size); });
}

void ldlt_solve(const double* factor, std::size_t n, double* x, std::size_t stride) {
  with_size(n, [&](auto size) { solve(factor, size, x, stride); });
}

}  // namespace unidyn
