// Whether an expression is identically zero, by exact evaluation at random rational points.
//
// Each trigonometric argument is an integer combination Σ n_k u_k of angles u_k (a coordinate, or
// a product such as Ω t) that each have a symbol of their own, appearing nowhere else (t of Ω t;
// Ω may appear anywhere and gets a value of its own); each u_k is given a random rational
// point of the unit circle, sin u = 2τ/(1 + τ²), cos u = (1 − τ²)/(1 + τ²) with τ rational, and
// sin, cos of Σ n_k u_k follow exactly from the angle-sum and multiple-angle formulas. Every other
// symbol (rates, accelerations, parameters, coordinates outside trigonometric functions) gets a
// random rational. The expression is then a rational number computed without rounding:
//   - not 0 at one point: the expression is not identically zero (a proof);
//   - 0 at every point: identically zero but with probability at most (degree / number of choices)
//     per point (Schwartz–Zippel): below 1e-9 with the points and ranges used here.
// Expressions this cannot evaluate exactly (an irrational radical at the point, a function other
// than sin, cos, tan, a constant angle other than a multiple of π/2) give no answer.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// true (zero at every point), false (not zero at a point: proven), or nothing (undecided).
std::optional<bool> vanishes_identically(const Expr& e, int points = 3);
// vanishes_identically of each, the work shared among processes (symbolic/process_map.hpp).
std::vector<std::optional<bool>> vanish_identically(const std::vector<Expr>& es);

// Whether e is identically zero: by the points where they decide, else by simplify (printing.hpp).
bool identically_zero(const Expr& e);

}  // namespace unidyn
