// A body's frame from its parent's by a joint (include/unidyn/model/tree_joint.hpp).
#include "unidyn/model/tree_joint.hpp"

#include "unidyn/symbolic/trig_identities.hpp"

namespace unidyn {

std::size_t joint_coordinate_count(TreeJoint::Kind kind) {
  switch (kind) {
    case TreeJoint::Kind::fixed:
      return 0;
    case TreeJoint::Kind::revolute:
    case TreeJoint::Kind::prismatic:
      return 1;
    case TreeJoint::Kind::planar:
      return 3;
    case TreeJoint::Kind::ball:
      return 4;
    case TreeJoint::Kind::floating:
      return 7;
  }
  return 0;
}

namespace {

// The joint's motion on the joint frame: R(q) and d(q).
FrameExpr joint_motion(const TreeJoint& joint, const std::vector<CoordinateSymbols>& coordinates) {
  std::vector<Expr> q;
  for (const std::size_t i : joint.coordinates) q.push_back(coordinates[i].value);
  FrameExpr motion;
  switch (joint.kind) {
    case TreeJoint::Kind::fixed:
      break;
    // (6.8) L(q, a)
    case TreeJoint::Kind::revolute:
      motion.rotation = axis_angle_rotation_expr(joint.axis, q[0]);
      break;
    case TreeJoint::Kind::prismatic:
      motion.origin = q[0] * joint.axis;
      break;
    // (6.36) the Euler parameters' rotation, and the origin's components
    case TreeJoint::Kind::floating:
      motion.origin = VectorExpr(q[0], q[1], q[2]);
      motion.rotation = euler_parameter_rotation_expr(q[3], VectorExpr(q[4], q[5], q[6]));
      break;
    // (6.36) a ball joint: the Euler parameters' rotation about the joint frame's origin
    case TreeJoint::Kind::ball:
      motion.rotation = euler_parameter_rotation_expr(q[0], VectorExpr(q[1], q[2], q[3]));
      break;
    // a = ±E_k: slide along E_k+1 and E_k+2, turn about a
    case TreeJoint::Kind::planar: {
      int k = 0;
      while (k < 2 && joint.axis[k].is_zero()) ++k;
      motion.origin =
          q[0] * basis_vector_expr((k + 1) % 3 + 1) + q[1] * basis_vector_expr((k + 2) % 3 + 1);
      motion.rotation = axis_angle_rotation_expr(joint.axis, q[2]);
      break;
    }
  }
  return motion;
}

}  // namespace

// Q_B = Q_P R0 R(q), o_B = o_P + Q_P (p + R0 d(q)), each entry with its angle sums combined: a
// chain of parallel axes keeps cos(q1 + q2 + q3) rather than the 2^k products its matrices
// multiply out to (a 20-link planar chain would not fit in memory).
FrameExpr child_frame(const TreeJoint& joint, const FrameExpr& parent,
                      const std::vector<CoordinateSymbols>& coordinates) {
  const FrameExpr motion = joint_motion(joint, coordinates);
  const TensorExpr joint_frame = parent.rotation.mul(joint.fixed_rotation);
  FrameExpr child{
      parent.origin + times(parent.rotation, joint.origin) + times(joint_frame, motion.origin),
      joint_frame.mul(motion.rotation)};
  for (int i = 0; i < 3; ++i) {
    child.origin[i] = combine_angle_sums(child.origin[i]);
    for (unsigned k = 0; k < 3; ++k) {
      child.rotation(static_cast<unsigned>(i), k) =
          combine_angle_sums(child.rotation(static_cast<unsigned>(i), k));
    }
  }
  return child;
}

}  // namespace unidyn
