// The linearised equations in closed form: M δq̈ + C δq̇ + K δq = 0 of a system without constraints
// at an operating point given exactly (the model language reads numbers as exact rationals, 0.05
// as 1/20; π and expressions in the parameters: `phi=acos(-g/(R0*Omega^2))`), the parameters kept
// as symbols:
//   M = M(q0),   C = −∂f/∂q̇ (q0, q̇0),   K = −∂f/∂q (q0, q̇0)   (q̈0 = 0 at an equilibrium or
// steady motion, which the numeric linearisation has checked), each entry simplified
// (sin² + cos² = 1, symbolic/printing.hpp).
#pragma once

#include <optional>
#include <vector>

#include "unidyn/analysis/operating_point.hpp"
#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

struct ExactSecondOrder {
  ExprMatrix M, C, K;
};

// A linearisation in closed form: M, C, K without constraints (exact_second_order), the state
// matrix A over Linearization::state with them (analysis/exact_state_matrix.hpp); neither where
// the point is not exact.
struct ExactLinearization {
  std::optional<ExactSecondOrder> second_order;
  std::optional<ExprMatrix> state_matrix;
};

// Whether e holds a floating-point number (a decimal typed on the command line, not read exactly).
bool has_float(const Expr& e);

// Nothing when the system has constraints or a value given is a floating-point number.
std::optional<ExactSecondOrder> exact_second_order(const System& system,
                                                   const EquationsOfMotion& equations,
                                                   const std::vector<GivenValue>& given);

}  // namespace unidyn
