// The linearisation of a constrained system in closed form: ẋ = A x with A's entries expressions in
// the parameters, at an operating point given exactly (analysis/exact_linearization.hpp says how
// values are read exactly).
//
// The steps of the numeric linearisation (analysis/linearization.hpp) done symbolically, with its
// choices — the dependent coordinates and rates, the ignorable coordinates dropped — so that the
// two describe the same state x:
//   0. The values the point's completion computed (integrate/initial_state.hpp) found exactly: a
//      coordinate from a position constraint linear in it with a constant coefficient (x3 from
//      x3 − R sin θ), the rates from the velocity rows A q̇ + e = 0 (linear), each checked against
//      the numeric point; q̈ and λ from [M −Aᵀ; A 0][q̈; λ] = [f; −b].
//   1. M, f, A, b, e differentiated along each coordinate and rate, at the point.
//   2. δq = P_q ξ, δq̇ = P_u η + R ξ from Ψ_q δq = 0 and A δq̇ + G δq = 0.
//   3. δq̈ = D [δq; δq̇] from the differentiated saddle-point system.
//   4. A = F(kept, kept), F = [R_I P_u,I; (D_q P_q + D_u R)_I (D_u P_u)_I], each entry simplified.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/analysis/linearization.hpp"
#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

// Nothing when the system has no constraints (exact_second_order gives M, C, K), a value given is
// a floating-point number, a value the completion computed is not found exactly, or the
// saddle-point system is larger than 10 unknowns or 400 expression nodes (symbolic elimination
// grows fast: the bicycle's 13 unknowns take minutes).
std::optional<ExprMatrix> exact_state_matrix(const System& system,
                                             const EquationsOfMotion& equations,
                                             const std::vector<GivenValue>& given,
                                             const OperatingPoint& point,
                                             const Linearization& linearization);

}  // namespace unidyn
