// A body placed on its parent by a joint: the kinematic tree of URDF and MJCF files, written in
// the model language as `joint:` on a body (docs/model-format.md).
//
// Each body carries a frame {o; e1, e2, e3}: its origin o and the basis e_i = Q E_i of its
// rotation Q. A joint fixes a joint frame on the parent's frame — the origin p (components on the
// parent's basis) and the rotation R0 — and moves the child's frame on it by the joint's
// coordinates: a rotation R(q) and a displacement d(q) on the joint frame's basis,
//   Q_B = Q_P R0 R(q),   o_B = o_P + Q_P (p + R0 d(q))                  (composition, (6.49))
// revolute: R = L(q, a) (6.8), d = 0;  prismatic: R = I, d = q a;
// floating: R from the Euler parameters (6.36), d = (x, y, z); ball: R from them, d = 0;
// planar (a = E_k): R = L(θ, a), d = x E_k+1 + y E_k+2 (indices cyclic).
// The ground's frame is {O; E1, E2, E3}; a body without a joint has its frame at its centre of
// mass with its own basis.
#pragma once

#include <optional>
#include <vector>

#include "unidyn/symbolic/coordinates.hpp"
#include "unidyn/symbolic/rotation_expr.hpp"

namespace unidyn {

struct TreeJoint {
  enum class Kind { fixed, revolute, prismatic, floating, planar, ball };
  Kind kind = Kind::fixed;
  std::optional<std::size_t> parent;                   // a body; none: the ground
  VectorExpr origin;                                   // p, on the parent's frame basis
  TensorExpr fixed_rotation = identity_tensor_expr();  // R0, on the parent's frame basis
  VectorExpr axis;                                     // a, unit, on the joint frame's basis
  std::vector<std::size_t>
      coordinates;  // q; floating: x y z e0 e1 e2 e3; planar: x y θ; ball: e0..e3
};

// A frame {o; Q}: its origin and rotation.
struct FrameExpr {
  VectorExpr origin;
  TensorExpr rotation = identity_tensor_expr();
};

// The coordinates a joint of each kind takes.
std::size_t joint_coordinate_count(TreeJoint::Kind kind);

// The child's frame from its parent's frame (the ground's: FrameExpr{}) and the joint.
FrameExpr child_frame(const TreeJoint& joint, const FrameExpr& parent,
                      const std::vector<CoordinateSymbols>& coordinates);

}  // namespace unidyn
