// Text and LaTeX of an expression in a canonical order: the same characters in every run, process
// and machine for the same expression.
//
// GiNaC keeps the terms of a sum and the factors of a product in the order of their hash values,
// and those follow where the library was loaded (the address of a type's name), which changes from
// run to run, and it gives a sum that is a factor of a product the sign of its leading term in
// that order ((a − b) c or −(b − a) c). These printers sort instead: the factors of a product by
// their own canonical text, the terms of a sum by the canonical text of the term without its
// number (so 2 x and −x sit together), then by that number; a sum's constant first and a
// product's number first, as GiNaC prints them; and a sum inside a product gets the sign of its
// first term in that order, the rest of the sign going to the product's number. The notation is
// otherwise GiNaC's: `-1/2*m*x'^2`, `sqrt(x)`, `x^(-1)`, `sin(q1+q2)`.
#pragma once

#include <string>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

std::string canonical_text(const Expr& e);
std::string canonical_latex(const Expr& e);
// In the notation SymPy's parser (sympify) reads: ** for powers, Abs, pi, and each symbol by its
// sympy_name.
std::string canonical_sympy(const Expr& e);

// A symbol's name as SymPy reads it: a rate q' as q_d, an acceleration q'' as q_dd, a multiplier
// lambda(c) as lambda_c; other names as they are.
std::string sympy_name(const std::string& name);

// a before b in the canonical order (their canonical texts compared).
bool canonical_less(const Expr& a, const Expr& b);

// The sign GiNaC chose for a sum against the canonical one: −1 when its first term in the
// canonical order (its number aside) has a negative number — GiNaC turns a sum that is a factor of
// a product by its own leading term, which changes from run to run, and the printers turn it back
// (also for an odd power of such a sum); 1 otherwise.
int canonical_sign(const Expr& e);

// GiNaC's normal form n/d (one fraction of expanded polynomials), with the sign that GiNaC fixes by
// a leading coefficient in its own variable order (which changes from run to run) fixed instead
// by the canonical order: the first term of the denominator, its number aside, has a positive
// number.
Expr canonical_normal(const Expr& e);

// Whether e divides by anything but numbers (a negative or fractional power of a non-number),
// anywhere in it: where it does not, canonical_normal(e) is e.
bool has_denominator(const Expr& e);

}  // namespace unidyn
