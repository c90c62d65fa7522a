// Impulses applied at an instant (book §9.8, Ex. 11.2, (11.13)–(11.15)): an impulse Î at a point
// P jumps the momenta by the generalised impulses,
//   [[∂T/∂q̇^i]] = Φ̂_i = Î · ∂v_P/∂q̇^i = Î · ∂r_P/∂q^i        (11.15)
// while the positions do not change.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// Φ̂_i of an applied impulse, i over the coordinates.
std::vector<Expr> generalized_impulses(const System& system, const AppliedImpulse& impulse);

}  // namespace unidyn
