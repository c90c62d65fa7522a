// A rigid body's spatial inertia (include/unidyn/tree/spatial.hpp).
#include "unidyn/tree/spatial.hpp"

namespace unidyn::tree {

Matrix6d rigid_body_inertia(double mass, const Eigen::Vector3d& center,
                            const Eigen::Matrix3d& central_inertia) {
  const Eigen::Vector3d h = mass * center;
  const Eigen::Matrix3d H = cross_matrix(h);
  Matrix6d I;
  // (7.x) parallel axes: Ī_o = J0 + m (|c|² 1 − c cᵀ)
  I.topLeftCorner<3, 3>() =
      central_inertia +
      mass * (center.squaredNorm() * Eigen::Matrix3d::Identity() - center * center.transpose());
  I.topRightCorner<3, 3>() = H;
  I.bottomLeftCorner<3, 3>() = -H;
  I.bottomRightCorner<3, 3>() = mass * Eigen::Matrix3d::Identity();
  return I;
}

}  // namespace unidyn::tree
