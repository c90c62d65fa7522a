// Every parametrisation of a rotation behind one interface, for conversions (the `rotation convert`
// command): matrix, axis-angle, quaternion, rodrigues, euler:I-J-K.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {

struct Parametrisation {
  enum class Kind { matrix, axis_angle, quaternion, rodrigues, euler };
  Kind kind;
  EulerSet euler_set{3, 1, 3};  // used when kind == euler

  // "matrix", "axis-angle", "quaternion", "rodrigues", "euler:3-1-3".
  std::string name() const;
  // How many numbers the parametrisation has: 9, 4, 4, 3, 3.
  std::size_t size() const;
  // Parses a name; throws std::invalid_argument naming the accepted kinds.
  static Parametrisation parse(std::string_view text);
};

// Input that is this far from a rotation is refused; closer input (numbers typed to six or more
// digits) is projected onto the nearest rotation, unit axis or unit quaternion.
inline constexpr double kRotationInputTolerance = 1e-5;

// The rotation tensor of `values` in the given parametrisation (matrix row by row,
// Q_ij = E_i · Q E_j; axis x y z then angle; e0 e1 e2 e3; λ1 λ2 λ3; γ¹ γ² γ³).
// Throws std::invalid_argument for a wrong count and NotARotation for values that are no rotation.
Tensor rotation_from(const Parametrisation& p, std::span<const double> values);

// The values of Q in the given parametrisation. Throws SingularConfiguration where it does not
// exist (the Rodrigues vector at angle π). Euler angles at gimbal lock follow euler_angles().
std::vector<double> rotation_to(const Parametrisation& p, const Tensor& Q);

}  // namespace unidyn
