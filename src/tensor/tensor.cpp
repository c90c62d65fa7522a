// Tensor algebra of Appendix A.
#include "unidyn/tensor/tensor.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>
#include <cmath>
#include <stdexcept>

namespace unidyn {

Vec3 basis_vector(int i) {
  if (i < 1 || i > 3) throw std::out_of_range("basis_vector: index must be 1, 2 or 3");
  return Vec3::Unit(i - 1);
}

int alternator(int i, int j, int k) {
  // (§A.2) the sign of the permutation (i, j, k) of (1, 2, 3), zero when an index repeats.
  return (i - j) * (j - k) * (k - i) / 2;
}

double triple_product(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a.dot(b.cross(c));
}

Tensor tensor_product(const Vec3& a, const Vec3& b) {
  return a * b.transpose();
}

Tensor alternator_times(const Vec3& c) {
  // (A.11) (εc)_ij = ε_ijk c_k
  Tensor A;
  A << 0.0, c.z(), -c.y(),  //
      -c.z(), 0.0, c.x(),   //
      c.y(), -c.x(), 0.0;
  return A;
}

Vec3 alternator_contract(const Tensor& A) {
  // (A.10) ε[A]_i = ε_ijk A_jk
  return {A(1, 2) - A(2, 1), A(2, 0) - A(0, 2), A(0, 1) - A(1, 0)};
}

Tensor skew(const Vec3& c) {
  return -alternator_times(c);
}

Vec3 axial(const Tensor& C) {
  return -0.5 * alternator_contract(C);
}

Tensor symmetric_part(const Tensor& B) {
  return 0.5 * (B + B.transpose());
}

Tensor skew_part(const Tensor& B) {
  return 0.5 * (B - B.transpose());
}

Invariants invariants(const Tensor& A) {
  const double trace = A.trace();
  return {trace, 0.5 * (trace * trace - (A * A).trace()), A.determinant()};
}

Tensor adjugate(const Tensor& A) {
  // Column k of A* is (A e_i) × (A e_j) for the cyclic (i, j, k): A*(a × b) = Aa × Ab.
  Tensor adj;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    adj.col(k) = A.col(i).cross(A.col(j));
  }
  return adj;
}

SpectralDecomposition spectral_decomposition(const Tensor& A_symmetric) {
  const Eigen::SelfAdjointEigenSolver<Tensor> solver(symmetric_part(A_symmetric));
  Tensor vectors = solver.eigenvectors();
  // Keep the eigenvector basis right-handed.
  if (vectors.determinant() < 0.0) vectors.col(2) = -vectors.col(2);
  return {solver.eigenvalues(), vectors};
}

bool is_positive_definite(const Tensor& A, double relative_tolerance) {
  const Vec3 values = spectral_decomposition(symmetric_part(A)).values;
  const double scale = values.cwiseAbs().maxCoeff();
  return values.minCoeff() > relative_tolerance * scale && scale > 0.0;
}

double rotation_defect(const Tensor& Q) {
  const double orthogonality = (Q.transpose() * Q - Tensor::Identity()).cwiseAbs().maxCoeff();
  return std::max(orthogonality, std::abs(Q.determinant() - 1.0));
}

bool is_rotation(const Tensor& Q, double tolerance) {
  return Q.allFinite() && rotation_defect(Q) <= tolerance;
}

Tensor nearest_rotation(const Tensor& A) {
  // Polar decomposition A = Q S: with A = U Σ Vᵀ, Q = U diag(1, 1, det(U Vᵀ)) Vᵀ.
  const Eigen::JacobiSVD<Tensor> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Tensor& U = svd.matrixU();
  const Tensor& V = svd.matrixV();
  Vec3 d(1.0, 1.0, (U * V.transpose()).determinant() < 0.0 ? -1.0 : 1.0);
  return U * d.asDiagonal() * V.transpose();
}

}  // namespace unidyn
