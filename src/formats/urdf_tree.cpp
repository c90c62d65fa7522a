// The tree of a URDF robot's links and joints, and the names they get in the model.
#include "urdf_tree.hpp"

#include <map>

#include "unidyn/formats/urdf.hpp"
#include "unidyn/symbolic/expression_parser.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

bool is_identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// A word the model language keeps: its constants and functions, time t, and lambda.
bool is_reserved(const std::string& name) {
  return is_reserved_name(name) || name == "t" || name == "lambda";
}

// The identifier nearest a name: other characters as '_', '_' before a leading digit, '_' after
// a reserved word.
std::string identifier(const std::string& name) {
  std::string id = name;
  for (char& c : id) c = is_identifier_char(c) ? c : '_';
  if (id.empty() || (id[0] >= '0' && id[0] <= '9')) id = "_" + id;
  if (is_reserved(id)) id += "_";
  return id;
}

const std::set<std::string> kJointTypes = {"revolute", "continuous", "prismatic",
                                           "fixed",    "floating",   "planar"};

// The link a joint's <parent link=...> or <child link=...> names.
std::size_t joint_end(const XmlSource& source, const XMLElement& joint, const char* end,
                      const std::map<std::string, std::size_t>& links) {
  const XMLElement* element = joint.FirstChildElement(end);
  if (element == nullptr) source.refuse(joint, std::string("<joint> needs <") + end + " link=...>");
  const std::string name = source.required(*element, "link");
  const auto found = links.find(name);
  if (found == links.end()) {
    source.refuse(*element, "link", "no link is named '" + printable(name) + "'");
  }
  return found->second;
}

// Following parent joints from `link` upwards: a link met twice is on a cycle, refused at the
// joint that closes it.
void refuse_cycle(const XmlSource& source, const UrdfTree& tree, std::size_t link) {
  std::vector<bool> seen(tree.links.size());
  while (!seen[link]) {
    seen[link] = true;
    link = tree.joints[*tree.links[link].joint].parent;
  }
  const UrdfJoint& closing = tree.joints[*tree.links[link].joint];
  std::string cycle = printable(tree.links[link].urdf_name);
  for (std::size_t at = closing.parent; at != link;
       at = tree.joints[*tree.links[at].joint].parent) {
    cycle = printable(tree.links[at].urdf_name) + " → " + cycle;
  }
  source.refuse(*closing.element, "joint '" + printable(closing.urdf_name) +
                                      "' closes a cycle of links (" +
                                      printable(tree.links[link].urdf_name) + " → " + cycle +
                                      "): a URDF robot is a tree");
}

// The links depth-first from the root, each link's child joints in file order.
std::vector<std::size_t> depth_first(const UrdfTree& tree, std::size_t root) {
  std::vector<std::size_t> order;
  std::vector<std::size_t> stack = {root};
  while (!stack.empty()) {
    const std::size_t link = stack.back();
    stack.pop_back();
    order.push_back(link);
    const auto& children = tree.links[link].child_joints;
    for (auto it = children.rbegin(); it != children.rend(); ++it) {
      stack.push_back(tree.joints[*it].child);
    }
  }
  return order;
}

// The one root: the link that is no joint's child.
std::size_t root_link(const XmlSource& source, const UrdfTree& tree) {
  std::vector<std::size_t> roots;
  for (std::size_t i = 0; i < tree.links.size(); ++i) {
    if (!tree.links[i].joint) roots.push_back(i);
  }
  if (roots.empty()) refuse_cycle(source, tree, 0);
  if (roots.size() > 1) {
    std::string names;
    for (std::size_t i : roots)
      names += (names.empty() ? "" : ", ") + printable(tree.links[i].urdf_name);
    source.refuse(*tree.links[roots[1]].element,
                  "several root links (no joint's child): " + names +
                      "; a URDF robot has one (join the others to it by joints)");
  }
  return roots[0];
}

// The <link> elements, named once each.
void read_links(const XmlSource& source, UrdfTree& tree,
                std::map<std::string, std::size_t>& index) {
  for (const auto* e = source.root().FirstChildElement("link"); e;
       e = e->NextSiblingElement("link")) {
    const std::string name = source.required(*e, "name");
    if (!index.emplace(name, tree.links.size()).second) {
      source.refuse(*e, "name", "a second link named '" + printable(name) + "'");
    }
    if (tree.links.size() == kMaxUrdfLinks) {
      source.refuse(*e, "more than " + std::to_string(kMaxUrdfLinks) + " links");
    }
    tree.links.push_back({e, name, std::nullopt, {}});
  }
  if (tree.links.empty()) source.refuse(source.root(), "<robot> has no <link>");
}

// The <joint> elements: a known type, a parent and a child that exist, each link one joint's
// child.
void read_joints(const XmlSource& source, UrdfTree& tree,
                 const std::map<std::string, std::size_t>& links) {
  std::set<std::string> names;
  for (const auto* e = source.root().FirstChildElement("joint"); e;
       e = e->NextSiblingElement("joint")) {
    const std::string name = source.required(*e, "name");
    if (!names.insert(name).second) {
      source.refuse(*e, "name", "a second joint named '" + printable(name) + "'");
    }
    const std::string type = source.required(*e, "type");
    if (!kJointTypes.count(type)) {
      source.refuse(*e, "type",
                    "unknown joint type '" + printable(type) +
                        "' (expected revolute, continuous, prismatic, fixed, floating or planar)");
    }
    const std::size_t parent = joint_end(source, *e, "parent", links);
    const std::size_t child = joint_end(source, *e, "child", links);
    UrdfLink& link = tree.links[child];
    if (link.joint) {
      source.refuse(*e->FirstChildElement("child"), "link",
                    "link '" + printable(link.urdf_name) + "' is already the child of joint '" +
                        printable(tree.joints[*link.joint].urdf_name) + "'");
    }
    link.joint = tree.joints.size();
    tree.links[parent].child_joints.push_back(tree.joints.size());
    tree.joints.push_back({e, name, type, parent, child});
  }
}

}  // namespace

Names::Names() : taken_{"g"} {}

std::string Names::claim(const std::string& wanted, const std::string& what,
                         const SourcePosition& where, std::vector<std::string>& notes,
                         std::string* change) {
  std::string name = identifier(wanted);
  std::string reason = name == wanted ? "" : "not a unidyn identifier";
  if (taken_.count(name)) {
    const std::string base = name;
    for (int suffix = 2; taken_.count(name); ++suffix) name = base + "_" + std::to_string(suffix);
    reason = "'" + base + "' names something else";
  }
  taken_.insert(name);
  if (!reason.empty()) {
    const std::string text =
        what + " '" + printable(wanted) + "' is named " + name + " in unidyn (" + reason + ")";
    notes.push_back(where.str() + ": " + text);
    if (change) *change = text;
  }
  return name;
}

UrdfTree read_tree(const XmlSource& source) {
  UrdfTree tree;
  std::map<std::string, std::size_t> links;
  read_links(source, tree, links);
  read_joints(source, tree, links);
  tree.order = depth_first(tree, root_link(source, tree));
  // a link the root does not reach is on a cycle
  if (tree.order.size() < tree.links.size()) {
    std::vector<bool> reached(tree.links.size());
    for (std::size_t link : tree.order) reached[link] = true;
    for (std::size_t i = 0; i < tree.links.size(); ++i) {
      if (!reached[i]) refuse_cycle(source, tree, i);
    }
  }
  return tree;
}

}  // namespace unidyn::formats
