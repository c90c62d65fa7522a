// A system that is a kinematic tree of joints (URDF and MJCF robots, the model language's
// `joint:`s), evaluated by the recursive algorithms of tree/ instead of the compiled M and f: q̈ by
// the articulated-body algorithm in O(n), with no equations formed (so no M to factorise).
//
// The symbolic model gives the numbers: each body's mass, centre of mass on its frame's basis
// (Qᵀ (x̄ − o)), J0, and its joint's p, R0 and axis, compiled on a tape of the parameters and
// evaluated again when they change; the joint forces τ (potentials in the coordinates, the joints'
// torsion springs and dampers) on a tape of the state. Gravity is a uniform field g.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/tape.hpp"
#include "unidyn/tree/tree_dynamics.hpp"

namespace unidyn {

// One evaluation's numbers (one per thread): the tree at the parameters it was last evaluated at.
struct TreeEvaluationData {
  tree::TreeModel model;
  std::vector<double> parameters;
  bool evaluated = false;
  tree::TreeData tree;
  TapeWorkspace workspace;
  std::vector<double> inputs, outputs;
  Eigen::VectorXd joint_forces, bias;
};

class TreeEvaluation;

// The tree of a system, or why the recursive algorithms do not take it (then tree is null).
struct TreePlan {
  std::shared_ptr<const TreeEvaluation> tree;
  std::string why_not;
};

// The system as a tree when it is one: every body on a fixed, revolute, prismatic, ball, floating
// or planar joint (three links: two slides and a turn), every coordinate one joint's, no particles
// or impulses, no constraint but the Euler parameters' unit norms (their multipliers are 0:
// tree/euler_parameter_joint.hpp) or, on a tree without them, bilateral constraints without
// friction (loops closed over the tree), and no force but gravity, potentials in the one-coordinate
// joints' coordinates and torsion springs and dampers on joint angles.
TreePlan plan_tree(const System& system);

class TreeEvaluation {
 public:
  TreeEvaluation(tree::TreeModel shape, std::vector<std::size_t> body_links, Tape constants,
                 Tape joint_forces, Tape potentials, std::size_t parameters);

  TreeEvaluationData make_data() const;
  // q̈ at (t, q, q̇); throws std::domain_error where the tree's inertia about a joint is not
  // positive.
  void accelerations(double t, tree::TreeVector q, tree::TreeVector qdot,
                     std::span<const double> parameters, Eigen::VectorXd& qddot,
                     TreeEvaluationData& data) const;
  // T and U: the tree's, gravity's and the potentials' in the coordinates and the torsion springs'.
  void energies(double t, tree::TreeVector q, tree::TreeVector qdot,
                std::span<const double> parameters, double& T, double& U,
                TreeEvaluationData& data) const;
  // Whether mass_and_forcing() is defined: not for a ball or floating joint (the model
  // language's M in Euler parameters is not the tree's; CompiledSystem takes the equations).
  bool forms_mass_matrix() const { return forms_mass_matrix_; }
  // q̈'s tape recorded at `parameters`: inputs [t, q, q̇, p], outputs q̈ and the pivots
  // (numeric/recorded_tree.hpp).
  Tape recorded_accelerations(std::span<const double> parameters) const;
  // M and f of M q̈ = f: f = τ − b.
  void mass_and_forcing(double t, tree::TreeVector q, tree::TreeVector qdot,
                        std::span<const double> parameters, Eigen::MatrixXd& M, Eigen::VectorXd& f,
                        TreeEvaluationData& data) const;

 private:
  // the tree's numbers at the parameters (again only when they changed), and τ at the state
  void prepare(double t, tree::TreeVector q, tree::TreeVector qdot,
               std::span<const double> parameters, TreeEvaluationData& data) const;

  tree::TreeModel shape_;                // the links' parents, kinds and coordinates
  std::vector<std::size_t> body_links_;  // each body's link (after a planar joint's two slides)
  Tape constants_;     // [t, q, q̇, p] (at t, q, q̇ = 0) → per link m, c, J0, p, R0, a; then g
  Tape joint_forces_;  // [t, q, q̇, p] → τ
  Tape potentials_;    // [t, q, q̇, p] → U of the forces other than gravity
  std::vector<double> reference_;  // q of the constants: 0, e0 = 1
  std::size_t p_ = 0;
  bool forms_mass_matrix_ = true;  // no ball or floating joint
};

}  // namespace unidyn
