// Wahba's problem and Horn's absolute orientation (6.37), solved by the SVD.
#include "unidyn/rotation/attitude_estimation.hpp"

#include <Eigen/SVD>
#include <stdexcept>

namespace unidyn {

AttitudeEstimate estimate_attitude(std::span<const VectorObservation> observations,
                                   bool with_translation) {
  if (observations.size() < 2) {
    throw std::invalid_argument("attitude estimation needs at least two observations");
  }
  double total_weight = 0.0;
  Vec3 mean_reference = Vec3::Zero();
  Vec3 mean_observed = Vec3::Zero();
  for (const auto& o : observations) {
    if (!(o.weight > 0.0)) throw std::invalid_argument("observation weights must be positive");
    total_weight += o.weight;
    mean_reference += o.weight * o.reference;
    mean_observed += o.weight * o.observed;
  }
  mean_reference /= total_weight;
  mean_observed /= total_weight;
  // With d free, ∂W/∂d = 0 gives d = b̄ − Q ā, leaving Wahba's problem in the centred vectors.
  const Vec3 a0 = with_translation ? mean_reference : Vec3::Zero();
  const Vec3 b0 = with_translation ? mean_observed : Vec3::Zero();

  // W = const − tr(Qᵀ B) with the attitude profile matrix B = Σ α_K b_K ⊗ a_K.
  Tensor B = Tensor::Zero();
  for (const auto& o : observations) {
    B += o.weight * tensor_product(o.observed - b0, o.reference - a0);
  }
  // tr(Qᵀ B) is largest at Q = U diag(1, 1, det U det V) Vᵀ, B = U Σ Vᵀ.
  const Eigen::JacobiSVD<Tensor> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Tensor& U = svd.matrixU();
  const Tensor& V = svd.matrixV();
  const Vec3 d(1.0, 1.0, U.determinant() * V.determinant() < 0.0 ? -1.0 : 1.0);
  AttitudeEstimate estimate{U * d.asDiagonal() * V.transpose(), Vec3::Zero(), 0.0};
  estimate.translation = b0 - estimate.rotation * a0;

  // (6.37) W = ½ Σ α_K ‖b_K − Q a_K − d‖²
  for (const auto& o : observations) {
    const Vec3 residual = o.observed - estimate.rotation * o.reference - estimate.translation;
    estimate.loss += 0.5 * o.weight * residual.squaredNorm();
  }
  return estimate;
}

}  // namespace unidyn
