// A URDF file as a unidyn model: the YAML text of its bodies placed by tree joints.
#include "unidyn/formats/urdf.hpp"

#include "unidyn/symbolic/printable_text.hpp"
#include "urdf_joint.hpp"
#include "urdf_parts.hpp"
#include "urdf_tree.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// The materials by name (the colours a <visual> may name): <robot>'s, then those a <visual>
// defines with a colour, first definition first (as URDF readers resolve them). <robot>'s are
// otherwise ignored.
std::map<std::string, const XMLElement*> named_materials(const XmlSource& source,
                                                         Ignored& ignored) {
  std::map<std::string, const XMLElement*> materials;
  const XMLElement& robot = source.root();
  for (const auto* m = robot.FirstChildElement("material"); m;
       m = m->NextSiblingElement("material")) {
    if (const char* name = m->Attribute("name")) materials.emplace(name, m);
    ignored.add(source, *m, "read only for the colours of visuals that name it");
  }
  for (const auto* link = robot.FirstChildElement("link"); link;
       link = link->NextSiblingElement("link")) {
    for (const auto* v = link->FirstChildElement("visual"); v;
         v = v->NextSiblingElement("visual")) {
      const XMLElement* m = v->FirstChildElement("material");
      const char* name = m ? m->Attribute("name") : nullptr;
      if (name && m->FirstChildElement("color")) materials.emplace(name, m);
    }
  }
  return materials;
}

// A link's body: its unidyn name (a comment when it changed), its joint, its inertia and visual.
void write_body(const LinkContext& context, const UrdfTree& tree, std::size_t link,
                std::vector<std::string>& body_names, Names& names, Written& written) {
  const UrdfLink& l = tree.links[link];
  std::string change;
  body_names[link] = names.claim(l.urdf_name, "link", context.source.position(*l.element, "name"),
                                 context.notes, &change);
  if (!written.bodies.empty()) written.bodies.push_back("");
  written.bodies.push_back("  " + body_names[link] + ":" + (change.empty() ? "" : "  # " + change));
  if (!l.joint) {
    written.bodies.push_back("    joint: {}  # the root link, fixed to the ground");
  } else {
    const UrdfJoint& joint = tree.joints[*l.joint];
    JointText text = joint_text(context, joint, body_names[joint.parent], names);
    written.bodies.push_back(text.line);
    for (auto& q : text.coordinates) written.coordinates.push_back(q);
    for (auto& value : text.initial) written.initial.push_back(value);
    if (!text.damper.empty()) written.dampers.push_back(text.damper);
    if (context.limits) {
      const std::string q = text.coordinates.empty() ? "" : text.coordinates[0];
      write_joint_limits(context, joint, q, names, written);
    }
  }
  for (auto& line : link_body_lines(context, *l.element, body_names[link])) {
    written.bodies.push_back(std::move(line));
  }
}

}  // namespace

ImportedModel import_urdf(const std::string& text, const std::string& file,
                          const ImportOptions& options) {
  if (text.size() > kMaxUrdfBytes) {
    throw ModelError({file, 0, 0}, "a URDF file larger than 16 MiB is refused");
  }
  const XmlSource source(text, file);
  const XMLElement& robot = source.root();
  if (std::string(robot.Name()) != "robot") {
    source.refuse(robot, std::string("expected <robot>, found <") + robot.Name() + ">");
  }
  const std::string name = source.required(robot, "name");
  if (const std::string why = unprintable_name_reason(name, false); !why.empty()) {
    source.refuse(robot, "name", "the robot's name " + why);
  }
  ImportedModel model;
  Ignored ignored;
  ignore_others(source, robot, {"link", "joint", "material"}, ignored);
  const auto materials = named_materials(source, ignored);
  const UrdfTree tree = read_tree(source);
  const LinkContext context{source, model.notes, ignored, materials, options.limits};
  Names names;
  Written written;
  std::vector<std::string> body_names(tree.links.size());
  for (std::size_t link : tree.order) write_body(context, tree, link, body_names, names, written);
  model.yaml = model_yaml({name, file, "URDF", "{g: 9.81}", "  - gravity: -g*E3"}, written);
  for (auto& note : ignored.notes()) model.notes.push_back(std::move(note));
  return model;
}

ImportedModel import_urdf_file(const std::string& path, const ImportOptions& options) {
  return import_urdf(read_bounded_file(path, kMaxUrdfBytes, "URDF file"), path, options);
}

}  // namespace unidyn::formats
