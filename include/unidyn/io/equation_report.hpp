// Printing derived equations: text, LaTeX, JSON (`unidyn derive`).
#pragma once

#include <ostream>
#include <string>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/equations/newton.hpp"
#include "unidyn/equations/second_form.hpp"

namespace unidyn {

enum class EquationFormat { text, latex, json };

// Lagrange's equations: each row Σ_j M_ij q̈^j = f_i + Σ_k λ_k a_k^i, then each constraint, T and U.
void write_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                    EquationFormat format);

// Lagrange's equations in the second form (10.16): for each coordinate u^A its partial velocities
// and partial angular velocities, then d/dt(∂T/∂u̇^A) − ∂T/∂u^A = Φ_A + Σ_k λ_k a_k^A.
void write_second_form(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                       const SecondForm& form, EquationFormat format);

// Newton's second law for each particle, m a = F + R, component by component on E1, E2, E3.
void write_newton(std::ostream& out, const System& system, const NewtonEquations& newton,
                  EquationFormat format);

}  // namespace unidyn
