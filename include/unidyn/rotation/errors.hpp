// Errors raised by the rotation layer.
#pragma once

#include <stdexcept>
#include <string>

namespace unidyn {

// A parametrisation that does not exist at this rotation or rate: an Euler-angle set at gimbal lock
// (its Euler basis is linearly dependent, §6.8), the Rodrigues vector at angle π (§6.9), the axis
// rate of the axis–angle pair at angle 0.
class SingularConfiguration : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

// Input that does not describe a rotation: a non-orthogonal matrix, a zero axis, a non-unit
// quaternion.
class NotARotation : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

}  // namespace unidyn
