// Accelerations and minimum-norm multipliers of dependent constraints (numeric/
// dependent_constraints.hpp).
#include "unidyn/numeric/dependent_constraints.hpp"

#include <stdexcept>

namespace unidyn {
namespace {

// G = A L⁻ᵀ of M = L Lᵀ, as Gᵀ = L⁻¹ Aᵀ; throws when M is not positive definite.
Eigen::MatrixXd transposed_weighted_rows(const Eigen::LLT<Eigen::MatrixXd>& llt,
                                         const Eigen::MatrixXd& A) {
  if (llt.info() != Eigen::Success) {
    throw std::runtime_error("the mass matrix is not positive definite");
  }
  return llt.matrixL().solve(A.transpose());
}

}  // namespace

MinimumNormSolution minimum_norm_solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& f,
                                       const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  const Eigen::LLT<Eigen::MatrixXd> llt(M);
  const Eigen::MatrixXd Gt = transposed_weighted_rows(llt, A);
  // z_f = L⁻¹ f, r = −b − G z_f
  const Eigen::VectorXd z_free = llt.matrixL().solve(f);
  const Eigen::VectorXd G_z_free = Gt.transpose() * z_free;
  const Eigen::VectorXd r = -b - G_z_free;
  // Gᵀ = V Σ Uᵀ: λ = U Σ⁻² Uᵀ r over the values kept, z = z_f + V Σ⁻¹ Uᵀ r
  Eigen::BDCSVD<Eigen::MatrixXd> svd(Gt, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd& sigma = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixU();  // of Gᵀ: Eigen's U is our V, its V our U
  const Eigen::MatrixXd& U = svd.matrixV();
  MinimumNormSolution out;
  const double largest = sigma.size() ? sigma(0) : 0.0;
  while (out.rank < sigma.size() && sigma(out.rank) > kRankTolerance * largest) ++out.rank;
  const Eigen::Index k = out.rank;
  const Eigen::VectorXd Ut_r = U.leftCols(k).transpose() * r;
  out.lambda = U.leftCols(k) * (Ut_r.array() / sigma.head(k).array().square()).matrix();
  const Eigen::VectorXd z =
      z_free + V.leftCols(k) * (Ut_r.array() / sigma.head(k).array()).matrix();
  out.qddot = llt.matrixU().solve(z);
  // the part of r no λ reaches, against the sizes of the terms it is made of
  const double scale = b.norm() + G_z_free.norm();
  const double outside = (r - U.leftCols(k) * Ut_r).norm();
  out.inconsistency = scale > 0 ? outside / scale : 0.0;
  return out;
}

std::vector<Eigen::Index> dependent_rows(const Eigen::MatrixXd& A) {
  // row k depends on rows 0..k−1 when it adds nothing to their span: its Gram–Schmidt remainder
  // against the independent ones kept (twice, for orthogonality)
  std::vector<Eigen::Index> dependent;
  Eigen::MatrixXd basis(A.cols(), 0);
  const double scale = A.rows() ? A.rowwise().norm().maxCoeff() : 0.0;
  for (Eigen::Index k = 0; k < A.rows(); ++k) {
    Eigen::VectorXd v = A.row(k).transpose();
    for (int pass = 0; pass < 2; ++pass) v -= basis * (basis.transpose() * v);
    if (v.norm() <= 1e3 * kRankTolerance * scale) {
      dependent.push_back(k);
      continue;
    }
    basis.conservativeResize(Eigen::NoChange, basis.cols() + 1);
    basis.col(basis.cols() - 1) = v / v.norm();
  }
  return dependent;
}

}  // namespace unidyn
