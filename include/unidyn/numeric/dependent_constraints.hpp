// Constrained accelerations whatever the rank of the constraints' rows: redundant rows (a spatial
// loop closed by revolute joints, Bricard's mechanism, a welded loop of an MJCF model) and
// singular positions (a four-bar whose bars align) make A M⁻¹ Aᵀ singular, and (3.8)'s
// M q̈ = f + Aᵀ λ, A q̈ + b = 0 then has many λ — but one q̈.
//
// Gauss's principle: q̈ is the acceleration closest to the free one M⁻¹ f in the kinetic-energy
// norm among those with A q̈ = −b. With M = L Lᵀ and z = Lᵀ q̈, G = A L⁻ᵀ, z_f = L⁻¹ f:
//   minimise ½ |z − z_f|²  subject to  G z = −b   ⇒   z = z_f + Gᵀ λ,   G Gᵀ λ = r = −b − G z_f,
// and G Gᵀ = A M⁻¹ Aᵀ. With the singular value decomposition Gᵀ = V Σ Uᵀ (Σ's values below
// kRankTolerance · σ_max dropped: the rank), λ = U Σ⁻² Uᵀ r is the minimum-norm solution — the
// multipliers of a statically indeterminate set are not unique, and this is the one of least
// |λ| —, and z − z_f = V Σ⁻¹ Uᵀ r does not depend on the choice: the accelerations are unique.
// The SVD of Gᵀ (divide and conquer: Eigen's BDCSVD) rather than an eigen-decomposition of A M⁻¹ Aᵀ
// keeps the rank decision at the precision of A itself (forming G Gᵀ squares its condition number).
// When r has a part outside the range of G (U's dropped columns), no q̈ satisfies the rows: they are
// inconsistent, reported as the part's relative size, for the caller to refuse.
#pragma once

#include <Eigen/Dense>
#include <vector>

namespace unidyn {

// Singular values of G below this fraction of the largest are taken as zero.
inline constexpr double kRankTolerance = 1e-10;

// The inconsistency (below) beyond which dependent rows are refused: rounding and the drift of a
// run from its constraints stay far below it.
inline constexpr double kInconsistentRows = 1e-6;

struct MinimumNormSolution {
  Eigen::VectorXd qddot;   // M⁻¹ (f + Aᵀ λ), unique
  Eigen::VectorXd lambda;  // the multipliers of least Euclidean norm
  Eigen::Index rank = 0;   // of A (of G, to kRankTolerance)
  // |part of r outside the range of G| / (|b| + |G z_f|): 0 for consistent rows, up to rounding
  double inconsistency = 0;
};

// q̈ and λ of M q̈ = f + Aᵀ λ, A q̈ + b = 0 by Gauss's principle, whatever the rank of A. Throws
// std::runtime_error when M is not positive definite.
MinimumNormSolution minimum_norm_solve(const Eigen::MatrixXd& M, const Eigen::VectorXd& f,
                                       const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

// The rows of A that depend on the rows before them (each row's part outside their span below
// 1e-7 of the largest row): in order, the rows a user could remove without changing the motion.
std::vector<Eigen::Index> dependent_rows(const Eigen::MatrixXd& A);

}  // namespace unidyn
