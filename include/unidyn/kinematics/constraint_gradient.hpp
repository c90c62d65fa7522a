// The gradient of a constraint with respect to each particle's position, ∂Ψ/∂r_P (book §2.6, §4.4),
// from its gradient in the coordinates: the Lagrange prescription of a constraint force on a
// particle is R_P = λ ∂Ψ/∂r_P.
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// Solves Σ_P (∂r_P/∂q^i) · g_P = a_i for the g_P (a = ∂Ψ/∂q for a position constraint, the
// coefficients of q̇ for a velocity constraint). Unique when the coordinates map one-to-one to the
// positions of the moving particles (3 coordinates per moving particle); throws
// std::invalid_argument otherwise. Particles that do not move get g_P = 0.
std::vector<VectorExpr> constraint_gradient(const System& system, const std::vector<Expr>& a);

// The row a of constraint k: ∂Ψ/∂q^i, or ∂(velocity form)/∂q̇^i.
std::vector<Expr> constraint_row(const System& system, std::size_t k);

}  // namespace unidyn
