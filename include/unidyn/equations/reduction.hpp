// Lagrange's equations, approach II (book (3.8), §3.7, §4.9): the integrable constraints that can
// be solved for a coordinate are substituted into the model, leaving the reduced coordinates and
// the constrained kinetic energy T̃ (3.4)–(3.5). Their constraint forces no longer appear — approach
// II cannot give them; approach I (lagrange_equations of the full model) does.
#pragma once

#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct Reduction {
  System system;                   // the reduced model
  std::vector<std::string> notes;  // what was eliminated, and what could not be
};

// Eliminates every position constraint Ψ that is linear in some coordinate q^k with a coefficient
// free of the coordinates (e.g. r − R, η, v − c): q^k = q^k − Ψ / (∂Ψ/∂q^k) is substituted in the
// positions, forces, remaining constraints, outputs and conserved quantities. Other constraints
// stay (with their multipliers); outputs that need an eliminated multiplier are dropped.
Reduction eliminate_constraints(const System& system);

}  // namespace unidyn
