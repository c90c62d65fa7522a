// The parts of an MJCF import shared by its files: what a body is written with, and its bodies.
#pragma once

#include <Eigen/Geometry>
#include <map>
#include <string>
#include <vector>

#include "urdf_parts.hpp"
#include "urdf_tree.hpp"

namespace unidyn::formats {

// A named joint's type and coordinates.
struct MjcfJointCoordinates {
  std::string type;
  std::vector<std::string> coordinates;
};

// What the bodies are written with: <compiler>'s angle unit, the names, and what is written.
struct MjcfContext {
  const XmlSource& source;
  std::vector<std::string>& notes;
  Ignored& ignored;
  Names& names;
  Written& written;
  bool degrees = true;            // <compiler angle>: MuJoCo's default is degree
  bool inertia_from_geom = true;  // <compiler inertiafromgeom> "auto" (the default) or "false"
  bool autolimits = false;        // <compiler autolimits>: a joint with a range is limited
  bool limits = false;            // --limits: limited joints' ranges as unilateral contacts
  int bodies = 0;                 // MuJoCo's ids: the world is body 0
  int joints = 0;
  int equalities = 0;
  // for <equality>: the bodies' model names and the joints by their names in the file, and each
  // body's frame on the ground at MuJoCo's reference configuration qpos0 (hinges and slides at 0,
  // balls unturned, a free body where the file puts it) by its model name
  std::map<std::string, std::string> named_bodies{};
  std::map<std::string, MjcfJointCoordinates> named_joints{};
  std::map<std::string, Eigen::Isometry3d> frames{};
};

// The <default> classes applied (mjcf_defaults.cpp): each <joint>, <geom>, ... of <worldbody>
// given its class's attributes that it does not set itself; an unknown class refused.
void apply_default_classes(XmlSource& source);

// An element's orientation (quat, euler or axisangle; none is the identity): the model's
// `rotation:` text ("" for none) and its value.
struct Orientation {
  std::string text;
  Eigen::Quaterniond value = Eigen::Quaterniond::Identity();
};
Orientation orientation(const MjcfContext& context, const tinyxml2::XMLElement& element);

// An angle as the model's text: "A*deg" in degrees (exact: deg is pi/180); in radians a rounded
// multiple of π/4 as that multiple (exact_angles.hpp), with a note, else as typed.
std::string angle_text(const MjcfContext& context, const tinyxml2::XMLElement& element,
                       const char* attribute, const Number& angle);

// The bodies under <worldbody> (or a <body>) whose frame is `parent` ("" for the ground),
// depth-first in file order (MuJoCo's order of bodies and of qpos).
void write_child_bodies(MjcfContext& context, const tinyxml2::XMLElement& parent_element,
                        const std::string& parent);

// The constraints of an <equality> element (mjcf_equality.cpp), after the bodies are read.
void write_equalities(MjcfContext& context, const tinyxml2::XMLElement& equality);

// The body lines after its `joint:` from <inertial>: mass, inertia, centre (mass: 0 without).
std::vector<std::string> inertial_lines(const MjcfContext& context,
                                        const tinyxml2::XMLElement& body, const std::string& name);

}  // namespace unidyn::formats
