// Euler angles: all twelve sets (book §6.8).
//
// The set "I-J-K" with angles (γ¹, γ², γ³) is the rotation about E_I by γ¹, then about the
// once-rotated J axis by γ², then about the twice-rotated K axis by γ³:
//   (6.20) Q = L(γ³, g3) L(γ², g2) L(γ¹, g1) = L(γ¹, E_I) L(γ², E_J) L(γ³, E_K),
// whose component matrix is the product R_I(γ¹) R_J(γ²) R_K(γ³) of elementary rotation matrices,
// e.g. (6.25) Rz(ψ) Ry(θ) Rx(φ) for 3-2-1. Symmetric (proper Euler) sets have I = K; the others are
// Tait–Bryan sets. The second angle is singular at 0, π (symmetric) or ±π/2 (Tait–Bryan), where
// g1 = ±g3 (gimbal lock).
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

struct EulerSet {
  // Axes 1..3 of the three successive rotations.
  int first;
  int second;
  int third;

  // I = K: 3-1-3, 3-2-3, 1-2-1, 1-3-1, 2-1-2, 2-3-2.
  bool symmetric() const { return first == third; }
  // "3-1-3".
  std::string name() const;
  // Parses "I-J-K" with I ≠ J ≠ K; nullopt for anything else (1-1-2, 4-1-2, "313").
  static std::optional<EulerSet> parse(std::string_view text);

  bool operator==(const EulerSet&) const = default;
};

// The twelve sets in the book's order of §6.8 (with 3-2-1 in place of the misprinted second 2-3-1).
const std::array<EulerSet, 12>& all_euler_sets();

// (6.20) Q = R_I(γ¹) R_J(γ²) R_K(γ³).
Tensor rotation_tensor(const EulerSet& set, const Vec3& angles);

// (6.20)–(6.21) Euler basis: g1 = E_I, g2 = L(γ¹, E_I) E_J, g3 = L(γ¹, E_I) L(γ², E_J) E_K,
// as the columns of the returned tensor (components on E).
Tensor euler_basis(const EulerSet& set, const Vec3& angles);

// [g1, g2, g3]: ± cos γ² for Tait–Bryan sets, ± sin γ² for symmetric sets; zero at gimbal lock.
double euler_basis_volume(const EulerSet& set, const Vec3& angles);

// Gimbal lock is declared when |[g1, g2, g3]| falls to this value or below: a few round-offs, so
// that setting γ¹ = 0 there changes the rotation by no more than 2|[g1, g2, g3]| (below 1e-13).
inline constexpr double kGimbalLockTolerance = 2e-14;

// (6.22) Dual Euler basis g^i with g^i · g_j = δ^i_j, as columns (components on E); the component
// matrix is the inverse transpose of the Euler basis's (footnote 14). g^2 = g_2. Throws
// SingularConfiguration at gimbal lock, where g^1 and g^3 do not exist.
Tensor dual_euler_basis(const EulerSet& set, const Vec3& angles);

// (6.21) ω = γ̇¹ g1 + γ̇² g2 + γ̇³ g3.
Vec3 angular_velocity(const EulerSet& set, const Vec3& angles, const Vec3& angle_rates);

// (6.22) γ̇^i = ω · g^i, the kinematic differential equation of the set (e.g. (6.45) for 3-2-3).
// Throws SingularConfiguration at gimbal lock.
Vec3 euler_angle_rates(const EulerSet& set, const Vec3& angles, const Vec3& omega);

// Angles of a rotation tensor. Ranges: γ¹, γ³ ∈ (−π, π]; γ² ∈ [0, π] for symmetric sets and
// [−π/2, π/2] for Tait–Bryan sets. At gimbal lock only γ¹ ± γ³ is defined: γ¹ is then set to 0 and
// `singular` is true. `volume` is [g1, g2, g3] at the angles found.
struct EulerAngles {
  Vec3 angles;
  double volume;
  bool singular;
};
EulerAngles euler_angles(const EulerSet& set, const Tensor& Q);

}  // namespace unidyn
