// A URDF joint: the frame it fixes on its parent link, its motion, its coordinates, its damper.
#include "urdf_joint.hpp"

#include <cmath>

#include "unidyn/formats/exact_angles.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// `axis: [a1, a2, a3]` of <axis xyz> (default 1 0 0, as URDF's); a zero axis refused. A planar
// joint's axis must be ±x, ±y or ±z of the joint frame.
std::string axis_text(const XmlSource& source, const UrdfJoint& joint) {
  const XMLElement* axis = joint.element->FirstChildElement("axis");
  const auto xyz = axis ? source.numbers_or(*axis, "xyz", {"1", "0", "0"})
                        : std::vector<Number>{{"1", 1}, {"0", 0}, {"0", 0}};
  int nonzero = 0;
  for (const Number& x : xyz) nonzero += x.value != 0;
  if (nonzero == 0) source.refuse(*axis, "xyz", "a joint's axis must not be zero");
  if (joint.type == "planar" && nonzero != 1) {
    source.refuse(*axis, "xyz",
                  "a planar joint's axis must be along x, y or z of the joint frame (unidyn's "
                  "planar joint slides along the other two)");
  }
  return ", axis: " + vector_text(xyz);
}

// The coordinates of a joint of each kind: one named after the joint, or the joint's name with
// suffixes (floating: x y z e0..e3; planar: x y theta).
std::vector<std::string> coordinate_names(const LinkContext& context, const UrdfJoint& joint,
                                          Names& names) {
  std::vector<const char*> suffixes;
  if (joint.type == "floating") suffixes = {"_x", "_y", "_z", "_e0", "_e1", "_e2", "_e3"};
  if (joint.type == "planar") suffixes = {"_x", "_y", "_theta"};
  if (joint.type == "fixed") return {};
  const SourcePosition where = context.source.position(*joint.element, "name");
  if (suffixes.empty()) return {names.claim(joint.urdf_name, "joint", where, context.notes)};
  std::vector<std::string> coordinates;
  for (const char* suffix : suffixes) {
    coordinates.push_back(
        names.claim(joint.urdf_name + suffix, "joint coordinate", where, context.notes));
  }
  return coordinates;
}

// The motion key: `revolute: q`, `prismatic: q`, `floating: [...]`, `planar: [...]`, or none.
std::string motion_text(const JointText& text, const std::string& type) {
  if (type == "fixed") return "";
  std::string list;
  for (const auto& q : text.coordinates) list += (list.empty() ? "" : ", ") + q;
  if (type == "revolute" || type == "continuous") return ", revolute: " + list;
  if (type == "prismatic") return ", prismatic: " + list;
  return ", " + type + ": [" + list + "]";
}

// <dynamics damping friction>: damping on a revolute or continuous joint is a torsion damper, on a
// prismatic joint a slide damper; anything else that changes the dynamics is refused.
std::string damper_text(const XmlSource& source, const UrdfJoint& joint,
                        const std::vector<std::string>& coordinates) {
  const XMLElement* dynamics = joint.element->FirstChildElement("dynamics");
  if (!dynamics) return "";
  const auto friction = source.numbers(*dynamics, "friction", 1);
  if (friction && (*friction)[0].value != 0) {
    source.refuse(*dynamics, "friction", "joint friction is not supported yet");
  }
  const auto damping = source.numbers(*dynamics, "damping", 1);
  if (!damping || (*damping)[0].value == 0) return "";
  const bool slides = joint.type == "prismatic";
  if (joint.type != "revolute" && joint.type != "continuous" && !slides) {
    source.refuse(*dynamics, "damping",
                  "joint damping on a " + joint.type + " joint is not supported yet");
  }
  if ((*damping)[0].value < 0) source.refuse(*dynamics, "damping", "damping must not be negative");
  return damper_line(slides, coordinates[0], (*damping)[0].text);
}

// The rpy angles, each typed as a rounded multiple of π/4 written as that multiple
// (exact_angles.hpp: the equations then hold its exact sine and cosine), with a note saying so.
std::string rpy_text(const LinkContext& context, const XMLElement& origin,
                     std::vector<Number> rpy) {
  std::vector<std::string> changed;
  for (Number& angle : rpy) {
    const auto exact = exact_quarter_pi_multiple(angle.value);
    if (!exact || *exact == angle.text) continue;
    changed.push_back(angle.text + " as " + *exact);
    angle.text = *exact;
  }
  if (!changed.empty()) {
    std::string list;
    for (const auto& c : changed) list += (list.empty() ? "" : ", ") + c;
    context.notes.push_back(context.source.position(origin, "rpy").str() + ": rpy read " + list +
                            kExactAngleNote);
  }
  return vector_text(rpy);
}

}  // namespace

void write_joint_limits(const LinkContext& context, const UrdfJoint& joint,
                        const std::string& coordinate, Names& names, Written& written) {
  const XmlSource& source = context.source;
  const XMLElement* limit = joint.element->FirstChildElement("limit");
  if (!limit) return;
  if (joint.type != "revolute" && joint.type != "prismatic") {
    context.notes.push_back(source.position(*limit).str() + ": <limit> not applied: a " +
                            joint.type + " joint has no position limits");
    return;
  }
  const Number lower = source.numbers_or(*limit, "lower", {"0"})[0];
  const Number upper = source.numbers_or(*limit, "upper", {"0"})[0];
  if (!(lower.value < upper.value)) {
    source.refuse(*limit, "--limits: lower " + lower.text + " is not below upper " + upper.text +
                              " (a joint held at one value is a fixed joint)");
  }
  write_limits(coordinate, lower.text, upper.text, source.position(*limit), names, context.notes,
               written);
  context.ignored.add(source, *limit,
                      "lower and upper made two unilateral contacts, Q_lower and Q_upper of the "
                      "joint's coordinate Q (--limits, no rebound); effort and velocity not "
                      "applied");
}

JointText joint_text(const LinkContext& context, const UrdfJoint& joint, const std::string& parent,
                     Names& names) {
  const XmlSource& source = context.source;
  const XMLElement& e = *joint.element;
  if (const auto* mimic = e.FirstChildElement("mimic")) {
    source.refuse(*mimic,
                  "<mimic> is not supported: it changes the dynamics (a constraint between "
                  "joints)");
  }
  ignore_others(source, e, {"parent", "child", "origin", "axis", "dynamics", "limit", "mimic"},
                context.ignored);
  if (const auto* limit = e.FirstChildElement("limit"); limit && !context.limits) {
    context.ignored.add(source, *limit,
                        "not applied (--limits makes lower and upper two unilateral contacts)");
  }
  JointText text;
  text.coordinates = coordinate_names(context, joint, names);
  text.line = "    joint: {parent: " + parent;
  if (const auto* origin = e.FirstChildElement("origin")) {
    if (const auto xyz = source.numbers(*origin, "xyz", 3))
      text.line += ", origin: " + vector_text(*xyz);
    if (const auto rpy = source.numbers(*origin, "rpy", 3))
      text.line += ", rpy: " + rpy_text(context, *origin, *rpy);
  }
  text.line += motion_text(text, joint.type);
  if (joint.type != "fixed" && joint.type != "floating") text.line += axis_text(source, joint);
  text.line += "}";
  // a floating joint starts at the joint frame: Euler parameters (1, 0, 0, 0)
  if (joint.type == "floating") text.initial.push_back(text.coordinates[3] + ": 1");
  text.damper = damper_text(source, joint, text.coordinates);
  return text;
}

}  // namespace unidyn::formats
