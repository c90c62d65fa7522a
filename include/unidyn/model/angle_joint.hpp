// The joint a coordinate is the angle of: a body B turning relative to another body P (or to the
// ground) about a unit axis w by that angle alone (book §8.6: the relative angular velocity of a
// pin joint).
//
// A coordinate q is the angle of a joint between B and P when their relative angular velocity is
// q̇ times a unit vector:
//   ω_B − ω_P = q̇ w,   ‖w‖ = 1   (ω_P = 0 for the ground),
// i.e. ∂(ω_B − ω_P)/∂q̇_k = 0 for every other coordinate, w = ∂(ω_B − ω_P)/∂q̇ and w · w = 1.
// Then equal and opposite moments τ w on B and −τ w on P have the generalised forces
//   Q_k = τ w · ∂(ω_B − ω_P)/∂q̇_k = τ δ_kq,
// so a torsion spring or damper in the joint acts on q alone, as its potential or its rate says.
// For one of a body's Euler angles γ^i, the moment τ g^i along the dual Euler basis vector (8.27)
// has the same property: Q_k = τ g^i · ∂ω/∂γ̇^k = τ δ_ik.
#pragma once

#include <optional>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct AngleJoint {
  std::size_t body;                   // B, turned by the angle
  std::optional<std::size_t> parent;  // P, or the ground when empty
  VectorExpr axis;                    // w on E1, E2, E3
};

// The joint whose angle is coordinate q, or none. Among several pairs, the first body B in the
// model's order, with its parent P first in order (a body before the ground).
std::optional<AngleJoint> joint_of_angle(const System& system, std::size_t q);

// The moments of a unit torque about angle q: per body, a vector m_B such that the moments τ m_B
// have the generalised forces τ on q and 0 on every other coordinate. With `on`, q must be one of
// that body's Euler angles or the angle of a joint of that body; without, any joint's angle or any
// body's Euler angle. Empty when q is none of these.
struct AngleTorque {
  std::size_t body;
  VectorExpr per_unit_torque;
};
std::vector<AngleTorque> unit_torque_about(const System& system, std::size_t q,
                                           std::optional<std::size_t> on = std::nullopt);

}  // namespace unidyn
