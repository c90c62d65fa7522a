// The joint a coordinate is the angle of: ω_B − ω_P = q̇ w with w a unit vector.
#include "unidyn/model/angle_joint.hpp"

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// Whether every component of v simplifies to zero.
bool vanishes(const VectorExpr& v) {
  for (int i = 0; i < 3; ++i) {
    if (!simplify(v[i]).is_zero()) return false;
  }
  return true;
}

}  // namespace

std::optional<AngleJoint> joint_of_angle(const System& system, std::size_t q) {
  const auto& coordinates = system.coordinates();
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const VectorExpr w_B = system.angular_velocity(b);
    if (vanishes(diff(w_B, coordinates[q].rate))) continue;
    // the parents to try: the other bodies in order, then the ground
    std::vector<std::optional<std::size_t>> parents;
    for (std::size_t p = 0; p < system.bodies.size(); ++p) {
      if (p != b) parents.emplace_back(p);
    }
    parents.emplace_back(std::nullopt);
    for (const auto& p : parents) {
      // ω_B − ω_P, its q̇ coefficient w, and nothing from any other rate
      const VectorExpr relative = p ? w_B - system.angular_velocity(*p) : w_B;
      const VectorExpr w = simplified(diff(relative, coordinates[q].rate));
      if (!simplify(dot(w, w) - 1).is_zero()) continue;
      bool alone = true;
      for (std::size_t k = 0; k < coordinates.size() && alone; ++k) {
        alone = k == q || vanishes(diff(relative, coordinates[k].rate));
      }
      if (alone && vanishes(relative - coordinates[q].rate * w)) return AngleJoint{b, p, w};
    }
  }
  return std::nullopt;
}

std::vector<AngleTorque> unit_torque_about(const System& system, std::size_t q,
                                           std::optional<std::size_t> on) {
  // (8.27) one of a body's Euler angles: along its dual Euler basis vector g^i
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    const auto& chart = system.bodies[b].chart;
    if (!chart || (on && *on != b)) continue;
    for (std::size_t i = 0; i < 3; ++i) {
      if (chart->coordinates[i] == q) return {{b, system.dual_euler_basis(b)[i]}};
    }
  }
  // a joint's angle: τ w on B, −τ w on P
  const auto joint = joint_of_angle(system, q);
  if (!joint || (on && joint->body != *on && joint->parent != *on)) return {};
  std::vector<AngleTorque> moments{{joint->body, joint->axis}};
  if (joint->parent) moments.push_back({*joint->parent, -joint->axis});
  return moments;
}

}  // namespace unidyn
