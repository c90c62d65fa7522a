// Expressions in the form a book prints them: each coefficient as short as the identities allow,
// and a sum grouped by monomials in chosen symbols (the accelerations, then products of rates).
#pragma once

#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// The shortest printed form among simplify's result (symbolic/printing.hpp) with angle sums
// combined or not, homogenised in sines and cosines or not (symbolic/trig_identities.hpp), each
// grouped by its sines and cosines with the common factors pulled out (symbolic/common_factor.hpp);
// ties go to the first in the canonical order. A homogenised form (A sin²θ + C cos²θ, as the book
// writes inertia about a turning axis, rather than C + (A − C) sin²θ) is preferred while it is at
// most 1.5 times as long as the shortest.
Expr textbook_simplify(const Expr& e);
// textbook_simplify of each, the work shared among processes (symbolic/process_map.hpp), every
// result remembered for later calls.
std::vector<Expr> textbook_simplify_all(const std::vector<Expr>& es);

// A sum as Σ coefficient × monomial over the monomials in `symbols` it contains (1 for the part
// free of them), each coefficient simplified by `simplifier` (textbook_simplify unless given),
// zero ones left out; by degree, highest first, then by the exponents in the order of `symbols`
// (x² before x y before y²).
struct GroupedTerm {
  Expr coefficient;
  Expr monomial;
};
// (As `simplifier`: the coefficients left as they are, to be simplified afterwards all at once.)
Expr as_it_is(const Expr& e);
std::vector<GroupedTerm> group_by_monomials(const Expr& e, const std::vector<Expr>& symbols,
                                            Expr (*simplifier)(const Expr&) = textbook_simplify);

// The terms joined as a person writes them: "a + b - c", the first one's sign kept.
std::string join_terms(const std::vector<std::string>& texts);

}  // namespace unidyn
