// The composite-rigid-body algorithm (Featherstone 2008, §6.2): M(q) of a tree.
//
// With I^c_i the inertia of link i and everything beyond it as one rigid body (each child's added,
// moved to the parent's frame), the wrench F = I^c_i S_i that q̈_i = 1 needs is carried toward the
// root, and each joint j it passes takes M_ji = S_jᵀ F: its share of moving the subtree of i.
#include <stdexcept>

#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn::tree {

void composite_inertia_mass_matrix(const TreeModel& model, TreeVector q, Eigen::MatrixXd& M,
                                   TreeData& data) {
  if (has_euler_parameters(model)) {
    throw std::invalid_argument("composite_inertia_mass_matrix: a ball or floating joint");
  }
  tree_placements(model, q, data);
  // I^c_i = I_i + Σ_children X_cᵀ I^c_c X_c, from the leaves inward
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    data.links[i].articulated = model.links[i].inertia;
  }
  for (std::size_t k = model.links.size(); k-- > 0;) {
    const int parent = model.links[k].parent;
    if (parent < 0) continue;
    data.links[static_cast<std::size_t>(parent)].articulated +=
        inertia_to_parent(data.links[k].placement, data.links[k].articulated);
  }
  const auto n = static_cast<Eigen::Index>(model.coordinates);
  M.setZero(n, n);
  for (std::size_t i = 0; i < model.links.size(); ++i) {
    const TreeLink& link = model.links[i];
    if (link.coordinate < 0) continue;
    // F = I^c_i S_i, moved link by link toward the root
    Vector6d F = data.links[i].articulated * joint_axis(link);
    M(link.coordinate, link.coordinate) = joint_axis(link).dot(F);
    for (std::size_t j = i; model.links[j].parent >= 0;) {
      F = wrench_to_parent(data.links[j].placement, F);
      j = static_cast<std::size_t>(model.links[j].parent);
      const TreeLink& ancestor = model.links[j];
      if (ancestor.coordinate < 0) continue;
      M(ancestor.coordinate, link.coordinate) = joint_axis(ancestor).dot(F);
      M(link.coordinate, ancestor.coordinate) = M(ancestor.coordinate, link.coordinate);
    }
  }
}

}  // namespace unidyn::tree
