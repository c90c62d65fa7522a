// Spatial inertias moved between frames, and a rigid body's (include/unidyn/tree/spatial.hpp).
#include "unidyn/tree/spatial.hpp"

namespace unidyn::tree {

Matrix6d inertia_to_parent(const FramePlacement& X, const Matrix6d& I) {
  const Eigen::Matrix3d& E = X.rotation;
  // the blocks on the parent's basis, still about the child's origin
  const Eigen::Matrix3d A = E * I.topLeftCorner<3, 3>() * E.transpose();
  const Eigen::Matrix3d B = E * I.topRightCorner<3, 3>() * E.transpose();
  const Eigen::Matrix3d C = E * I.bottomRightCorner<3, 3>() * E.transpose();
  // Steiner: about the parent's origin, r× = R
  const Eigen::Matrix3d R = cross_matrix(X.offset);
  const Eigen::Matrix3d RBt = R * B.transpose();
  Matrix6d out;
  out.topLeftCorner<3, 3>() = A + RBt + RBt.transpose() - R * C * R;
  out.topRightCorner<3, 3>() = B + R * C;
  out.bottomLeftCorner<3, 3>() = out.topRightCorner<3, 3>().transpose();
  out.bottomRightCorner<3, 3>() = C;
  return out;
}

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
