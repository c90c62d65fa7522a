// A system evaluated as a kinematic tree (include/unidyn/numeric/tree_evaluation.hpp).
#include "unidyn/numeric/tree_evaluation.hpp"

#include <algorithm>
#include <cmath>

#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/recorded_tree.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {

namespace {

// The numbers the constants tape gives per link: m, c (3), J0 (9), p (3), R0 (9), a (3).
constexpr std::size_t kLinkConstants = 28;

// Why a body is not a link of a tree the recursive algorithms take ("" when it is).
std::string why_not_link(const System& system, std::size_t b) {
  const Body& body = system.bodies[b];
  if (!body.joint) return "body '" + body.name + "' is not placed by a joint";
  const TreeJoint& joint = *body.joint;
  if (joint.parent && *joint.parent >= b) {
    return "body '" + body.name + "' comes before its parent";
  }
  for (std::size_t k = 1; k < joint.coordinates.size(); ++k) {
    if (joint.coordinates[k] != joint.coordinates[0] + k) {
      return "body '" + body.name + "''s joint coordinates are not consecutive";
    }
  }
  return "";
}

tree::JointKind link_kind(TreeJoint::Kind kind) {
  switch (kind) {
    case TreeJoint::Kind::revolute:
      return tree::JointKind::revolute;
    case TreeJoint::Kind::prismatic:
      return tree::JointKind::prismatic;
    case TreeJoint::Kind::ball:
      return tree::JointKind::ball;
    case TreeJoint::Kind::floating:
      return tree::JointKind::floating;
    default:
      return tree::JointKind::fixed;
  }
}

// The links' structure: parents, kinds and coordinates ("" in why_not when every body is one), and
// each body's link. A planar joint is three links: two massless frames sliding along E_k+1 and
// E_k+2 of its joint frame (x, y), then the body turning about a = ±E_k (θ) — the same frame,
// o = p + R0 (x E_k+1 + y E_k+2) and Q = R0 L(θ, a) (model/tree_joint.hpp).
tree::TreeModel tree_shape(const System& system, std::vector<std::size_t>& body_links,
                           std::string& why_not) {
  tree::TreeModel shape;
  shape.coordinates = system.coordinates().size();
  std::vector<int> owners(shape.coordinates, 0);
  for (std::size_t b = 0; b < system.bodies.size() && why_not.empty(); ++b) {
    why_not = why_not_link(system, b);
    if (!why_not.empty()) break;
    const TreeJoint& joint = *system.bodies[b].joint;
    tree::TreeLink link;
    link.parent = joint.parent ? static_cast<int>(body_links[*joint.parent]) : -1;
    link.kind = link_kind(joint.kind);
    if (joint.kind != TreeJoint::Kind::fixed) {
      link.coordinate = static_cast<int>(joint.coordinates.front());
      for (const std::size_t k : joint.coordinates) ++owners[k];
    }
    if (joint.kind == TreeJoint::Kind::planar) {
      // the slides along x and y, then the body's turn by θ
      for (int slide = 0; slide < 2; ++slide) {
        link.kind = tree::JointKind::prismatic;
        shape.links.push_back(link);
        link.parent = static_cast<int>(shape.links.size()) - 1;
        ++link.coordinate;
      }
      link.kind = tree::JointKind::revolute;
    }
    body_links.push_back(shape.links.size());
    shape.links.push_back(link);
  }
  for (std::size_t k = 0; k < owners.size() && why_not.empty(); ++k) {
    if (owners[k] != 1) {
      why_not = "coordinate '" + system.coordinates()[k].name + "' is not one joint's";
    }
  }
  return shape;
}

// Whether the constraints are ones the recursive path takes ("" in why_not when so): on a tree
// with ball or floating joints, only their Euler parameters' unit norms (constraints of the
// description, whose multipliers are 0); on another, bilateral constraints (loops closed over the
// tree: q̈ from its M and f and the rows, CompiledSystem::solve_tree) without friction or a switch.
bool takes_constraints(const System& system, const tree::TreeModel& shape, std::string& why_not) {
  std::vector<Expr> norms;
  for (const Body& body : system.bodies) {
    const TreeJoint& joint = *body.joint;
    if (joint.kind != TreeJoint::Kind::ball && joint.kind != TreeJoint::Kind::floating) continue;
    Expr norm = -1;
    for (auto k = joint.coordinates.end() - 4; k != joint.coordinates.end(); ++k) {
      norm += GiNaC::pow(system.coordinates()[*k].value, 2);
    }
    norms.push_back(norm);
  }
  const bool euler = tree::has_euler_parameters(shape);
  for (const Constraint& c : system.constraints) {
    const bool unit =
        c.parametrisation && std::any_of(norms.begin(), norms.end(), [&](const Expr& n) {
          return (c.expression - n).expand().is_zero();
        });
    if (euler && !unit) why_not = "it has the constraint '" + c.name + "'";
    if (c.unilateral) why_not = "its constraint '" + c.name + "' is unilateral";
    if (c.friction) why_not = "its constraint '" + c.name + "' is rough";
    if (!c.off_while.empty()) why_not = "its constraint '" + c.name + "' switches";
    if (!why_not.empty()) return false;
  }
  return true;
}

// Per link m, Qᵀ (x̄ − o), J0, p, R0, a; then the sum of the gravity fields g.
std::vector<Expr> link_constants(const System& system) {
  std::vector<Expr> out;
  VectorExpr g;
  for (const ForceElement& f : system.forces) {
    if (f.kind == ForceElement::Kind::gravity) g = g + f.field;
  }
  for (const Body& body : system.bodies) {
    const TreeJoint& joint = *body.joint;
    out.push_back(body.mass);
    for (unsigned i = 0; i < 3; ++i) {
      Expr c = 0;
      for (unsigned k = 0; k < 3; ++k) {
        c += body.rotation(k, i) *
             (body.center[static_cast<int>(k)] - body.origin[static_cast<int>(k)]);
      }
      out.push_back(c);
    }
    for (unsigned i = 0; i < 9; ++i) out.push_back(body.inertia(i / 3, i % 3));
    for (int i = 0; i < 3; ++i) out.push_back(joint.origin[i]);
    for (unsigned i = 0; i < 9; ++i) out.push_back(joint.fixed_rotation(i / 3, i % 3));
    for (int i = 0; i < 3; ++i) out.push_back(joint.axis[i]);
  }
  for (int i = 0; i < 3; ++i) out.push_back(g[i]);
  return out;
}

// τ: −∂U/∂q of the potentials and torsion springs, −c q̇ of the torsion and slide dampers ("" in
// why_not when every force is one of these or gravity).
std::vector<Expr> joint_forces(const System& system, std::string& why_not) {
  const auto& q = system.coordinates();
  std::vector<Expr> tau(q.size(), Expr(0));
  for (const ForceElement& f : system.forces) {
    using Kind = ForceElement::Kind;
    if (f.kind == Kind::gravity) continue;
    if (f.kind == Kind::potential || (f.kind == Kind::torsion_spring && f.angle)) {
      for (std::size_t k = 0; k < q.size(); ++k) tau[k] -= derivative(f.potential, q[k].value);
    } else if ((f.kind == Kind::torsion_damper || f.kind == Kind::slide_damper) && f.angle) {
      tau[*f.angle] -= f.coefficient * q[*f.angle].rate;
    } else {
      why_not =
          "its force '" + f.label + "' (line " + std::to_string(f.where.line) + ") acts at points";
      break;
    }
  }
  return tau;
}

// The coordinates the constants are evaluated at: 0, but e0 = 1 of each ball or floating joint
// (R(e) is not defined at e = 0).
std::vector<double> reference_coordinates(const tree::TreeModel& shape) {
  std::vector<double> q(shape.coordinates, 0.0);
  for (const tree::TreeLink& link : shape.links) {
    if (link.kind == tree::JointKind::ball) q[static_cast<std::size_t>(link.coordinate)] = 1;
    if (link.kind == tree::JointKind::floating)
      q[static_cast<std::size_t>(link.coordinate) + 3] = 1;
  }
  return q;
}

// Whether no force acts along a ball or floating joint's coordinates (the algorithm takes none
// there) — "" in why_not when none does.
bool no_forces_on_euler_joints(const tree::TreeModel& shape,
                               const std::vector<std::size_t>& body_links,
                               const std::vector<Expr>& tau, const System& system,
                               std::string& why_not) {
  for (std::size_t b = 0; b < body_links.size(); ++b) {
    const tree::TreeLink& link = shape.links[body_links[b]];
    if (!tree::has_euler_parameters(link)) continue;
    const std::size_t count = link.kind == tree::JointKind::ball ? 4 : 7;
    for (std::size_t k = 0; k < count; ++k) {
      if (!tau[static_cast<std::size_t>(link.coordinate) + k].is_zero()) {
        why_not = "a force acts on the coordinates of body '" + system.bodies[b].name +
                  "''s ball or floating joint";
        return false;
      }
    }
  }
  return true;
}

// Whether the constants are constant: the same at the start's zeros and at another state.
bool constants_hold(const Tape& constants, const tree::TreeModel& shape,
                    const std::vector<std::size_t>& body_links, const System& system,
                    std::string& why_not) {
  std::vector<double> zero(constants.input_count(), 0.0), other = zero;
  const std::size_t n = system.coordinates().size();
  const std::vector<double> reference = reference_coordinates(shape);
  std::copy(reference.begin(), reference.end(), zero.begin() + 1);
  for (std::size_t k = 0; k < 1 + 2 * n; ++k) other[k] = 0.37 + 0.11 * static_cast<double>(k);
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    zero[1 + 2 * n + k] = other[1 + 2 * n + k] = system.parameters[k].value;
  }
  const std::vector<double> a = constants.evaluate(zero), moved = constants.evaluate(other);
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!std::isfinite(a[k]) || std::abs(a[k] - moved[k]) > 1e-12 * (1 + std::abs(a[k]))) {
      const std::size_t body = k / kLinkConstants;
      why_not = body < system.bodies.size()
                    ? "body '" + system.bodies[body].name + "' has a number that moves with q or t"
                    : "gravity moves with q or t";
      return false;
    }
  }
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    if (tree::has_euler_parameters(shape.links[body_links[b]])) continue;  // no axis
    const double* axis = a.data() + b * kLinkConstants + 25;
    const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    if (std::abs(norm - 1) > 1e-12) {
      why_not = "the axis of body '" + system.bodies[b].name + "''s joint is not a unit vector";
      return false;
    }
  }
  return true;
}

// A body's link b from its constants c (m, c, J0, p, R0, a); a planar joint's body (after its two
// slides: links b − 2, b − 1) turns about a at the slides' frame, which the first places.
void set_link_numbers(const double* c, bool planar, std::vector<tree::TreeLink>& links,
                      std::size_t b) {
  tree::TreeLink& link = links[b];
  const Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>> J0(c + 4);
  link.inertia = tree::rigid_body_inertia(c[0], Eigen::Vector3d(c[1], c[2], c[3]), J0);
  link.origin = Eigen::Vector3d(c[13], c[14], c[15]);
  link.fixed_rotation = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(c + 16);
  link.axis = Eigen::Vector3d(c[25], c[26], c[27]);
  if (!planar) return;
  // a = ±E_k: the slides along E_k+1, E_k+2 of the joint frame
  Eigen::Index k = 0;
  while (k < 2 && link.axis[k] == 0) ++k;
  tree::TreeLink &x = links[b - 2], &y = links[b - 1];
  x.origin = link.origin;
  x.fixed_rotation = link.fixed_rotation;
  x.axis = Eigen::Vector3d::Unit((k + 1) % 3);
  y.axis = Eigen::Vector3d::Unit((k + 2) % 3);
  link.origin.setZero();
  link.fixed_rotation.setIdentity();
}

}  // namespace

TreePlan plan_tree(const System& system) {
  TreePlan plan;
  std::string& why_not = plan.why_not;
  if (!system.particles.empty()) why_not = "it has particles";
  if (!system.impulses.empty()) why_not = "it applies impulses";
  if (system.bodies.empty()) why_not = "it has no bodies";
  if (!why_not.empty()) return plan;
  std::vector<std::size_t> body_links;
  tree::TreeModel shape = tree_shape(system, body_links, why_not);
  if (!why_not.empty() || !takes_constraints(system, shape, why_not)) return plan;
  const std::vector<Expr> tau = joint_forces(system, why_not);
  if (!why_not.empty() || !no_forces_on_euler_joints(shape, body_links, tau, system, why_not)) {
    return plan;
  }
  const std::vector<Expr> inputs = tape_inputs(system, false);
  Tape constants = Tape::compile(link_constants(system), inputs);
  if (!constants_hold(constants, shape, body_links, system, why_not)) return plan;
  Expr potential = 0;
  for (const ForceElement& f : system.forces) {
    if (f.kind != ForceElement::Kind::gravity) potential += f.potential;
  }
  plan.tree = std::make_shared<const TreeEvaluation>(
      std::move(shape), std::move(body_links), std::move(constants), Tape::compile(tau, inputs),
      Tape::compile(std::vector<Expr>{potential}, inputs), system.parameters.size());
  return plan;
}

TreeEvaluation::TreeEvaluation(tree::TreeModel shape, std::vector<std::size_t> body_links,
                               Tape constants, Tape joint_forces, Tape potentials,
                               std::size_t parameters)
    : shape_(std::move(shape)),
      body_links_(std::move(body_links)),
      constants_(std::move(constants)),
      joint_forces_(std::move(joint_forces)),
      potentials_(std::move(potentials)),
      reference_(reference_coordinates(shape_)),
      p_(parameters),
      forms_mass_matrix_(!tree::has_euler_parameters(shape_)) {}

TreeEvaluationData TreeEvaluation::make_data() const {
  TreeEvaluationData data;
  data.model = shape_;
  data.tree = tree::TreeData(shape_);
  data.workspace.reserve(constants_);
  data.workspace.reserve(joint_forces_);
  data.workspace.reserve(potentials_);
  data.inputs.assign(constants_.input_count(), 0.0);
  data.outputs.resize(std::max(constants_.output_count(), joint_forces_.output_count()));
  data.joint_forces.resize(static_cast<Eigen::Index>(shape_.coordinates));
  return data;
}

void TreeEvaluation::prepare(double t, tree::TreeVector q, tree::TreeVector qdot,
                             std::span<const double> parameters, TreeEvaluationData& data) const {
  if (parameters.size() != p_) throw std::invalid_argument("wrong number of parameter values");
  const std::size_t n = shape_.coordinates;
  // the numbers again only for new parameters (at t, q, q̇ = 0); the parameters stay in the inputs
  if (!data.evaluated || !std::equal(parameters.begin(), parameters.end(), data.parameters.begin(),
                                     data.parameters.end())) {
    std::fill(data.inputs.begin(), data.inputs.end(), 0.0);
    std::copy(reference_.begin(), reference_.end(), data.inputs.begin() + 1);
    std::copy(parameters.begin(), parameters.end(),
              data.inputs.begin() + 1 + 2 * static_cast<long>(n));
    constants_.evaluate(data.inputs, std::span(data.outputs.data(), constants_.output_count()),
                        data.workspace);
    const double* c = data.outputs.data();
    for (std::size_t b = 0; b < body_links_.size(); ++b) {
      // a planar joint's two slides are the links just before its body's
      const bool planar = body_links_[b] == (b == 0 ? 0 : body_links_[b - 1] + 1) + 2;
      set_link_numbers(c, planar, data.model.links, body_links_[b]);
      c += kLinkConstants;
    }
    data.model.gravity = Eigen::Vector3d(c[0], c[1], c[2]);
    data.parameters.assign(parameters.begin(), parameters.end());
    data.evaluated = true;
  }
  data.inputs[0] = t;
  for (std::size_t i = 0; i < n; ++i) {
    data.inputs[1 + i] = q[static_cast<Eigen::Index>(i)];
    data.inputs[1 + n + i] = qdot[static_cast<Eigen::Index>(i)];
  }
  joint_forces_.evaluate(data.inputs,
                         std::span(data.joint_forces.data(), joint_forces_.output_count()),
                         data.workspace);
}

void TreeEvaluation::accelerations(double t, tree::TreeVector q, tree::TreeVector qdot,
                                   std::span<const double> parameters, Eigen::VectorXd& qddot,
                                   TreeEvaluationData& data) const {
  prepare(t, q, qdot, parameters, data);
  tree::articulated_body_accelerations(data.model, q, qdot, data.joint_forces, qddot, data.tree);
}

Tape TreeEvaluation::recorded_accelerations(std::span<const double> parameters) const {
  TreeEvaluationData data = make_data();
  const Eigen::VectorXd q = Eigen::Map<const Eigen::VectorXd>(
      reference_.data(), static_cast<Eigen::Index>(reference_.size()));
  prepare(0, q, Eigen::VectorXd::Zero(q.size()), parameters, data);
  return record_tree_accelerations(data.model, joint_forces_, parameters);
}

void TreeEvaluation::energies(double t, tree::TreeVector q, tree::TreeVector qdot,
                              std::span<const double> parameters, double& T, double& U,
                              TreeEvaluationData& data) const {
  prepare(t, q, qdot, parameters, data);
  double other = 0;
  potentials_.evaluate(data.inputs, std::span(&other, 1), data.workspace);
  T = tree::tree_kinetic_energy(data.model, q, qdot, data.tree);
  U = tree::tree_gravity_potential(data.model, q, data.tree) + other;
}

void TreeEvaluation::mass_and_forcing(double t, tree::TreeVector q, tree::TreeVector qdot,
                                      std::span<const double> parameters, Eigen::MatrixXd& M,
                                      Eigen::VectorXd& f, TreeEvaluationData& data) const {
  prepare(t, q, qdot, parameters, data);
  tree::composite_inertia_mass_matrix(data.model, q, M, data.tree);
  tree::inverse_dynamics_bias(data.model, q, qdot, data.bias, data.tree);
  f = data.joint_forces - data.bias;
}

}  // namespace unidyn
