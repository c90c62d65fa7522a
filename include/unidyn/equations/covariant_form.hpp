// Lagrange's equations in the covariant form (4.30): the convective terms from the mass matrix by
// Christoffel symbols of the first kind (4.25), generalised to a kinetic energy that depends on t
// and is not only quadratic in the rates, T = ½ q̇ᵀ M q̇ + b · q̇ + T0 (moving constraints):
//
//   d/dt(∂T/∂q̇^R) − ∂T/∂q^R = Σ_K M_RK q̈^K + Σ_{K≤S} c_R,KS q̇^K q̇^S + Σ_K g_RK q̇^K + k_R
//   c_R,KS = ∂M_RK/∂q^S + ∂M_RS/∂q^K − ∂M_KS/∂q^R   (K < S: [KS, R] + [SK, R])
//   c_R,KK = ∂M_RK/∂q^K − ½ ∂M_KK/∂q^R                (K = S: [KK, R])
//   g_RK   = ∂M_RK/∂t + ∂b_R/∂q^K − ∂b_K/∂q^R          (rheonomic and gyroscopic)
//   k_R    = ∂b_R/∂t − ∂T0/∂q^R
//
// Given a mass matrix equal to the derived one but shorter (simplified entry by entry), these terms
// come from derivatives of short expressions, where the derived rows are long: the book's form of
// a 10-link chain is then read off M, not dug out of the expanded rows.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

// Each row's convective part (the q̈-free part of its inertia terms) by the formulas above with
// `mass_matrix` (equal to eq.mass_matrix), or none for a row where exact evaluation
// (symbolic/zero_test.hpp) does not show it equal to the derived one.
std::vector<std::optional<Expr>> covariant_convective_terms(const System& system,
                                                            const EquationsOfMotion& eq,
                                                            const ExprMatrix& mass_matrix);

// T = ½ q̇ᵀ M q̇ + b · q̇ + T0 with `mass_matrix` (equal to eq.mass_matrix), or none where exact
// evaluation does not show it equal to eq.kinetic_energy.
std::optional<Expr> quadratic_kinetic_energy(const System& system, const EquationsOfMotion& eq,
                                             const ExprMatrix& mass_matrix);

}  // namespace unidyn
