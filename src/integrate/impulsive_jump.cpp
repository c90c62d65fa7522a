// [M −Aᵀ; A 0] [Δq̇; ν] = [Φ̂; Δr].
#include "unidyn/integrate/impulsive_jump.hpp"

namespace unidyn {

std::optional<ImpulsiveJump> impulsive_jump(const Eigen::MatrixXd& M, const Eigen::MatrixXd& A,
                                            const Eigen::VectorXd& impulse,
                                            const Eigen::VectorXd& row_change) {
  const Eigen::Index n = M.rows(), r = A.rows();
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n + r, n + r);
  K.topLeftCorner(n, n) = M;
  K.topRightCorner(n, r) = -A.transpose();
  K.bottomLeftCorner(r, n) = A;
  Eigen::VectorXd rhs(n + r);
  rhs << impulse, row_change;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (!lu.isInvertible()) return std::nullopt;
  const Eigen::VectorXd x = lu.solve(rhs);
  return ImpulsiveJump{x.head(n), x.tail(r)};
}

}  // namespace unidyn
