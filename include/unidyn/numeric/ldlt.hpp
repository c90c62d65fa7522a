// The factorisation M = L D Lᵀ (L unit lower triangular, D diagonal) of a small symmetric positive
// definite matrix and the solve M x = y with it, on plain row-major arrays: the mass matrix's
// solve in every right-hand side.
//
// Eigen's LLT on a dynamic matrix allocates, blocks and calls a matrix-vector product per column;
// for the sizes of a mechanical system (n ≤ a few dozen) plain loops are 2–3× faster and do not
// allocate. Without Cholesky's square roots each pivot costs one division: for the small systems,
// whose factorisation is a chain of dependent pivots, that is most of its time. Column by column,
// with c_ik = L_ik d_k (so that each sum is a dot product of two rows, and the rows of a column
// are independent):
//   d_k = M_kk − Σ_{l<k} L_kl c_kl,   c_ik = M_ik − Σ_{l<k} c_il L_kl,   L_ik = c_ik / d_k  (i >
//   k),
// then L y = f (forward), z = D⁻¹ y, Lᵀ x = z (backward).
#pragma once

#include <cstddef>

namespace unidyn {

// Factors the n×n row-major `m` in place: its strict lower triangle becomes L and its diagonal
// holds 1 / d_j (each solve then multiplies); the upper triangle is left as it was.
// False when a pivot d_j is not positive (or not a number): `m` is then not positive definite.
bool ldlt_factor(double* m, std::size_t n);

// x ← M⁻¹ x, with M factored by ldlt_factor; x has n entries `stride` apart.
void ldlt_solve(const double* factor, std::size_t n, double* x, std::size_t stride = 1);

}  // namespace unidyn
