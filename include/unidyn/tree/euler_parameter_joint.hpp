// Ball and floating joints of a tree (tree_model.hpp): their Euler parameters e = (e0, ε) and
// rates ė as the twist ν = (ω, v) of the link on its own basis, and back from ν̇ to ë (and d̈).
//
// (6.36) R(e) = ((e0² − ε · ε) 1 + 2 ε εᵀ + 2 e0 ε×) / |e|² is a rotation for every e ≠ 0, as the
// model language writes it: it sees only the unit ê = e / s (s = |e|), and the norm s is free —
// the constraint e · e = 1 fixes it, and its multiplier is 0 (no force depends on s). With ê as
// a unit quaternion, ê̇ = ½ ê ⊗ (0, ω) for ω on the link's basis, so
//
//   ω = 2 (ê0 ε̂̇ − ê̇0 ε̂ − ε̂ × ε̂̇),    ê̈ = ½ ê ⊗ (0, ω̇) − ¼ |ω|² ê,
//
// and e = s ê gives ë = s̈ ê + 2 ṡ ê̇ + s ê̈ with s̈ = −ṡ² / s, the s that keeps e · ë + ė · ė = 0
// (the constraint's second derivative) whatever the state. A floating joint's d on the joint
// frame has ḋ = R v and d̈ = R (v̇ + ω × v).
#pragma once

#include "unidyn/tree/tree_model.hpp"

namespace unidyn::tree {

// The link's placement E_i = R0 R(ê), r_i = p (+ R0 d) at q; fills ê, s and R(ê).
FramePlacement euler_joint_placement(const TreeLink& link, TreeVector q, EulerJointData& joint);

// The placement and the joint's twist ν at (q, q̇); fills ṡ and ê̇ too.
FramePlacement euler_joint_kinematics(const TreeLink& link, TreeVector q, TreeVector qdot,
                                      EulerJointData& joint);

// ë (and d̈) of the link's coordinates from the joint's twist rate ν̇ (its first 3 or 6
// components), written into qddot.
void euler_joint_accelerations(const TreeLink& link, const EulerJointData& joint,
                               const Vector6d& rate_of_twist, Eigen::VectorXd& qddot);

}  // namespace unidyn::tree
