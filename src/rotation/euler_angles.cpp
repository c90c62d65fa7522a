// Euler angles of all twelve sets (§6.8).
#include "unidyn/rotation/euler_angles.hpp"

#include <cmath>
#include <numbers>

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

// atan2 returns −π for a second argument < 0 and a first argument −0 or a tiny negative number;
// the documented range of γ¹ and γ³ is (−π, π].
double principal_angle(double angle) {
  return angle == -std::numbers::pi ? std::numbers::pi : angle;
}

// 0-based index of the axis that is neither a nor b.
int remaining_axis(int a, int b) {
  return 3 - a - b;
}

// The angle of an elementary rotation matrix about axis k (0-based): with (a, b) the cyclic
// successors of k, M_ba = sin γ and M_aa = M_bb = cos γ.
double elementary_angle(const Tensor& M, int k) {
  const int a = (k + 1) % 3;
  const int b = (k + 2) % 3;
  return principal_angle(std::atan2(M(b, a) - M(a, b), M(a, a) + M(b, b)));
}

}  // namespace

std::string EulerSet::name() const {
  return std::to_string(first) + "-" + std::to_string(second) + "-" + std::to_string(third);
}

std::optional<EulerSet> EulerSet::parse(std::string_view text) {
  if (text.size() != 5 || text[1] != '-' || text[3] != '-') return std::nullopt;
  const auto axis = [](char c) { return (c >= '1' && c <= '3') ? c - '0' : 0; };
  const EulerSet set{axis(text[0]), axis(text[2]), axis(text[4])};
  if (set.first == 0 || set.second == 0 || set.third == 0) return std::nullopt;
  if (set.first == set.second || set.second == set.third) return std::nullopt;
  return set;
}

const std::array<EulerSet, 12>& all_euler_sets() {
  static const std::array<EulerSet, 12> sets = {{{1, 2, 3},
                                                 {3, 2, 3},
                                                 {1, 2, 1},
                                                 {1, 3, 1},
                                                 {1, 3, 2},
                                                 {2, 3, 1},
                                                 {2, 3, 2},
                                                 {2, 1, 2},
                                                 {2, 1, 3},
                                                 {3, 1, 3},
                                                 {3, 2, 1},
                                                 {3, 1, 2}}};
  return sets;
}

Tensor rotation_tensor(const EulerSet& set, const Vec3& angles) {
  // (6.20) Q = L(γ¹, E_I) L(γ², E_J) L(γ³, E_K)
  return elementary_rotation(set.first, angles[0]) * elementary_rotation(set.second, angles[1]) *
         elementary_rotation(set.third, angles[2]);
}

Tensor euler_basis(const EulerSet& set, const Vec3& angles) {
  const Tensor Q1 = elementary_rotation(set.first, angles[0]);
  const Tensor Q12 = Q1 * elementary_rotation(set.second, angles[1]);
  Tensor g;
  g.col(0) = basis_vector(set.first);        // g1 = E_I, fixed
  g.col(1) = Q1 * basis_vector(set.second);  // g2, the once-rotated J axis
  g.col(2) = Q12 * basis_vector(set.third);  // g3 = t_K, the twice-rotated K axis
  return g;
}

double euler_basis_volume(const EulerSet& set, const Vec3& angles) {
  const Tensor g = euler_basis(set, angles);
  return triple_product(g.col(0), g.col(1), g.col(2));
}

Tensor dual_euler_basis(const EulerSet& set, const Vec3& angles) {
  const Tensor g = euler_basis(set, angles);
  const double volume = triple_product(g.col(0), g.col(1), g.col(2));
  if (std::abs(volume) <= kGimbalLockTolerance) {
    throw SingularConfiguration("Euler angles " + set.name() +
                                " are at gimbal lock: the Euler basis is linearly dependent");
  }
  // g^i = (g_j × g_k) / [g1, g2, g3], (i, j, k) cyclic: the inverse transpose of [g].
  Tensor dual;
  for (int i = 0; i < 3; ++i) {
    dual.col(i) = g.col((i + 1) % 3).cross(g.col((i + 2) % 3)) / volume;
  }
  return dual;
}

Vec3 angular_velocity(const EulerSet& set, const Vec3& angles, const Vec3& angle_rates) {
  // (6.21) ω = γ̇¹ g1 + γ̇² g2 + γ̇³ g3
  return euler_basis(set, angles) * angle_rates;
}

Vec3 euler_angle_rates(const EulerSet& set, const Vec3& angles, const Vec3& omega) {
  // (6.22) γ̇^i = ω · g^i
  return dual_euler_basis(set, angles).transpose() * omega;
}

EulerAngles euler_angles(const EulerSet& set, const Tensor& Q) {
  const int i = set.first - 1;
  const int j = set.second - 1;
  double first = 0.0;
  double second = 0.0;
  bool singular = false;
  if (set.symmetric()) {
    // Q = R_I(ψ) R_J(θ) R_I(φ): Q_II = cos θ, (Q_JI, Q_KI) = sin θ (sin ψ, −s cos ψ), s = ε_IJK.
    const int k = remaining_axis(i, j);
    const double s = alternator(set.first, set.second, k + 1);
    const double sin_second = std::hypot(Q(j, i), Q(k, i));
    second = std::atan2(sin_second, Q(i, i));
    singular = sin_second <= kGimbalLockTolerance;
    if (!singular) first = principal_angle(std::atan2(Q(j, i), -s * Q(k, i)));
  } else {
    // Q = R_I(ψ) R_J(θ) R_K(φ): Q_IK = s sin θ, (Q_JK, Q_KK) = cos θ (−s sin ψ, cos ψ), s = ε_IJK.
    const int k = set.third - 1;
    const double s = alternator(set.first, set.second, set.third);
    const double cos_second = std::hypot(Q(i, i), Q(i, j));
    second = std::atan2(s * Q(i, k), cos_second);
    singular = cos_second <= kGimbalLockTolerance;
    if (!singular) first = principal_angle(std::atan2(-s * Q(j, k), Q(k, k)));
  }
  // The third angle from what remains, R_K(φ) = R_J(θ)ᵀ R_I(ψ)ᵀ Q: this absorbs the error of ψ near
  // gimbal lock, so the angles reproduce Q to round-off even there.
  const Tensor remainder =
      (elementary_rotation(set.first, first) * elementary_rotation(set.second, second))
          .transpose() *
      Q;
  const double third = elementary_angle(remainder, set.third - 1);
  const Vec3 angles(first, second, third);
  return {angles, euler_basis_volume(set, angles), singular};
}

}  // namespace unidyn
