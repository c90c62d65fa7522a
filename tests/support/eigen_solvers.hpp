// Eigen's eigenvalue solvers, instantiated once for all the tests
// (tests/support/eigen_solvers.cpp): each instantiation costs 8–25 s of compile time in every file
// that makes it.
#pragma once

#include <Eigen/Dense>

namespace unidyn::test {

// The eigenvalues of a general real matrix (Eigen::EigenSolver), in Eigen's order.
Eigen::VectorXcd eigenvalues(const Eigen::MatrixXd& A);

// A symmetric eigenproblem's solution: eigenvalues ascending, eigenvectors in the columns (for
// K v = λ M v normalised so that vᵀ M v = 1), as Eigen's self-adjoint solvers give them.
class SymmetricEigen {
 public:
  SymmetricEigen(Eigen::VectorXd values, Eigen::MatrixXd vectors, Eigen::ComputationInfo info)
      : values_(std::move(values)), vectors_(std::move(vectors)), info_(info) {}
  const Eigen::VectorXd& eigenvalues() const { return values_; }
  const Eigen::MatrixXd& eigenvectors() const { return vectors_; }
  Eigen::ComputationInfo info() const { return info_; }

 private:
  Eigen::VectorXd values_;
  Eigen::MatrixXd vectors_;
  Eigen::ComputationInfo info_;
};

// A v = λ v for a symmetric A (Eigen::SelfAdjointEigenSolver).
SymmetricEigen symmetric_eigen(const Eigen::MatrixXd& A);

// K v = λ M v for a symmetric K and a positive definite M
// (Eigen::GeneralizedSelfAdjointEigenSolver).
SymmetricEigen generalized_symmetric_eigen(const Eigen::MatrixXd& K, const Eigen::MatrixXd& M);

}  // namespace unidyn::test
