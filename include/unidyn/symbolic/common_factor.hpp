// The common factor of a sum's terms, pulled out as a book writes it: m a² + m a² cos θ is
// m a² (1 + cos θ), and 2 m + 4 m x is 2 m (1 + 2 x).
#pragma once

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// e with the largest monomial common to every term of the sum taken out: each base (a symbol, a
// function, a sum) at its least power over the terms, and the number gcd(numerators) /
// lcm(denominators) of the terms' rational numbers (positive). Anything but a sum, or a sum with
// nothing in common, is returned as it is.
Expr pull_common_factor(const Expr& e);

}  // namespace unidyn
