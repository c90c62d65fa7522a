// An MJCF element's orientation (quat, euler, axisangle) as the model's constant `rotation:`.
#include <cmath>
#include <numbers>

#include "mjcf_parts.hpp"
#include "unidyn/formats/exact_angles.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

double radians(const MjcfContext& context, const Number& angle) {
  return context.degrees ? angle.value * std::numbers::pi / 180 : angle.value;
}

// quat="w x y z": MuJoCo's (and the model's) order, divided by its norm by both.
Orientation from_quat(const MjcfContext& context, const XMLElement& element) {
  const auto q = context.source.required_numbers(element, "quat", 4);
  Eigen::Quaterniond value(q[0].value, q[1].value, q[2].value, q[3].value);
  if (value.norm() == 0) context.source.refuse(element, "quat", "a zero quaternion");
  if (q[1].value == 0 && q[2].value == 0 && q[3].value == 0 && q[0].value > 0) return {};
  return {"{quaternion: " + vector_text(q) + "}", value.normalized()};
}

// axisangle="x y z a": a turn by a about the axis.
Orientation from_axis_angle(const MjcfContext& context, const XMLElement& element) {
  const auto v = context.source.required_numbers(element, "axisangle", 4);
  const Eigen::Vector3d axis(v[0].value, v[1].value, v[2].value);
  if (axis.norm() == 0) context.source.refuse(element, "axisangle", "a zero axis");
  if (v[3].value == 0) return {};
  return {"{axis: " + vector_text({v[0], v[1], v[2]}) +
              ", angle: " + angle_text(context, element, "axisangle", v[3]) + "}",
          Eigen::Quaterniond(Eigen::AngleAxisd(radians(context, v[3]), axis.normalized()))};
}

// euler="a b c" of eulerseq xyz (lowercase: about the moving axes): R = Rx(a) Ry(b) Rz(c), the
// factors that are not 0 as a product of axis-angle rotations.
Orientation from_euler(const MjcfContext& context, const XMLElement& element) {
  const auto angles = context.source.required_numbers(element, "euler", 3);
  const char* axes[] = {"[1, 0, 0]", "[0, 1, 0]", "[0, 0, 1]"};
  std::vector<std::string> factors;
  Orientation out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (angles[i].value == 0) continue;
    factors.push_back(std::string("{axis: ") + axes[i] +
                      ", angle: " + angle_text(context, element, "euler", angles[i]) + "}");
    out.value = out.value * Eigen::Quaterniond(Eigen::AngleAxisd(radians(context, angles[i]),
                                                                 Eigen::Vector3d::Unit(int(i))));
  }
  if (factors.size() == 1) out.text = factors[0];
  if (factors.size() > 1) out.text = "[" + joined(factors) + "]";
  return out;
}

}  // namespace

std::string angle_text(const MjcfContext& context, const XMLElement& element, const char* attribute,
                       const Number& angle) {
  if (angle.value == 0) return "0";
  if (context.degrees) return angle.text + "*deg";
  const auto exact = exact_quarter_pi_multiple(angle.value);
  if (!exact || *exact == angle.text) return angle.text;
  context.notes.push_back(context.source.position(element, attribute).str() + ": " + attribute +
                          " angle " + angle.text + " read as " + *exact + kExactAngleNote);
  return *exact;
}

Orientation orientation(const MjcfContext& context, const XMLElement& element) {
  for (const char* refused : {"xyaxes", "zaxis"}) {
    if (element.Attribute(refused)) {
      context.source.refuse(element, refused,
                            std::string(refused) +
                                "= is not supported yet: give the orientation as quat, euler or "
                                "axisangle");
    }
  }
  int given = 0;
  for (const char* attribute : {"quat", "euler", "axisangle"})
    given += element.Attribute(attribute) != nullptr;
  if (given > 1) {
    context.source.refuse(element, "an orientation is one of quat, euler and axisangle");
  }
  if (element.Attribute("quat")) return from_quat(context, element);
  if (element.Attribute("axisangle")) return from_axis_angle(context, element);
  if (element.Attribute("euler")) return from_euler(context, element);
  return {};
}

}  // namespace unidyn::formats
