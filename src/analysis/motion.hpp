// The motion from an operating point, integrated with its variational equations: what the Floquet
// analysis integrates over a period (analysis/floquet.hpp), and what the linearisation follows for
// a while to see that a steady motion stays what it is (steadiness.hpp).
//
//   q̈ from M q̈ = f + Aᵀλ, A q̈ + b = 0 (the constraints that hold at the point),
//   Φ̇ = F(t) Φ, Φ(t0) = I   (F of reduced_system.hpp, with the point's choice of dependent values)
//
// by DOP853 at rtol = atol = 1e-12.
#pragma once

#include <Eigen/Dense>
#include <functional>

#include "reduced_system.hpp"

namespace unidyn::detail {

struct MotionSolution {
  Eigen::VectorXd q, qdot;    // at the end
  Eigen::MatrixXd monodromy;  // Φ at the end (states × states)
  std::size_t steps = 0;      // accepted
};

// F along the motion: with Φ, at each evaluation of the right-hand side (at t, on or near the
// motion); without, at the end of each step (on it: 12 times fewer than DOP853's stages).
using MotionVisitor = std::function<void(double t, const Eigen::MatrixXd& F)>;

// The motion from point over `duration`, Φ of `states` states (0: none). Throws IntegrationError,
// std::runtime_error (M or the constraints singular on the way).
MotionSolution integrate_motion(const CompiledSystem& compiled, const OperatingPoint& point,
                                const Choice& choice, Eigen::Index states, double duration,
                                const MotionVisitor& visit);

}  // namespace unidyn::detail
