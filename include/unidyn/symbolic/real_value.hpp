// The value of an expression at given values of its symbols, in doubles, without GiNaC's own
// evaluation: substituting 0 into 1/m makes GiNaC throw from inside its evaluation, and what it
// had built then leaks. Here such a value is simply not a real number.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// e at `values` (symbol → number): the finite real it evaluates to, or nothing (a division by
// zero, the logarithm of a negative number, a symbol without a value, an unknown function).
std::optional<double> real_value(const Expr& e, const GiNaC::exmap& values);

// Each of e at each of the points: result[i][k] is e[i] at points[k]; each node of the
// expressions (shared ones too) is looked at once for all the points.
std::vector<std::vector<std::optional<double>>> real_values(
    const std::vector<Expr>& e, const std::vector<GiNaC::exmap>& points);

}  // namespace unidyn
