// Printing derived equations: text, LaTeX, JSON (`unidyn derive`).
#pragma once

#include <ostream>
#include <string>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/equations/newton.hpp"
#include "unidyn/equations/second_form.hpp"

namespace unidyn {

enum class EquationFormat { text, latex, json };

// What kind of constraint c is, as the text reports say it: "position", "velocity", with
// ", unilateral" or ", off while 'C' holds" (off_while).
std::string constraint_kind_text(const Constraint& c);

// Lagrange's equations: each row Σ_j M_ij q̈^j = f_i + Σ_k λ_k a_k^i, then each constraint, T and U.
void write_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                    EquationFormat format);

// Lagrange's equations as JSON for other tools: the expressions in SymPy's notation
// (symbolic/canonical_text.hpp canonical_sympy: ** for powers, rates q_d, accelerations q_dd,
// multipliers lambda_c), each coordinate with those names and its initial value and rate, the
// parameters with their values, T, U, M, f and each constraint's row a_k, e_k and bias b_k
// (M q_dd = f + A^T lambda, a_k q_d + e_k = 0, a_k q_dd + b_k = 0).
void write_lagrange_json(std::ostream& out, const System& system, const EquationsOfMotion& eq);

// Lagrange's equations in the second form (10.16): for each coordinate u^A its partial velocities
// and partial angular velocities, then d/dt(∂T/∂u̇^A) − ∂T/∂u^A = Φ_A + Σ_k λ_k a_k^A.
void write_second_form(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                       const SecondForm& form, EquationFormat format);

// Kane's equations (10.16): for each coordinate u^r its partial velocities and partial angular
// velocities (from `form`), the generalised active force F_r = Σ F · ∂v/∂u̇^r + M · ∂ω/∂u̇^r −
// ∂U/∂u^r (+ Σ_k λ_k a_k^r) and the generalised inertia force F*_r = −Σ m a · ∂v/∂u̇^r −
// Σ (J ω̇ + ω × J ω) · ∂ω/∂u̇^r, from Kane's own sums (`eq` of kane_equations: F*_r = −(M q̈ + c)_r),
// and F_r + F*_r = 0.
void write_kane(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                const SecondForm& form, EquationFormat format);

// Newton's second law for each particle, m a = F + R, component by component on E1, E2, E3.
void write_newton(std::ostream& out, const System& system, const NewtonEquations& newton,
                  EquationFormat format);

}  // namespace unidyn
