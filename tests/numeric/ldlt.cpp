// ldlt_factor / ldlt_solve against Eigen's LLT, the identity L D Lᵀ = M, and the refusal of
// matrices that are not positive definite.
#include "unidyn/numeric/ldlt.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>
#include <vector>

namespace unidyn {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// A random symmetric positive definite n×n matrix, as a mass matrix is (B Bᵀ + n I)
RowMajor random_spd(std::size_t n, std::mt19937& random) {
  std::uniform_real_distribution<double> u(-1, 1);
  const auto N = static_cast<Eigen::Index>(n);
  const Eigen::MatrixXd B = Eigen::MatrixXd::NullaryExpr(N, N, [&] { return u(random); });
  return B * B.transpose() + double(n) * Eigen::MatrixXd::Identity(N, N);
}

TEST(Ldlt, FactorsReassembleTheMatrix) {
  std::mt19937 random(7);
  for (std::size_t n : {1, 2, 3, 6, 10, 23}) {
    const RowMajor M = random_spd(n, random);
    RowMajor F = M;
    ASSERT_TRUE(ldlt_factor(F.data(), n));
    // L (unit diagonal) from the lower triangle, d from the diagonal's reciprocal
    const auto N = static_cast<Eigen::Index>(n);
    Eigen::MatrixXd L = Eigen::MatrixXd::Identity(N, N);
    Eigen::VectorXd d(N);
    for (Eigen::Index i = 0; i < N; ++i) {
      for (Eigen::Index j = 0; j < i; ++j) L(i, j) = F(i, j);
      d[i] = 1.0 / F(i, i);
      EXPECT_GT(d[i], 0.0);
    }
    EXPECT_LE((L * d.asDiagonal() * L.transpose() - Eigen::MatrixXd(M)).norm(), 1e-13 * M.norm())
        << n;
    // the upper triangle is left as it was
    for (Eigen::Index i = 0; i < N; ++i) {
      for (Eigen::Index j = i + 1; j < N; ++j) EXPECT_EQ(F(i, j), M(i, j));
    }
  }
}

TEST(Ldlt, SolvesAsEigensLltDoes) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t n : {1, 2, 4, 10, 31}) {
    const RowMajor M = random_spd(n, random);
    const auto N = static_cast<Eigen::Index>(n);
    const Eigen::VectorXd f = Eigen::VectorXd::NullaryExpr(N, [&] { return u(random); });
    RowMajor F = M;
    ASSERT_TRUE(ldlt_factor(F.data(), n));
    Eigen::VectorXd x = f;
    ldlt_solve(F.data(), n, x.data());
    const Eigen::VectorXd expected = Eigen::MatrixXd(M).llt().solve(f);
    EXPECT_LE((x - expected).norm(), 1e-12 * expected.norm()) << n;
    EXPECT_LE((M * x - f).norm(), 1e-12 * f.norm()) << n;
    // a strided right-hand side: a row of a row-major block, every third entry
    std::vector<double> strided(3 * n, 99.0);
    for (std::size_t i = 0; i < n; ++i) strided[3 * i] = f[Eigen::Index(i)];
    ldlt_solve(F.data(), n, strided.data(), 3);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_EQ(strided[3 * i], x[Eigen::Index(i)]);
      EXPECT_EQ(strided[3 * i + 1], 99.0);
    }
  }
}

TEST(Ldlt, RefusesWhatIsNotPositiveDefinite) {
  // semi-definite (rank one), indefinite, negative, and a NaN
  std::vector<double> rank_one = {1, 2, 2, 4};
  std::vector<double> indefinite = {1, 2, 2, 1};
  std::vector<double> negative = {-1};
  std::vector<double> nan = {1, 0, 0, std::nan("")};
  EXPECT_FALSE(ldlt_factor(rank_one.data(), 2));
  EXPECT_FALSE(ldlt_factor(indefinite.data(), 2));
  EXPECT_FALSE(ldlt_factor(negative.data(), 1));
  EXPECT_FALSE(ldlt_factor(nan.data(), 2));
  // and the 4×4 mass matrix of Euler parameters' redundant coordinates, singular: e ⊗ e of a unit e
  const Eigen::Vector4d e(0.5, 0.5, 0.5, 0.5);
  RowMajor P = e * e.transpose();
  EXPECT_FALSE(ldlt_factor(P.data(), 4));
}

}  // namespace
}  // namespace unidyn
