// Whether an eigenvalue has as many independent eigenvectors as its multiplicity (the motion it
// stands for stays bounded), shared by the modes' and the Floquet multipliers' verdicts.
#pragma once

#include <Eigen/Dense>
#include <complex>

namespace unidyn::detail {

// Whether the eigenvalue mu of multiplicity k of A has k independent eigenvectors: the null space
// of A − mu I, its pivots below `tolerance` (absolute) counted as zero.
inline bool semisimple(const Eigen::MatrixXd& A, std::complex<double> mu, Eigen::Index k,
                       double tolerance) {
  using complex = std::complex<double>;
  const Eigen::MatrixXcd shifted =
      A.cast<complex>() - mu * Eigen::MatrixXcd::Identity(A.rows(), A.cols());
  Eigen::FullPivLU<Eigen::MatrixXcd> lu(shifted);
  lu.setThreshold(tolerance / std::max(shifted.cwiseAbs().maxCoeff(), 1e-300));
  return A.rows() - lu.rank() >= k;
}

}  // namespace unidyn::detail
