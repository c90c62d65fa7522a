// The jump of the rates at an impulsive instant (book §2.10, (11.13)–(11.15)): a generalised
// impulse Φ̂ is applied while the rows A of the constraints that hold change their rates by Δr
// (0: kept), their impulses ν acting through Aᵀ:
//   M Δq̇ = Φ̂ + Aᵀ ν,   A Δq̇ = Δr
// — the saddle-point system [M −Aᵀ; A 0] [Δq̇; ν] = [Φ̂; Δr], regular also when M is only
// semi-definite (Euler parameters with their unit-norm row).
#pragma once

#include <Eigen/Dense>
#include <optional>

namespace unidyn {

struct ImpulsiveJump {
  Eigen::VectorXd rate_change;         // Δq̇
  Eigen::VectorXd constraint_impulse;  // ν, one per row of A
};

// None when the system is singular (dependent constraints).
std::optional<ImpulsiveJump> impulsive_jump(const Eigen::MatrixXd& M, const Eigen::MatrixXd& A,
                                            const Eigen::VectorXd& impulse,
                                            const Eigen::VectorXd& row_change);

}  // namespace unidyn
