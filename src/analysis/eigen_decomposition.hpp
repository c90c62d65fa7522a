// The eigenvalues (and eigenvectors) of a real square matrix by Eigen's EigenSolver (Hessenberg
// reduction and the shifted QR iteration to the real Schur form), and of a symmetric one,
// instantiated in one file: each instantiation costs about 8–10 s of compile time in every file
// that makes it.
#pragma once

#include <Eigen/Dense>

namespace unidyn {

struct EigenDecomposition {
  bool converged = false;
  Eigen::VectorXcd values;
  Eigen::MatrixXcd vectors;  // the eigenvectors in the columns, when asked for
};

EigenDecomposition eigen_decomposition(const Eigen::MatrixXd& A, bool with_vectors);

// The eigenvalues of a symmetric matrix, ascending (Eigen's SelfAdjointEigenSolver).
Eigen::VectorXd symmetric_eigenvalues(const Eigen::MatrixXd& A);

}  // namespace unidyn
