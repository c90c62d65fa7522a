// Numbered intermediate quantities (MotionGenesis' "zees"): the subexpressions that occur more
// than once in a set of expressions, each named z1, z2, … once, so that large equations stay
// readable.
#pragma once

#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

struct Intermediates {
  std::vector<GiNaC::realsymbol> names;  // z1, z2, …
  std::vector<Expr> values;              // z_k in terms of the variables and the earlier z_j
  std::vector<Expr> expressions;         // the given expressions in terms of the z
};

// Every subexpression of at least `min_size` nodes (symbolic/printing.hpp expression_size) that
// occurs at least twice in `expressions` (the same up to the order of terms and factors: compared
// by canonical text) is named, smaller ones first, in the canonical order among equals, and
// replaced wherever it occurs.
Intermediates common_subexpressions(const std::vector<Expr>& expressions, std::size_t min_size = 4);

}  // namespace unidyn
