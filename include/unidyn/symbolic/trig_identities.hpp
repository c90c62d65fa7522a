// Trigonometric identities that give equations the form a book prints them in.
//
// Angle sums and differences, applied to pairs of terms K f(a) g(b) of an expanded sum that share
// the factor K (anything else, other sines and cosines included):
//   K cos a cos b + K sin a sin b = K cos(a − b)      K cos a cos b − K sin a sin b = K cos(a + b)
//   K sin a cos b + K cos a sin b = K sin(a + b)      K sin a cos b − K cos a sin b = K sin(a − b)
// (the double pendulum's l1 l2 m2 (cos θ1 cos θ2 + sin θ1 sin θ2) is l1 l2 m2 cos(θ1 − θ2)).
//
// Homogenisation with sin²x + cos²x = 1: the terms of a polynomial in s = sin x and c = cos x are
// raised to one degree per parity by factors (s² + c²)^k, so C − C sin²θ + A sin²θ becomes
// A sin²θ + C cos²θ, the form the heavy top's mass matrix has in the book (9.22).
#pragma once

#include <optional>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// Every distinct x appearing as sin(x) or cos(x) in e, in the canonical order.
std::vector<Expr> trig_arguments(const Expr& e);

// e expanded and collected in its sines and cosines: Σ c_k m_k with m_k the distinct products of
// their powers; none where e has no sine or cosine or one sits other than as a factor to a
// natural power (under a root, in a denominator, inside another function).
std::optional<Expr> collect_in_sines_and_cosines(const Expr& e);

// The expanded sum with the angle-sum identities applied while a pair of terms matches (pairs
// chosen in the canonical order). Sums of more than 400 terms are left expanded.
Expr combine_angle_sums(const Expr& e);

// The expanded sum homogenised in the sine and cosine of each argument in turn (the canonical
// order), or e expanded where it is not a polynomial in them.
Expr homogenize_trig(const Expr& e);

}  // namespace unidyn
