// A budget on expansion. Expanding can turn forty characters into millions of terms
// ((x + y + t + m + g + 1)^40 has 1 221 759): before an expression is expanded, an upper bound on
// its number of terms is compared with the budget, so that a model stops with its position and a
// reason (exit 2) instead of taking minutes and all the memory.
#pragma once

#include <stdexcept>
#include <string_view>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// The most terms a power of a sum typed in a model file may expand to (checked by the parser at
// the '^', so the error names its position).
inline constexpr double kMaxModelExpressionTerms = 1e4;
// The most terms any one product in an expansion of the derivation, simplification and checks may
// make (before like terms combine).
inline constexpr double kMaxExpandedTerms = 1e6;

// An upper bound on the number of terms of e.expand() (and of every expansion inside it, such as
// a function's argument): sums add, products multiply, (a sum of k terms)^n has at most
// C(n + k − 1, k − 1). Infinity when it does not fit a double.
double expanded_terms_bound(const Expr& e);

// The most terms of any power of a sum in e once expanded (1 when it has none): how much e can
// grow in the expansions of the derivation.
double largest_power_terms(const Expr& e);

// An expansion past the budget.
class ExpressionTooLarge : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Whether e is a sum of monomials (or one) in symbols, numbers, constants and functions: what
// GiNaC's expand gives back as it is.
bool is_expanded(const Expr& e);

// e.expand(), or ExpressionTooLarge (naming what was being done) when one of its products would
// make more than kMaxExpandedTerms terms. When expanded_terms_bound(e) is within the budget this
// is GiNaC's expand(); otherwise the expansion is made one checked product at a time.
Expr expand_within_budget(const Expr& e, std::string_view what);

// The most terms GiNaC's normal() may be given to multiply out when it brings an expression to one
// fraction. Its greatest common divisors cost far more than the terms themselves (a 50-character
// potential 1/((x+y+m+2)^10-(x-y+g)^10+1) took 34 s to print), so this budget is smaller than
// kMaxExpandedTerms.
inline constexpr double kMaxNormalTerms = 1e4;

// An upper bound on the terms of the numerators and denominators normal(e) multiplies out on its
// way to one fraction (before greatest common divisors cancel anything): fractions added over the
// product of their denominators, powers of sums expanded.
double fraction_terms_bound(const Expr& e);

// Whether e has no denominator, or normal(e) is within kMaxNormalTerms.
bool normal_affordable(const Expr& e);

// GiNaC::normal(e) (one fraction, whose numerator and denominator are expanded), or
// ExpressionTooLarge as expand_within_budget, or when it is not normal_affordable.
Expr normal_within_budget(const Expr& e, std::string_view what);

// Throws ExpressionTooLarge when expanding e would (as expand_within_budget).
void check_expansion_budget(const Expr& e, std::string_view what);

}  // namespace unidyn
