// The Cholesky factorisation M = L Lᵀ of a small symmetric positive definite matrix and the solve
// M x = y with it, on plain row-major arrays: the mass matrix's solve in every right-hand side.
//
// Eigen's LLT on a dynamic matrix allocates, blocks and calls a matrix-vector product per column;
// for the sizes of a mechanical system (n ≤ a few dozen) the plain loops below are 2–3× faster,
// and they do not allocate. Cholesky–Crout order, lower triangle:
//   L_jj = √(M_jj − Σ_{k<j} L_jk²),   L_ij = (M_ij − Σ_{k<j} L_ik L_jk) / L_jj   (i > j),
// then L y = f (forward) and Lᵀ x = y (backward).
#pragma once

#include <cstddef>

namespace unidyn {

// Factors the n×n row-major `m` in place: its lower triangle becomes L and its diagonal holds
// 1 / L_jj (each solve then multiplies); the upper triangle is left as it was. False when a pivot
// is not positive (or not a number): `m` is then not positive definite.
bool cholesky_factor(double* m, std::size_t n);

// x ← M⁻¹ x, with M factored by cholesky_factor; x has n entries `stride` apart.
void cholesky_solve(const double* factor, std::size_t n, double* x, std::size_t stride = 1);

}  // namespace unidyn
