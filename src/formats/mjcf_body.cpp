// MJCF bodies and their joints as the model's bodies placed by tree joints. MuJoCo moves a body
// by its joints in order, each about (hinge, ball) or along (slide) its axis through its anchor
// `pos` on the body frame; a body's frame is placed on its parent's by its pos and orientation.
#include <cstring>

#include "mjcf_parts.hpp"
#include "unidyn/formats/mjcf.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;
using Vector = std::vector<Number>;

const Vector kZero = {{"0", 0}, {"0", 0}, {"0", 0}};

bool is_zero(const Vector& v) {
  return v[0].value == 0 && v[1].value == 0 && v[2].value == 0;
}

Number negated(const Number& x) {
  if (x.value == 0) return {"0", 0};
  return {x.text[0] == '-' ? x.text.substr(1) : "-" + x.text, -x.value};
}

// a + b as the model's text ("0.1 + 0.2", "0.1 - 0.2"): exact, as the numbers typed.
Vector sum(const Vector& a, const Vector& b) {
  Vector out;
  for (std::size_t i = 0; i < 3; ++i) {
    if (a[i].value == 0 || b[i].value == 0) {
      out.push_back(a[i].value == 0 ? b[i] : a[i]);
    } else {
      const bool minus = b[i].text[0] == '-';
      out.push_back({a[i].text + (minus ? " - " + b[i].text.substr(1) : " + " + b[i].text),
                     a[i].value + b[i].value});
    }
  }
  return out;
}

struct MjcfJoint {
  const XMLElement* element = nullptr;
  std::string type;  // hinge, slide, ball, free
  Vector anchor;     // pos on the body frame
  std::vector<std::string> coordinates;
  std::string name;  // in the file, or jointN
};

// A joint's coordinates: its name (hinge, slide), with _e0.._e3 (ball) or _x, _y, _z, _e0.._e3
// (free); an unnamed joint is named jointN after its MuJoCo id, with a note.
std::vector<std::string> coordinate_names(MjcfContext& context, const XMLElement& joint,
                                          const std::string& type, std::string& name) {
  const int id = context.joints++;
  const char* given = joint.Attribute("name");
  const SourcePosition where = context.source.position(joint, "name");
  name = given ? given : "joint" + std::to_string(id);
  if (!given) {
    context.notes.push_back(where.str() + ": an unnamed joint is named " + name +
                            " (its MuJoCo id)");
  }
  std::vector<const char*> suffixes;
  if (type == "ball") suffixes = {"_e0", "_e1", "_e2", "_e3"};
  if (type == "free") suffixes = {"_x", "_y", "_z", "_e0", "_e1", "_e2", "_e3"};
  if (suffixes.empty()) return {context.names.claim(name, "joint", where, context.notes)};
  std::vector<std::string> names;
  for (const char* suffix : suffixes) {
    names.push_back(context.names.claim(name + suffix, "joint coordinate", where, context.notes));
  }
  return names;
}

// Attributes that change the dynamics unidyn does not model yet: refused unless 0.
void refuse_nonzero(const MjcfContext& context, const XMLElement& joint) {
  for (const char* attribute : {"stiffness", "armature", "frictionloss", "ref", "springdamper"}) {
    const auto value = context.source.numbers(joint, attribute,
                                              std::strcmp(attribute, "springdamper") == 0 ? 2 : 1);
    if (value && ((*value)[0].value != 0 || (*value).back().value != 0)) {
      context.source.refuse(joint, attribute,
                            std::string("joint ") + attribute + " is not supported yet");
    }
  }
}

// damping on a hinge: a torsion damper; on a slide a slide damper; on another joint refused.
void read_damping(MjcfContext& context, const MjcfJoint& joint) {
  const auto damping = context.source.numbers(*joint.element, "damping", 1);
  if (!damping || (*damping)[0].value == 0) return;
  if ((*damping)[0].value < 0) {
    context.source.refuse(*joint.element, "damping", "damping must not be negative");
  }
  if (joint.type != "hinge" && joint.type != "slide") {
    context.source.refuse(*joint.element, "damping",
                          "joint damping on a " + joint.type + " joint is not supported yet");
  }
  context.written.dampers.push_back(
      damper_line(joint.type == "slide", joint.coordinates[0], (*damping)[0].text));
}

// A limited joint's range (limited="true", or a range under <compiler autolimits="true">): with
// --limits two unilateral contacts, else noted; a ball's (a cone) refused with --limits.
void read_range(MjcfContext& context, const MjcfJoint& joint) {
  const XmlSource& source = context.source;
  const auto range = source.numbers(*joint.element, "range", 2);
  if (!range) return;
  const char* limited = joint.element->Attribute("limited");
  const bool applies = limited ? std::strcmp(limited, "true") == 0 : context.autolimits;
  if (!applies || !context.limits) {
    context.ignored.add(source, *joint.element,
                        "range: not applied (--limits makes a limited joint's range two "
                        "unilateral contacts)");
    return;
  }
  if (joint.type != "hinge" && joint.type != "slide") {
    source.refuse(*joint.element, "range",
                  "--limits: a " + joint.type + " joint's range is not supported yet");
  }
  const auto& [lower, upper] = std::pair{(*range)[0], (*range)[1]};
  if (!(lower.value < upper.value)) {
    source.refuse(
        *joint.element, "range",
        "--limits: the range's lower " + lower.text + " is not below its upper " + upper.text);
  }
  const bool angles = joint.type == "hinge";
  write_limits(joint.coordinates[0],
               angles ? angle_text(context, *joint.element, "range", lower) : lower.text,
               angles ? angle_text(context, *joint.element, "range", upper) : upper.text,
               source.position(*joint.element, "range"), context.names, context.notes,
               context.written);
}

// The body's <joint> and <freejoint> elements in order: type (hinge by default), anchor, names.
std::vector<MjcfJoint> read_joints(MjcfContext& context, const XMLElement& body, bool top_level) {
  std::vector<MjcfJoint> joints;
  for (const auto* e = body.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const bool free = std::strcmp(e->Name(), "freejoint") == 0;
    if (!free && std::strcmp(e->Name(), "joint") != 0) continue;
    const char* type = free ? "free" : e->Attribute("type");
    MjcfJoint joint{
        e, type ? type : "hinge", context.source.numbers_or(*e, "pos", {"0", "0", "0"}), {}, ""};
    if (joint.type != "hinge" && joint.type != "slide" && joint.type != "ball" &&
        joint.type != "free") {
      context.source.refuse(*e, "type",
                            "unknown joint type '" + printable(joint.type) +
                                "' (expected hinge, slide, ball or free)");
    }
    if (joint.type == "free" && !top_level) {
      context.source.refuse(*e, "a free joint moves a body of <worldbody> only (as in MuJoCo)");
    }
    refuse_nonzero(context, *e);
    joint.coordinates = coordinate_names(context, *e, joint.type, joint.name);
    for (const auto& q : joint.coordinates) context.written.coordinates.push_back(q);
    if (e->Attribute("name")) context.named_joints[joint.name] = {joint.type, joint.coordinates};
    read_damping(context, joint);
    read_range(context, joint);
    joints.push_back(std::move(joint));
  }
  if (joints.size() > 1) {
    for (const auto& joint : joints) {
      if (joint.type == "free") {
        context.source.refuse(*joint.element, "a free joint is a body's only joint");
      }
    }
  }
  return joints;
}

// `joint: {parent, origin, rotation, motion}`, each key only when it is not its default.
std::string joint_line(const std::string& parent, const Vector& origin, const std::string& rotation,
                       const std::string& motion) {
  std::vector<std::string> keys;
  if (!parent.empty()) keys.push_back("parent: " + parent);
  if (!is_zero(origin)) keys.push_back("origin: " + vector_text(origin));
  if (!rotation.empty()) keys.push_back("rotation: " + rotation);
  if (!motion.empty()) keys.push_back(motion);
  return "    joint: {" + joined(keys) + "}";
}

// The motion key of a joint: revolute or prismatic with its axis (default 0 0 1), ball, floating.
std::string motion_text(const MjcfContext& context, const MjcfJoint& joint) {
  const std::string list = joined(joint.coordinates);
  if (joint.type == "ball") return "ball: [" + list + "]";
  if (joint.type == "free") return "floating: [" + list + "]";
  const Vector axis = context.source.numbers_or(*joint.element, "axis", {"0", "0", "1"});
  if (is_zero(axis))
    context.source.refuse(*joint.element, "axis", "a joint's axis must not be zero");
  return std::string(joint.type == "hinge" ? "revolute: " : "prismatic: ") + list +
         ", axis: " + vector_text(axis);
}

// A massless frame's block before the body: `name:`, its joint line, mass 0.
void write_frame(MjcfContext& context, const std::string& name, const std::string& joint,
                 const std::string& comment) {
  auto& bodies = context.written.bodies;
  if (!bodies.empty()) bodies.push_back("");
  bodies.push_back("  " + name + ":  # " + comment);
  bodies.push_back(joint);
  bodies.push_back("    mass: 0  # a frame");
}

// The initial values of a joint's coordinates at MuJoCo's qpos0: a ball's Euler parameters
// (1, 0, 0, 0); a free joint's the body's pos and orientation.
void write_initial(MjcfContext& context, const MjcfJoint& joint, const Vector& pos,
                   const Orientation& orientation) {
  auto& initial = context.written.initial;
  if (joint.type == "ball") initial.push_back(joint.coordinates[0] + ": 1");
  if (joint.type != "free") return;
  for (std::size_t i = 0; i < 3; ++i) {
    if (pos[i].value != 0) initial.push_back(joint.coordinates[i] + ": " + pos[i].text);
  }
  const Eigen::Quaterniond& q = orientation.value;
  const double e[] = {q.w(), q.x(), q.y(), q.z()};
  for (std::size_t i = 0; i < 4; ++i) {
    if (e[i] != 0) initial.push_back(joint.coordinates[3 + i] + ": " + exact_text(e[i]));
  }
}

// The body's `joint:` line, after the frames its joints need: each joint places a frame at its
// anchor (the first on the parent by the body's pos and orientation), the next joint's frame is
// placed on it, and the body sits at −anchor on the last. A single joint at the body's origin
// places the body itself.
std::string place_body(MjcfContext& context, const std::string& name, const std::string& parent,
                       const Vector& pos, const Orientation& orientation,
                       const std::vector<MjcfJoint>& joints) {
  std::string at = parent;
  Vector offset = pos;
  std::string rotation = orientation.text;
  if (joints.size() == 1 && joints[0].type == "free") {
    write_initial(context, joints[0], pos, orientation);
    return joint_line("", kZero, "", motion_text(context, joints[0]));
  }
  for (std::size_t k = 0; k < joints.size(); ++k) {
    const MjcfJoint& joint = joints[k];
    write_initial(context, joint, pos, orientation);
    const std::string motion = motion_text(context, joint);
    if (k + 1 == joints.size() && is_zero(joint.anchor)) {
      return joint_line(at, offset, rotation, motion);
    }
    // a turned body with an anchor off its origin: the body's frame first, fixed
    if (!rotation.empty() && !is_zero(joint.anchor)) {
      const std::string place = context.names.claim(
          name + "_place", "frame", context.source.position(*joint.element), context.notes);
      write_frame(context, place, joint_line(at, offset, rotation, ""),
                  "body " + name + "'s frame before its joints");
      at = place;
      offset = kZero;
      rotation.clear();
    }
    const std::string frame = context.names.claim(
        joint.name + "_frame", "frame", context.source.position(*joint.element), context.notes);
    write_frame(context, frame, joint_line(at, sum(offset, joint.anchor), rotation, motion),
                "joint " + joint.name + " at its anchor");
    at = frame;
    offset = {negated(joint.anchor[0]), negated(joint.anchor[1]), negated(joint.anchor[2])};
    rotation.clear();
  }
  return joint_line(at, offset, rotation, "");
}

// A <body>: its frames and block, then its child bodies.
void write_body(MjcfContext& context, const XMLElement& body, const std::string& parent) {
  const XmlSource& source = context.source;
  const int id = ++context.bodies;
  if (static_cast<std::size_t>(id) > kMaxMjcfBodies) {
    source.refuse(body, "more than " + std::to_string(kMaxMjcfBodies) + " bodies");
  }
  if (body.BoolAttribute("mocap", false))
    source.refuse(body, "mocap", "mocap bodies are not supported");
  const char* given = body.Attribute("name");
  std::string change;
  const std::string name =
      context.names.claim(given ? given : "body" + std::to_string(id), "body",
                          source.position(body, "name"), context.notes, &change);
  if (!given) change = "an unnamed body is named " + name + " (its MuJoCo id)";
  if (!given) context.notes.push_back(source.position(body).str() + ": " + change);
  ignore_others(source, body, {"inertial", "joint", "freejoint", "body", "geom"}, context.ignored);
  const Vector pos = source.numbers_or(body, "pos", {"0", "0", "0"});
  const Orientation turned = orientation(context, body);
  // its frame at qpos0: every joint's motion is 0 there (a free body's pos and orientation place
  // it)
  const auto parent_frame = context.frames.find(parent);
  Eigen::Isometry3d frame =
      parent_frame != context.frames.end() ? parent_frame->second : Eigen::Isometry3d::Identity();
  frame = frame * Eigen::Translation3d(pos[0].value, pos[1].value, pos[2].value) * turned.value;
  context.frames[name] = frame;
  if (given) context.named_bodies[given] = name;
  const auto joints = read_joints(context, body, parent.empty());
  const std::string line = place_body(context, name, parent, pos, turned, joints);
  auto& bodies = context.written.bodies;
  if (!bodies.empty()) bodies.push_back("");
  bodies.push_back("  " + name + ":" + (change.empty() ? "" : "  # " + change));
  bodies.push_back(line);
  for (auto& l : inertial_lines(context, body, name)) bodies.push_back(std::move(l));
  write_child_bodies(context, body, name);
}

}  // namespace

void write_child_bodies(MjcfContext& context, const XMLElement& parent_element,
                        const std::string& parent) {
  for (const auto* body = parent_element.FirstChildElement("body"); body;
       body = body->NextSiblingElement("body")) {
    write_body(context, *body, parent);
  }
}

}  // namespace unidyn::formats
