// Conversions between every pair of parametrisations of a rotation.
#include "unidyn/rotation/parametrisation.hpp"

#include <cmath>
#include <stdexcept>

#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"
#include "unidyn/rotation/euler_parameters.hpp"
#include "unidyn/rotation/rodrigues_vector.hpp"

namespace unidyn {
namespace {

constexpr std::string_view kKinds =
    "matrix, axis-angle, quaternion, rodrigues, euler:I-J-K (e.g. euler:3-1-3)";

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", x);
  return buffer;
}

// A vector that should be of unit length: refused when its norm is off by more than the input
// tolerance, otherwise scaled to unit length.
Vec3 unit_input(const Vec3& v, std::string_view what) {
  const double norm = v.norm();
  if (!(std::abs(norm - 1.0) <= kRotationInputTolerance)) {
    throw NotARotation(std::string(what) + " must be a unit vector (its norm is " + number(norm) +
                       ")");
  }
  return v / norm;
}

}  // namespace

std::string Parametrisation::name() const {
  switch (kind) {
    case Kind::matrix:
      return "matrix";
    case Kind::axis_angle:
      return "axis-angle";
    case Kind::quaternion:
      return "quaternion";
    case Kind::rodrigues:
      return "rodrigues";
    case Kind::euler:
      return "euler:" + euler_set.name();
  }
  return "";
}

std::size_t Parametrisation::size() const {
  switch (kind) {
    case Kind::matrix:
      return 9;
    case Kind::axis_angle:
    case Kind::quaternion:
      return 4;
    case Kind::rodrigues:
    case Kind::euler:
      return 3;
  }
  return 0;
}

Parametrisation Parametrisation::parse(std::string_view text) {
  if (text == "matrix") return {Kind::matrix};
  if (text == "axis-angle") return {Kind::axis_angle};
  if (text == "quaternion") return {Kind::quaternion};
  if (text == "rodrigues") return {Kind::rodrigues};
  if (text.starts_with("euler:")) {
    const auto set = EulerSet::parse(text.substr(6));
    if (!set) {
      throw std::invalid_argument("'" + std::string(text) +
                                  "' is not an Euler-angle set: expected euler:I-J-K with axes "
                                  "1, 2, 3 and no axis twice in a row, e.g. euler:3-1-3");
    }
    return {Kind::euler, *set};
  }
  throw std::invalid_argument("unknown rotation kind '" + std::string(text) + "': expected " +
                              std::string(kKinds));
}

Tensor rotation_from(const Parametrisation& p, std::span<const double> values) {
  if (values.size() != p.size()) {
    throw std::invalid_argument(p.name() + " takes " + std::to_string(p.size()) + " numbers, got " +
                                std::to_string(values.size()));
  }
  for (double x : values) {
    if (!std::isfinite(x)) throw NotARotation(p.name() + " values must be finite numbers");
  }
  switch (p.kind) {
    case Parametrisation::Kind::matrix: {
      Tensor Q;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) Q(i, j) = values[3 * i + j];
      }
      const double defect = rotation_defect(Q);
      if (!(defect <= kRotationInputTolerance)) {
        throw NotARotation("matrix is not a rotation: max(|QᵀQ − I|, |det Q − 1|) = " +
                           number(defect));
      }
      return nearest_rotation(Q);
    }
    case Parametrisation::Kind::axis_angle: {
      const Vec3 axis = unit_input(Vec3(values[0], values[1], values[2]), "axis");
      return rotation_tensor(AxisAngle{axis, values[3]});
    }
    case Parametrisation::Kind::quaternion: {
      const Eigen::Vector4d q(values[0], values[1], values[2], values[3]);
      const double norm = q.norm();
      if (!(std::abs(norm - 1.0) <= kRotationInputTolerance)) {
        throw NotARotation("quaternion must have unit norm (its norm is " + number(norm) + ")");
      }
      return rotation_tensor(EulerParameters{q[0] / norm, q.tail<3>() / norm});
    }
    case Parametrisation::Kind::rodrigues:
      return rotation_tensor(RodriguesVector{Vec3(values[0], values[1], values[2])});
    case Parametrisation::Kind::euler:
      return rotation_tensor(p.euler_set, Vec3(values[0], values[1], values[2]));
  }
  throw std::logic_error("rotation_from: unhandled kind");
}

std::vector<double> rotation_to(const Parametrisation& p, const Tensor& Q) {
  switch (p.kind) {
    case Parametrisation::Kind::matrix: {
      std::vector<double> values;
      for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) values.push_back(Q(i, j));
      }
      return values;
    }
    case Parametrisation::Kind::axis_angle: {
      const AxisAngle a = axis_angle(Q);
      return {a.axis.x(), a.axis.y(), a.axis.z(), a.angle};
    }
    case Parametrisation::Kind::quaternion: {
      const EulerParameters e = euler_parameters(Q);
      return {e.e0, e.e.x(), e.e.y(), e.e.z()};
    }
    case Parametrisation::Kind::rodrigues: {
      const Vec3 l = rodrigues_vector(Q).lambda;
      return {l.x(), l.y(), l.z()};
    }
    case Parametrisation::Kind::euler: {
      const Vec3 g = euler_angles(p.euler_set, Q).angles;
      return {g.x(), g.y(), g.z()};
    }
  }
  throw std::logic_error("rotation_to: unhandled kind");
}

}  // namespace unidyn
