// Accelerations and minimum-norm multipliers of dependent constraints (numeric/
// dependent_constraints.hpp), against what the test computes itself: a row written twice against
// the single row's closed form (λ = (−β − a M⁻¹ f) / (a M⁻¹ aᵀ), its share λ (1, 2) / 5 of least
// norm), a row that is the sum of two others against the saddle-point system of the two solved by
// LU, and rows that contradict each other found inconsistent.
#include "unidyn/numeric/dependent_constraints.hpp"

#include <gtest/gtest.h>

#include <random>

namespace unidyn {
namespace {

// A random symmetric positive definite M, a forcing f and rows, from one seed.
struct Problem {
  Eigen::MatrixXd M;
  Eigen::VectorXd f;
  explicit Problem(int n, unsigned seed = 3) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> u(-1, 1);
    const Eigen::MatrixXd R = Eigen::MatrixXd::NullaryExpr(n, n, [&] { return u(random); });
    M = R * R.transpose() + 0.5 * Eigen::MatrixXd::Identity(n, n);
    f = Eigen::VectorXd::NullaryExpr(n, [&] { return u(random); });
  }
};

TEST(DependentConstraints, ARowWrittenTwiceSharesItsMultiplier) {
  const Problem p(4);
  const Eigen::RowVectorXd a = (Eigen::RowVectorXd(4) << 0.3, -1.2, 0.7, 2.0).finished();
  const double beta = 0.4;
  // the single row: a q̈ + β = 0
  const Eigen::VectorXd Minv_at = p.M.ldlt().solve(a.transpose());
  const Eigen::VectorXd Minv_f = p.M.ldlt().solve(p.f);
  const double lambda = (-beta - a.dot(Minv_f)) / a.dot(Minv_at);
  const Eigen::VectorXd qddot = Minv_f + Minv_at * lambda;
  // written twice, the second times 2
  Eigen::MatrixXd A(2, 4);
  A << a, 2 * a;
  const MinimumNormSolution s = minimum_norm_solve(p.M, p.f, A, Eigen::Vector2d(beta, 2 * beta));
  EXPECT_EQ(s.rank, 1);
  EXPECT_LT((s.qddot - qddot).norm(), 1e-12 * qddot.norm());
  EXPECT_NEAR(s.lambda[0], lambda / 5, 1e-12 * std::abs(lambda));
  EXPECT_NEAR(s.lambda[1], 2 * lambda / 5, 1e-12 * std::abs(lambda));
  EXPECT_LT(s.inconsistency, 1e-13);
  EXPECT_EQ(dependent_rows(A), std::vector<Eigen::Index>{1});
}

TEST(DependentConstraints, ARowThatIsTheSumOfTwoOthers) {
  const Problem p(5, 11);
  Eigen::MatrixXd A(3, 5);
  A.row(0) << 1, 0.5, -0.3, 0.2, 0;
  A.row(1) << 0, -0.4, 1.1, 0.6, 0.9;
  A.row(2) = A.row(0) + A.row(1);
  const Eigen::Vector3d b(0.3, -0.8, -0.5);
  // the two independent rows by the saddle-point system [M −Aᵀ; A 0] [q̈; λ] = [f; −b], LU
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(7, 7);
  K.topLeftCorner(5, 5) = p.M;
  K.topRightCorner(5, 2) = -A.topRows(2).transpose();
  K.bottomLeftCorner(2, 5) = A.topRows(2);
  Eigen::VectorXd rhs(7);
  rhs << p.f, -b.head(2);
  const Eigen::VectorXd x = K.fullPivLu().solve(rhs);
  const MinimumNormSolution s = minimum_norm_solve(p.M, p.f, A, b);
  EXPECT_EQ(s.rank, 2);
  EXPECT_LT((s.qddot - x.head(5)).norm(), 1e-12 * x.head(5).norm());
  // the same generalised force Aᵀ λ; λ of least norm: orthogonal to the null space (1, 1, −1)
  EXPECT_LT((A.transpose() * s.lambda - A.topRows(2).transpose() * x.tail(2)).norm(), 1e-12);
  EXPECT_NEAR(s.lambda.dot(Eigen::Vector3d(1, 1, -1)), 0.0, 1e-12);
  EXPECT_EQ(dependent_rows(A), std::vector<Eigen::Index>{2});
  // b₃ ≠ b₁ + b₂: no acceleration satisfies the three
  const MinimumNormSolution apart = minimum_norm_solve(p.M, p.f, A, Eigen::Vector3d(0.3, -0.8, 0));
  EXPECT_GT(apart.inconsistency, 0.1);
  EXPECT_LT(s.inconsistency, 1e-13);
}

TEST(DependentConstraints, IndependentRowsAsTheUsualSolveAndAZeroRowDependent) {
  const Problem p(3, 5);
  Eigen::MatrixXd A(2, 3);
  A << 1, 2, 3, 0, 0, 0;
  EXPECT_EQ(dependent_rows(A), std::vector<Eigen::Index>{1});
  A.row(1) << -1, 0.5, 0;
  EXPECT_TRUE(dependent_rows(A).empty());
  // A M⁻¹ Aᵀ regular: λ = (A M⁻¹ Aᵀ)⁻¹ (−b − A M⁻¹ f)
  const Eigen::Vector2d b(0.1, 0.2);
  const Eigen::MatrixXd Minv_At = p.M.ldlt().solve(A.transpose());
  const Eigen::Vector2d lambda = (A * Minv_At).ldlt().solve(-b - A * p.M.ldlt().solve(p.f));
  const MinimumNormSolution s = minimum_norm_solve(p.M, p.f, A, b);
  EXPECT_EQ(s.rank, 2);
  EXPECT_LT((s.lambda - lambda).norm(), 1e-12 * lambda.norm());
  EXPECT_THROW(minimum_norm_solve(-p.M, p.f, A, b), std::runtime_error);
}

}  // namespace
}  // namespace unidyn
