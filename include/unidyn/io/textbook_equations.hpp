// Lagrange's equations as a book prints them: the default of `unidyn derive`.
#pragma once

#include <ostream>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/io/equation_report.hpp"

namespace unidyn {

// T grouped by products of rates, U, then for each coordinate q^i, in text or LaTeX:
//   Σ_j M_ij q̈^j + Σ (terms in q̇^j q̇^k, grouped by the product) + Σ (terms in q̇^j) + (the rest:
//   the potential's and the applied forces' terms) = Σ_k λ_k a_k^i   (0 without constraints)
// — each equation with everything but the constraint forces on the left, −f_i grouped by the
// rates; every coefficient in its shortest printed form (symbolic/textbook_form.hpp): angle sums
// combined, sin² + cos² = 1 used, common factors out. Then each constraint. LaTeX: an align
// environment, one equation per coordinate labelled eq:<coordinate> (a constraint eq:<name>), long
// ones broken into lines.
// With `intermediates` (`--form zees`), the subexpressions repeated among all the coefficients are
// named z1, z2, … first (symbolic/common_subexpressions.hpp), MotionGenesis-style, and used.
void write_textbook_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                             EquationFormat format, bool intermediates = false);

}  // namespace unidyn
