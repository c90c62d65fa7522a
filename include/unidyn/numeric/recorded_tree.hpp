// A tree's q̈ as generated code: the articulated-body algorithm (tree/articulated_body.hpp) run
// once on recorded scalars (numeric/tape_recorder.hpp) at the model's numbers, so that every
// mass, offset and axis is folded in and every product with a zero of an axis or an inertia is
// gone — the recursive dynamics unrolled for this robot, as RobCoGen and SD-FAST generate it. The
// tape then becomes native code with the system's other tapes.
//
// It holds for the numbers it was recorded at (the parameters given); its inputs are the compiled
// system's [t, q, q̇, p], its outputs q̈ and then every pivot of the algorithm (each D_i, and the
// Cholesky pivots of a ball or floating joint's D), which must be positive for q̈ to be the
// tree's: where one is not, the caller takes the numeric algorithm, which says why.
#pragma once

#include <span>

#include "unidyn/numeric/tape.hpp"
#include "unidyn/tree/tree_model.hpp"

namespace unidyn {

// model: the tree at the parameters; joint_forces: [t, q, q̇, p] → τ; the parameters'
// values, folded in as numbers.
Tape record_tree_accelerations(const tree::TreeModel& model, const Tape& joint_forces,
                               std::span<const double> parameters);

}  // namespace unidyn
