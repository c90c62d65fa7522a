// A link's <inertial> as a body's mass, inertia tensor and centre of mass.
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>

#include "unidyn/symbolic/printable_text.hpp"
#include "urdf_parts.hpp"
#include "urdf_visual.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// URDF's rpy: R = Rz(y) Ry(p) Rx(r), about the fixed axes x, y, z in turn.
Eigen::Matrix3d rpy_rotation(const std::vector<Number>& rpy) {
  return (Eigen::AngleAxisd(rpy[2].value, Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy[1].value, Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy[0].value, Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

// The tensor of <inertia ixx ixy ixz iyy iyz izz>, as typed.
std::vector<std::vector<Number>> typed_urdf_tensor(const XmlSource& source,
                                                   const XMLElement& inertia) {
  const auto at = [&](const char* name) {
    if (!inertia.Attribute(name)) source.refuse(inertia, std::string("<inertia> needs ") + name);
    return (source.required_numbers(inertia, name, 1))[0];
  };
  const Number xx = at("ixx"), xy = at("ixy"), xz = at("ixz"), yy = at("iyy"), yz = at("iyz"),
               zz = at("izz");
  return {{xx, xy, xz}, {xy, yy, yz}, {xz, yz, zz}};
}

// inertia: the tensor as typed, or turned onto the link frame (R J Rᵀ) when <inertial>'s origin
// has a rotation, with a note and a comment.
void write_inertia(const LinkContext& context, const XMLElement& inertial,
                   std::vector<std::string>& lines) {
  const XmlSource& source = context.source;
  const XMLElement* inertia = inertial.FirstChildElement("inertia");
  if (!inertia) source.refuse(inertial, "<inertial> needs <inertia ixx=... izz=...>");
  const auto components = typed_urdf_tensor(source, *inertia);
  Eigen::Matrix3d J;
  std::vector<std::vector<std::string>> rows(3, std::vector<std::string>(3));
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      J(i, k) = components[i][k].value;
      rows[i][k] = components[i][k].text;
    }
  }
  expect_realisable(source, *inertia, J);
  const XMLElement* origin = inertial.FirstChildElement("origin");
  const auto rpy = origin ? source.numbers(*origin, "rpy", 3) : std::nullopt;
  if (rpy && ((*rpy)[0].value != 0 || (*rpy)[1].value != 0 || (*rpy)[2].value != 0)) {
    const Eigen::Matrix3d R = rpy_rotation(*rpy);
    const Eigen::Matrix3d RJRt = R * J * R.transpose();
    const Eigen::Matrix3d turned = 0.5 * (RJRt + RJRt.transpose());  // symmetric to the last bit
    for (int i = 0; i < 3; ++i) {
      for (int k = 0; k < 3; ++k) rows[i][k] = exact_text(turned(i, k));
    }
    const std::string why = "the <inertia> on the <inertial> frame (rpy " + vector_text(*rpy) +
                            ") turned onto the link frame: R J R^T";
    context.notes.push_back(source.position(*origin, "rpy").str() + ": " + why);
    lines.push_back("    # " + why);
  }
  lines.push_back("    inertia: " + tensor_text(rows));
}

// A link of mass 0 (or without <inertial>) is a frame; it has no inertia.
void expect_frame(const XmlSource& source, const XMLElement& inertial) {
  const XMLElement* inertia = inertial.FirstChildElement("inertia");
  if (!inertia) return;
  for (const auto& row : typed_urdf_tensor(source, *inertia)) {
    for (const Number& x : row) {
      if (x.value != 0) {
        source.refuse(*inertia,
                      "a link of mass 0 is a frame and cannot have inertia (give it a mass)");
      }
    }
  }
}

}  // namespace

std::vector<std::string> link_body_lines(const LinkContext& context, const XMLElement& link,
                                         const std::string& name) {
  const XmlSource& source = context.source;
  ignore_others(source, link, {"inertial", "visual"}, context.ignored);
  const XMLElement* inertial = link.FirstChildElement("inertial");
  std::optional<Number> mass;
  if (inertial) {
    ignore_others(source, *inertial, {"origin", "mass", "inertia"}, context.ignored);
    const XMLElement* m = inertial->FirstChildElement("mass");
    if (!m) source.refuse(*inertial, "<inertial> needs <mass value=...>");
    if (!m->Attribute("value")) source.refuse(*m, "<mass> needs value=\"...\"");
    mass = (source.required_numbers(*m, "value", 1))[0];
    if (mass->value < 0) source.refuse(*m, "value", "a mass must be positive or 0 (a frame)");
  }
  if (!mass || mass->value == 0) {
    if (inertial) expect_frame(source, *inertial);
    std::vector<std::string> lines = {"    mass: 0  # a frame: the link has no mass"};
    frame_visuals(context, link);
    return lines;
  }
  std::vector<std::string> lines = {"    mass: " + mass->text};
  write_inertia(context, *inertial, lines);
  const XMLElement* origin = inertial->FirstChildElement("origin");
  const auto center = origin ? source.numbers(*origin, "xyz", 3) : std::nullopt;
  if (center) lines.push_back("    center: " + name + ".frame_point(" + vector_text(*center) + ")");
  const std::vector<Number> zero = {{"0", 0}, {"0", 0}, {"0", 0}};
  for (auto& line : visual_lines(context, link, center ? *center : zero)) {
    lines.push_back(std::move(line));
  }
  return lines;
}

}  // namespace unidyn::formats
