// A URDF robot's links and joints as a tree: the root link, each link's parent joint and child
// joints, in the depth-first order the model is written in, and the unidyn names of all of them.
#pragma once

#include <cstddef>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "xml_source.hpp"

namespace unidyn::formats {

// The model's names: identifiers, none reserved, none twice. A URDF name that is not one is
// changed (other characters → '_', a numeric suffix on a collision), with a note.
class Names {
 public:
  Names();
  // The unidyn name for `wanted` (the URDF's name of a `what`, e.g. "link"), and the change as a
  // note at `where` when there is one (`change` receives the reason, for a YAML comment).
  std::string claim(const std::string& wanted, const std::string& what, const SourcePosition& where,
                    std::vector<std::string>& notes, std::string* change = nullptr);

 private:
  std::set<std::string> taken_;
};

struct UrdfJoint {
  const tinyxml2::XMLElement* element = nullptr;
  std::string urdf_name;
  std::string type;
  std::size_t parent = 0;  // links
  std::size_t child = 0;
};

struct UrdfLink {
  const tinyxml2::XMLElement* element = nullptr;
  std::string urdf_name;
  std::optional<std::size_t> joint;       // the joint of which it is the child
  std::vector<std::size_t> child_joints;  // in file order
};

struct UrdfTree {
  std::vector<UrdfLink> links;     // in file order
  std::vector<UrdfJoint> joints;   // in file order
  std::vector<std::size_t> order;  // the links depth-first from the root
};

// The links and joints of <robot>; refused: a duplicate name, an unknown joint type, a joint
// naming an unknown link, a link that is two joints' child, a cycle, no root or several roots,
// more than kMaxUrdfLinks links.
UrdfTree read_tree(const XmlSource& source);

}  // namespace unidyn::formats
