// Partial derivatives of expressions (book §1.4, the chain rule behind (4.11) and (4.25)).
#pragma once

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// ∂e/∂x: equal to GiNaC's e.diff(x), term for term. Sums, products, integer and rational powers,
// sines and cosines are differentiated here (GiNaC's diff of a function throws and catches an
// exception on each call before it applies the chain rule: a third of the printing's time on the
// 10-link pendulum); anything else by GiNaC.
Expr derivative(const Expr& e, const GiNaC::symbol& x);

// (∂e/∂x_1, …, ∂e/∂x_n) in one walk through e: what n calls of derivative give, in the time of a
// few.
// (each x_k a symbol)
std::vector<Expr> gradient(const Expr& e, const std::vector<Expr>& xs);

}  // namespace unidyn
