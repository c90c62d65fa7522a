// Vectors and second-order tensors of Euclidean 3-space (book Appendix A).
//
// Components are taken on the fixed right-handed orthonormal basis {E1, E2, E3}:
// a vector a = a_i E_i is a Vec3, a tensor A = A_ik E_i ⊗ E_k is a Tensor with A(i,k) = E_i · (A
// E_k). Conventions (the book's, §A.3 and §A.7):
//   (a ⊗ b) c = (b · c) a,     (εc) a = a × c,     C = −εc  ⇔  C a = c × a,     c = −½ ε[C].
#pragma once

#include <Eigen/Core>
#include <Eigen/Dense>
#include <array>

namespace unidyn {

using Vec3 = Eigen::Vector3d;
using Tensor = Eigen::Matrix3d;

// Fixed basis vector E_i, i = 1, 2, 3 (the book's numbering).
Vec3 basis_vector(int i);

// ε_ijk, the alternator symbol, indices 1..3 (§A.2): ε123 = ε231 = ε312 = 1, ε213 = ε132 = ε321 =
// −1.
int alternator(int i, int j, int k);

// [a, b, c] = a · (b × c), the scalar triple product (§A.2).
double triple_product(const Vec3& a, const Vec3& b, const Vec3& c);

// (A.1) tensor product: (a ⊗ b) c = (b · c) a.
Tensor tensor_product(const Vec3& a, const Vec3& b);

// (A.11) εc = c3 (E1⊗E2 − E2⊗E1) + c2 (E3⊗E1 − E1⊗E3) + c1 (E2⊗E3 − E3⊗E2); (εc) a = a × c.
Tensor alternator_times(const Vec3& c);

// (A.10) ε[A]_i = ε_ijk A_jk, the contraction of the alternator with a tensor.
Vec3 alternator_contract(const Tensor& A);

// Skew tensor of a vector, C = −εc, so that C a = c × a (§A.7).
Tensor skew(const Vec3& c);

// Axial vector of a tensor, c = −½ ε[C]; for a skew C, C a = c × a (§A.7, mind the misprinted
// sign).
Vec3 axial(const Tensor& C);

// Symmetric and skew parts, B = ½(B + Bᵀ) + ½(B − Bᵀ) (§A.6).
Tensor symmetric_part(const Tensor& B);
Tensor skew_part(const Tensor& B);

// Principal invariants (§A.6): I_A = tr A, II_A = ½((tr A)² − tr A²), III_A = det A.
struct Invariants {
  double first;
  double second;
  double third;
};
Invariants invariants(const Tensor& A);

// Adjugate A* with A*(a × b) = Aa × Ab; A* = det(A) A⁻ᵀ when A is invertible (§A.6).
// Computed from cofactors, so it exists for singular A too.
Tensor adjugate(const Tensor& A);

// Spectral decomposition of a symmetric tensor, A = Σ λ_i u_i ⊗ u_i (§A.8), eigenvalues ascending,
// eigenvectors forming a right-handed orthonormal basis (columns of `vectors`).
struct SpectralDecomposition {
  Vec3 values;
  Tensor vectors;
};
SpectralDecomposition spectral_decomposition(const Tensor& A_symmetric);

// A a · a > 0 for every a ≠ 0: the smallest eigenvalue of the symmetric part exceeds
// relative_tolerance × the largest in magnitude (the default keeps round-off of a semidefinite
// tensor from deciding the answer).
bool is_positive_definite(const Tensor& A, double relative_tolerance = 1e-12);

// ‖QᵀQ − I‖ ≤ tol and det Q > 0: a proper-orthogonal tensor, hence a rotation (Euler's theorem,
// §6.6).
bool is_rotation(const Tensor& Q, double tolerance = 1e-12);

// Largest entry of |QᵀQ − I| together with |det Q − 1|: how far Q is from being a rotation.
double rotation_defect(const Tensor& Q);

// Nearest rotation to a tensor in the Frobenius norm (polar decomposition through the SVD).
Tensor nearest_rotation(const Tensor& A);

}  // namespace unidyn
