// The eigenvalues (and eigenvectors) of a real square matrix, instantiated once.
#include "eigen_decomposition.hpp"

#include <Eigen/Eigenvalues>

namespace unidyn {

EigenDecomposition eigen_decomposition(const Eigen::MatrixXd& A, bool with_vectors) {
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(A, with_vectors);
  EigenDecomposition out;
  out.converged = solver.info() == Eigen::Success;
  if (!out.converged) return out;
  out.values = solver.eigenvalues();
  if (with_vectors) out.vectors = solver.eigenvectors();
  return out;
}

Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& A) {
  return Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(A).eigenvalues();
}

}  // namespace unidyn
