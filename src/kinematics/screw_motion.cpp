// Chasles' screw of a rigid displacement.
#include "unidyn/kinematics/screw_motion.hpp"

#include <cmath>

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {

ScrewMotion screw_motion(const Tensor& R, const Vec3& z) {
  // s and φ of R; below this angle the axis is lost in round-off
  const AxisAngle rotation = axis_angle(R);
  if (!(rotation.angle > 1e-12)) {
    throw SingularConfiguration("a pure translation has no screw axis (Chasles, §7.2)");
  }
  const Vec3& s = rotation.axis;
  // (7.7) ρ = ½ (z⊥ + cot(φ/2) s × z), σ = s · z
  const double slide = s.dot(z);
  const Vec3 across = z - slide * s;
  const Vec3 point = 0.5 * (across + s.cross(z) / std::tan(rotation.angle / 2));
  return {s, rotation.angle, point, slide};
}

ScrewMotion screw_motion(const Tensor& Q0, const Vec3& d0, const Tensor& Q, const Vec3& d) {
  // (7.5) x(t) = Q Q0ᵀ x(t0) + z with z = d − Q Q0ᵀ d0
  const Tensor R = Q * Q0.transpose();
  return screw_motion(R, d - R * d0);
}

}  // namespace unidyn
