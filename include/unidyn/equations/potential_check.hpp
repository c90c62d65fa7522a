// Whether a force element has a potential (book §2.4, (2.5) and Problem 2.1; §8.7 and Ex. 8.7):
// its generalised forces Φ_i (lagrange.hpp element_generalized_forces) are −∂U/∂q^i for some U(q)
// iff they depend on the coordinates alone (not on t or the rates) and
//   ∂Φ_i/∂q^j = ∂Φ_j/∂q^i   for all i < j
// (for a particle in Cartesian coordinates: curl F = 0). U is then the line integral from q = 0,
//   U(q) = −∫_0^1 Φ(s q) · q ds,
// in closed form when Φ is a polynomial in q (each power s^k integrates to 1/(k + 1)).
#pragma once

#include <optional>
#include <string>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct PotentialCheck {
  bool conservative = false;
  // Why not: "depends on t", "depends on der(x)", or "dPhi_x/dy - dPhi_y/dx" with its value.
  std::string witness;
  Expr value = 0;
  // U (with U(0) = 0) when Φ is a polynomial in the coordinates.
  std::optional<Expr> potential;
};

// The check for force element `element` of the system.
PotentialCheck potential_check(const System& system, std::size_t element);

// The one decision of what is conservative: every `force:` and `moment:` whose check finds U in
// closed form becomes a conservative element with that U (potential_proven), so that its U is in
// the energy T + U of every command, in −∂U/∂q of the equations, and in the symplectic methods.
void adopt_proven_potentials(System& system);

}  // namespace unidyn
