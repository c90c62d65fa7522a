// sin x and cos x made once for each argument.
//
// GiNaC evaluates a function as it is made (sin_eval tries multiples of π, inverse functions,
// signs: some 30 000 instructions a call), and the derivation and the printers make the same
// sines and cosines again and again (d sin u = cos u du at every node; the substitutions of each
// simplification). These return GiNaC::sin(x) and GiNaC::cos(x), remembered by argument (in this
// thread; dropped when they grow past a bound): the same expression, evaluated once.
#pragma once

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

Expr sine_of(const Expr& x);
Expr cosine_of(const Expr& x);

}  // namespace unidyn
