// Attitude from vector observations: Wahba's problem and the orthogonal Procrustes problem (6.37).
#pragma once

#include <span>

#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

// One pair (a_K, b_K) with weight α_K > 0: b_K is observed where Q a_K + d is predicted.
struct VectorObservation {
  Vec3 reference;
  Vec3 observed;
  double weight = 1.0;
};

struct AttitudeEstimate {
  Tensor rotation;
  Vec3 translation;
  // W = ½ Σ α_K ‖b_K − Q a_K − d‖² at the optimum.
  double loss;
};

// (6.37) minimises W = ½ Σ α_K ‖b_K − Q a_K − d‖² over rotations Q (and d when `with_translation`,
// Horn's problem; otherwise d = 0, Wahba's). Solved by the SVD of the attitude profile matrix
// B = Σ α_K b_K ⊗ a_K (centred when d is free): Q = U diag(1, 1, det U det V) Vᵀ.
// Throws std::invalid_argument with fewer than two observations or non-positive weights.
AttitudeEstimate estimate_attitude(std::span<const VectorObservation> observations,
                                   bool with_translation);

}  // namespace unidyn
