// The equations of motion through partial velocities (Kane's method; Lagrange's equations in the
// second form, book (10.16)): Newton's and Euler's laws projected on ∂v/∂q̇^i and ∂ω/∂q̇^i,
//
//   M_ij = Σ_P m ∂v_P/∂q̇^i · ∂v_P/∂q̇^j + Σ_B (m ∂v̄/∂q̇^i · ∂v̄/∂q̇^j + ∂ω/∂q̇^i · J ∂ω/∂q̇^j)
//   f_i  = Φ_i − ∂U/∂q^i − Σ_P m ∂v_P/∂q̇^i · a_P⁰
//                        − Σ_B (m ∂v̄/∂q̇^i · ā⁰ + ∂ω/∂q̇^i · (J ω̇⁰ + ω × J ω)),
//
// with J = Q J0 Qᵀ about the centre of mass, and a⁰, ā⁰, ω̇⁰ the accelerations at q̈ = 0. The
// same M q̈ = f + Aᵀλ as lagrange_equations (Σ m a · ∂v/∂q̇^i = d/dt(∂T/∂q̇^i) − ∂T/∂q^i, (10.16)),
// without differentiating T: only positions, centres and ω are differentiated, so the cost grows
// with the size of the velocities rather than of T (an n-link chain: n² small derivatives, not n²
// derivatives of a T with n² terms). Each particle's and body's share is also kept as a
// PartialVelocityTerm (J, W, h), for the numeric M and c (numeric/inertia_assembly.hpp).
#pragma once

#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

EquationsOfMotion kane_equations(const System& system);

}  // namespace unidyn
