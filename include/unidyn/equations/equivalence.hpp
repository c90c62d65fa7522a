// `unidyn check`: Newton's and Lagrange's equations agree, symbolically and at random states, and
// the constraints are consistent.
#pragma once

#include <string>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/equations/newton.hpp"

namespace unidyn {

struct EquivalenceReport {
  // Newton projected minus Lagrange, per coordinate, after simplification.
  std::vector<Expr> symbolic_residual;
  bool symbolic_zero = false;
  // The same evaluated in doubles at random states (q, q̇, q̈, t in [−1, 1], parameters at their
  // values): the largest |residual| relative to the larger of the sum of Lagrange's terms and the
  // sum of the residual's own terms (the scale of the round-off where they cancel). States where
  // Lagrange's terms are not real (outside the model's domain: sqrt(L^2 - x^2) at |x| > L) are
  // left out; `states` counts those used.
  int states = 0;
  double numeric_relative_residual = 0.0;
};

EquivalenceReport check_equivalence(const System& system, const EquationsOfMotion& lagrange,
                                    const NewtonEquations& newton, int states = 20,
                                    unsigned seed = 1);

}  // namespace unidyn
