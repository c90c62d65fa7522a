// A tree's kinetic energy and gravity's potential energy (include/unidyn/tree/tree_dynamics.hpp).
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {

double tree_kinetic_energy(const TreeModel& model, TreeVector q, TreeVector qdot, TreeData& data) {
  tree_kinematics(model, q, qdot, data);
  // (7.x) T = Σ ½ Vᵀ I V: Koenig's ½ m v̄ · v̄ + ½ ω · J ω of each body, about its frame's origin
  double T = 0;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const Vector6d& V = data.links[i].velocity;
    T += 0.5 * V.dot(model.links[i].inertia * V);
  }
  return T;
}

double tree_gravity_potential(const TreeModel& model, TreeVector q, TreeData& data) {
  tree_placements(model, q, data);
  // each frame on the ground's basis, Q_i = Q_parent E_i, o_i = o_parent + Q_parent r_i; then
  // (2.5) U = −Σ m g · x̄ with m x̄ = m o + Q h (h = m c, read off I's block h×)
  std::vector<Eigen::Matrix3d> Q(model.links.size());
  std::vector<Eigen::Vector3d> o(model.links.size());
  double U = 0;
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    const FramePlacement& X = data.links[i].placement;
    if (link.parent < 0) {
      Q[i] = X.rotation;
      o[i] = X.offset;
    } else {
      const auto p = static_cast<std::size_t>(link.parent);
      Q[i] = Q[p] * X.rotation;
      o[i] = o[p] + Q[p] * X.offset;
    }
    const Matrix6d& I = link.inertia;
    const Eigen::Vector3d h(I(2, 4), I(0, 5), I(1, 3));
    U -= model.gravity.dot(I(3, 3) * o[i] + Q[i] * h);
  }
  return U;
}

}  // namespace unidyn::tree
