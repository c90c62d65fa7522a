// The cubic Hermite interpolant on a step: the dense output of the fixed-step methods that know the
// derivative at both ends of each step (RATTLE, alf).
#pragma once

namespace unidyn {

// The weights of y(t) = h00 y₀ + h01 y₁ + h10 y₀' + h11 y₁' at θ = (t − t₀)/h in a step of size h.
struct HermiteWeights {
  double h00, h01, h10, h11;
};
inline HermiteWeights cubic_hermite(double theta, double h) {
  const double one_minus = 1.0 - theta;
  return {(1.0 + 2.0 * theta) * one_minus * one_minus, theta * theta * (3.0 - 2.0 * theta),
          theta * one_minus * one_minus * h, -theta * theta * one_minus * h};
}

}  // namespace unidyn
