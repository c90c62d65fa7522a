// The form of the equations of motion the tapes evaluate: the derived expressions, with the small
// ones that sin²x + cos²x = 1 shortens replaced by their simplification.
#pragma once

#include <cstddef>

#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

// Entries of more nodes than this, or whose expansion could make more terms, are evaluated as
// derived (simplifying them costs more than the tape saves, and expansion can make them larger).
inline constexpr std::size_t kEvaluationSimplifyNodes = 500;
inline constexpr double kEvaluationSimplifyTerms = 2000;

// eq with each small entry of M, f, A, b, e and Ψ (kEvaluationSimplifyNodes,
// kEvaluationSimplifyTerms) replaced by simplify(entry) (symbolic/printing.hpp) when that is
// smaller: sines and cosines that cancel drop out of the evaluation (the heavy top's M and f need
// sin θ and cos θ only, not ψ's and φ's: a fifth of its right-hand side). The same expressions, so
// the same motion to round-off; the choice depends on the expressions alone, so every run evaluates
// the same arithmetic.
EquationsOfMotion evaluation_form(const EquationsOfMotion& eq);

}  // namespace unidyn
