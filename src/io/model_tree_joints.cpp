// The model file's tree joints: `joint:` on a body places it on its parent (docs/model-format.md,
// include/unidyn/model/tree_joint.hpp), as URDF and MJCF files describe a robot.
#include "model_reader.hpp"

#include "unidyn/symbolic/printing.hpp"

namespace unidyn::model_reading {

namespace {

// The motions a joint may name, each with the coordinates it takes.
const std::vector<std::pair<std::string, TreeJoint::Kind>>& joint_motions() {
  static const std::vector<std::pair<std::string, TreeJoint::Kind>> motions = {
      {"revolute", TreeJoint::Kind::revolute},
      {"prismatic", TreeJoint::Kind::prismatic},
      {"floating", TreeJoint::Kind::floating},
      {"planar", TreeJoint::Kind::planar},
      {"ball", TreeJoint::Kind::ball}};
  return motions;
}

}  // namespace

// Q_B = Q_P R0 R(q), o_B = o_P + Q_P (p + R0 d(q)) on the parent's frame (the ground's: O, E_i).
void ModelReader::place_by_joint(const YAML::Node& node, Body& body, System& system) {
  const TreeJoint joint = tree_joint(node, system);
  FrameExpr parent;
  if (joint.parent) {
    const Body& p = system.bodies[*joint.parent];
    parent = {p.origin, p.rotation};
  }
  const FrameExpr frame = child_frame(joint, parent, system.coordinates());
  body.rotation = frame.rotation;
  body.origin = frame.origin;
  body.joint = joint;
  // a floating or ball joint's Euler parameters keep e0² + e · e = 1, as a quaternion rotation's do
  if (joint.kind == TreeJoint::Kind::floating || joint.kind == TreeJoint::Kind::ball) {
    const std::vector<std::size_t> e(joint.coordinates.end() - 4, joint.coordinates.end());
    add_unit_norm_constraint(e, body.name, at(node), system);
  }
}

// joint: {parent, origin, rpy | rotation, revolute | prismatic | floating | planar, axis}
TreeJoint ModelReader::tree_joint(const YAML::Node& node, const System& system) {
  expect_map(node, "joint");
  expect_keys(node,
              {"parent", "origin", "rpy", "rotation", "revolute", "prismatic", "floating", "planar",
               "ball", "axis"},
              "a joint");
  TreeJoint joint;
  if (node["parent"]) {
    joint.parent = system.find_body(scalar(node["parent"], "parent"));
    if (!joint.parent) fail(node["parent"], "parent: names a body given before this one");
  }
  if (node["origin"]) joint.origin = constant_vector(node["origin"], system, "origin");
  if (node["rpy"] && node["rotation"]) fail(node, "a joint has rpy: or rotation:, not both");
  // URDF's roll, pitch, yaw about the fixed x, y, z: Rz(y) Ry(p) Rx(r), the 3-2-1 set (6.25)
  if (node["rpy"]) {
    const VectorExpr rpy = constant_vector(node["rpy"], system, "rpy");
    joint.fixed_rotation = euler_rotation_expr(*EulerSet::parse("3-2-1"), rpy[2], rpy[1], rpy[0]);
  }
  if (node["rotation"]) {
    joint.fixed_rotation = rotation(node["rotation"], system);
    for (unsigned i = 0; i < 3; ++i) {
      for (unsigned k = 0; k < 3; ++k) {
        expect_parameters_only(node["rotation"], joint.fixed_rotation(i, k), system,
                               "a joint's fixed rotation is constant (numbers and parameters)");
      }
    }
  }
  for (const auto& [key, kind] : joint_motions()) {
    if (!node[key]) continue;
    if (joint.kind != TreeJoint::Kind::fixed) fail(node[key], "a joint has one motion");
    joint.kind = kind;
    joint.coordinates = joint_coordinates(node[key], kind, system);
  }
  const bool has_axis = joint.kind == TreeJoint::Kind::revolute ||
                        joint.kind == TreeJoint::Kind::prismatic ||
                        joint.kind == TreeJoint::Kind::planar;
  if (node["axis"] && !has_axis) {
    fail(node["axis"], "axis: is for a revolute, prismatic or planar joint");
  }
  joint.axis = joint_axis(node, joint.kind, system);
  return joint;
}

// The coordinates a motion names: one (revolute, prismatic), [x, y, z, e0, e1, e2, e3] (floating)
// or [x, y, theta] (planar) or [e0, e1, e2, e3] (ball); each moves one joint.
std::vector<std::size_t> ModelReader::joint_coordinates(const YAML::Node& node,
                                                        TreeJoint::Kind kind,
                                                        const System& system) {
  const std::size_t count = joint_coordinate_count(kind);
  std::vector<YAML::Node> names;
  if (count == 1) {
    names.push_back(node);
  } else {
    if (!node.IsSequence() || node.size() != count) {
      fail(node, kind == TreeJoint::Kind::floating
                     ? "floating: takes seven coordinates [x, y, z, e0, e1, e2, e3]"
                 : kind == TreeJoint::Kind::ball ? "ball: takes four coordinates [e0, e1, e2, e3]"
                                                 : "planar: takes three coordinates [x, y, theta]");
    }
    for (const auto& n : node) names.push_back(n);
  }
  std::vector<std::size_t> out;
  for (const auto& n : names) {
    const std::string name = scalar(n, "a coordinate");
    const auto q = system.find_coordinate(name);
    if (!q) fail(n, "'" + name + "' is not one of the coordinates");
    for (const Body& b : system.bodies) {
      if (b.joint && std::count(b.joint->coordinates.begin(), b.joint->coordinates.end(), *q))
        fail(n, "coordinate '" + name + "' already moves the joint of body '" + b.name + "'");
    }
    if (std::count(out.begin(), out.end(), *q)) fail(n, "a joint's coordinates differ");
    out.push_back(*q);
  }
  return out;
}

// The axis: numbers on the joint frame, divided by its length; default E1 (URDF's); a planar
// joint's is ±E1, ±E2 or ±E3.
VectorExpr ModelReader::joint_axis(const YAML::Node& node, TreeJoint::Kind kind,
                                   const System& system) {
  if (!node["axis"]) return basis_vector_expr(1);
  const VectorExpr axis = constant_vector(node["axis"], system, "axis");
  const Expr length_squared = simplify(dot(axis, axis));
  if (length_squared.is_zero()) fail(node["axis"], "a joint's axis must not be the zero vector");
  if (kind == TreeJoint::Kind::planar) {
    int zeros = 0;
    for (int i = 0; i < 3; ++i) zeros += axis[i].is_zero() ? 1 : 0;
    if (zeros != 2) fail(node["axis"], "a planar joint's axis is along E1, E2 or E3 of its frame");
  }
  return axis / GiNaC::sqrt(length_squared);
}

// A vector of numbers and parameters.
VectorExpr ModelReader::constant_vector(const YAML::Node& node, const System& system,
                                        const std::string& what) {
  const VectorExpr v = vector_expr(node, SystemScope(system), what);
  for (int i = 0; i < 3; ++i) {
    expect_parameters_only(node, v[i], system, what + " is constant: numbers and parameters");
  }
  return v;
}

}  // namespace unidyn::model_reading
