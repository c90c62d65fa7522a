// Eigen's eigenvalue solvers, instantiated once for all the tests.
#include "support/eigen_solvers.hpp"

#include <Eigen/Eigenvalues>

namespace unidyn::test {

Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& A) {
  return Eigen::EigenSolver<Eigen::MatrixXd>(A, false).eigenvalues();
}

SymmetricEigen symmetric_eigen(const Eigen::MatrixXd& A) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(A);
  return {solver.eigenvalues(), solver.eigenvectors(), solver.info()};
}

SymmetricEigen generalized_symmetric_eigen(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
  return {solver.eigenvalues(), solver.eigenvectors(), solver.info()};
}

}  // namespace unidyn::test
