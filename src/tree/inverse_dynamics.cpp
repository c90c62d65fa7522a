// The recursive Newton–Euler algorithm (Featherstone 2008, §5.3) at q̈ = 0: the bias forces
// b(q, q̇) of M q̈ = τ − b.
//
// Outward, each link's acceleration with no joint accelerating, A_i = X_i A_parent + c_i (the
// ground's (0, −g) brings gravity), and the wrench its motion needs, (8.x) the balance of
// momentum and of angular momentum about its origin: W_i = I A_i + V_i ×* I V_i. Inward, each
// link's joint transmits the wrench of it and all beyond it; the joint's share is b_i = S_iᵀ W_i.
#include <stdexcept>

#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {

void inverse_dynamics_bias(const TreeModel& model, TreeVector q, TreeVector qdot,
                           Eigen::VectorXd& bias, TreeData& data) {
  if (has_euler_parameters(model)) {
    throw std::invalid_argument("inverse_dynamics_bias: a ball or floating joint");
  }
  tree_kinematics(model, q, qdot, data);
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    LinkData& d = data.links[i];
    d.acceleration = carried_acceleration(model, data, i);
    d.force = link.inertia * d.acceleration +
              wrench_cross(d.velocity, Vector6d(link.inertia * d.velocity));
  }
  bias.resize(static_cast<Eigen::Index>(model.coordinates));
  for (std::size_t k = model.links.size(); k-- > 0;) {
    const TreeLink& link = model.links[k];
    const LinkData& d = data.links[k];
    if (link.coordinate >= 0) bias[link.coordinate] = joint_axis(link).dot(d.force);
    if (link.parent < 0) continue;
    data.links[static_cast<std::size_t>(link.parent)].force +=
        wrench_to_parent(d.placement, d.force);
  }
}

}  // namespace unidyn::tree
