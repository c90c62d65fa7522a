// The degrees of an expression in several symbols at once.
#pragma once

#include <optional>
#include <unordered_map>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// For each symbol x_k: the degree of p in x_k where p is a polynomial in x_k, none where it is
// not (x_k in a denominator, a function, a non-integer power) — GiNaC's p.is_polynomial(x_k) and
// p.degree(x_k) for every k in one walk through p's terms rather than two walks per symbol.
class PolynomialDegrees {
 public:
  explicit PolynomialDegrees(const std::vector<Expr>& xs);
  std::vector<std::optional<int>> operator()(const Expr& p) const;

 private:
  std::vector<Expr> xs_;
  std::unordered_map<Expr, std::size_t, ExprHash, GiNaC::ex_is_equal> index_;
};

// The same for one expression.
std::vector<std::optional<int>> polynomial_degrees(const Expr& p, const std::vector<Expr>& xs);

}  // namespace unidyn
