// Sums with their common factors pulled out, greedily (the multivariate Horner scheme), so that an
// expression costs fewer multiplications to evaluate: a x + a y + b x is a (x + y) + b x, and
// x/d + y/d is (x + y)/d.
//
// At each sum, the factor (a base at an integer power) that the most terms hold is taken out of
// them, a (Σ terms/a) + Σ the others, and both parts are treated again until no two terms share a
// factor; ties go to the base first in the canonical order (canonical_text.hpp), then the lower
// power, so that the result is the same in every run. Each term's own factors are treated first,
// inside out. A factor is taken out only where it is held at that very power: x² y + x² z is
// x² (y + z), but x³ y + x z stays (x (x² y + z) saves nothing where x² and x³ = x² x are made once
// anyway). Numbers stay in the terms (GiNaC would multiply a number back into a sum).
//
// The value is unchanged and nothing is multiplied out: taking a factor out of k terms removes it
// from each of them, k − 1 multiplications fewer.
#pragma once

#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

Expr horner_form(const Expr& e);
// horner_form of each, with subexpressions met in several of them treated once.
std::vector<Expr> horner_form(const std::vector<Expr>& es);

}  // namespace unidyn
