// The recursive dynamics of a kinematic tree (tree_model.hpp), M(q) q̈ = τ − b(q, q̇) with b the
// Coriolis, centripetal and gravity forces — the book's Lagrange's equations (M q̈ = f, f = τ − b)
// of the tree, computed without forming them (Featherstone 2008):
//   articulated_body_accelerations  q̈ in O(n) (ABA, ch. 7);
//   composite_inertia_mass_matrix   M in O(n d), d the tree's depth (CRBA, ch. 6);
//   inverse_dynamics_bias           b = τ at q̈ = 0 (recursive Newton–Euler, ch. 5);
// and the energies T and gravity's U.
#pragma once

#include "unidyn/tree/tree_model.hpp"

namespace unidyn::tree {

// q̈ of the tree under the joint forces τ (one per coordinate); a template over the scalar
// (articulated_body.hpp), double's compiled once.
template <class S>
void articulated_body_accelerations(const TreeModel& model,
                                    std::type_identity_t<BasicTreeVector<S>> q,
                                    std::type_identity_t<BasicTreeVector<S>> qdot,
                                    std::type_identity_t<BasicTreeVector<S>> tau,
                                    Eigen::Matrix<S, Eigen::Dynamic, 1>& qddot,
                                    BasicTreeData<S>& data);
extern template void articulated_body_accelerations<double>(const TreeModel&, TreeVector,
                                                            TreeVector, TreeVector,
                                                            Eigen::VectorXd&, TreeData&);

// M(q), n × n, both triangles. One-coordinate joints only (std::invalid_argument for a ball or
// floating joint: the model language's M in Euler parameters is not the tree's).
void composite_inertia_mass_matrix(const TreeModel& model, TreeVector q, Eigen::MatrixXd& M,
                                   TreeData& data);

// b(q, q̇): the joint forces that give q̈ = 0. One-coordinate joints only, as M.
void inverse_dynamics_bias(const TreeModel& model, TreeVector q, TreeVector qdot,
                           Eigen::VectorXd& bias, TreeData& data);

// T = Σ ½ V_iᵀ I_i V_i.
double tree_kinetic_energy(const TreeModel& model, TreeVector q, TreeVector qdot, TreeData& data);

// Gravity's U = −Σ m g · x̄.
double tree_gravity_potential(const TreeModel& model, TreeVector q, TreeData& data);

}  // namespace unidyn::tree
