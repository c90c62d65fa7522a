// MJCF <default> classes (MuJoCo's XML reference, "default"): each class sets attributes of the
// elements of a kind (<joint>, <geom>, ...) that name it by class=, or that sit in a body whose
// childclass= (or an ancestor's) names it, or else of every element ("main", the top <default>).
// A nested <default class="..."> starts from its parent's settings. Applied here before the
// bodies are read: a missing attribute is copied from the class's setting, and its position (in
// messages) stays the <default>'s.
#include <map>
#include <string>
#include <utility>

#include "mjcf_parts.hpp"

namespace unidyn::formats {
namespace {

using tinyxml2::XMLElement;

// A class's settings: per element kind, per attribute, the <default> child that sets it.
using ClassSettings = std::map<std::string, std::map<std::string, const XMLElement*>>;

// The classes of one <default> element and those nested in it, from `inherited`.
void read_class(const XmlSource& source, const XMLElement& element, const std::string& name,
                ClassSettings settings, std::map<std::string, ClassSettings>& classes) {
  if (classes.count(name)) source.refuse(element, "class", "class '" + name + "' is defined twice");
  for (const auto* kind = element.FirstChildElement(); kind; kind = kind->NextSiblingElement()) {
    if (std::string(kind->Name()) == "default") continue;
    for (const auto* a = kind->FirstAttribute(); a; a = a->Next()) {
      settings[kind->Name()][a->Name()] = kind;
    }
  }
  classes[name] = settings;
  for (const auto* nested = element.FirstChildElement("default"); nested;
       nested = nested->NextSiblingElement("default")) {
    const char* nested_name = nested->Attribute("class");
    if (!nested_name) source.refuse(*nested, "a nested <default> needs class=\"...\"");
    read_class(source, *nested, nested_name, settings, classes);
  }
}

// Copies the class's settings into the elements below `parent` (bodies' childclass= passed on).
void apply_classes(XmlSource& source, XMLElement& parent, const std::string& childclass,
                   const std::map<std::string, ClassSettings>& classes) {
  for (auto* e = parent.FirstChildElement(); e; e = e->NextSiblingElement()) {
    const bool body = std::string(e->Name()) == "body";
    const char* own = e->Attribute(body ? "childclass" : "class");
    const std::string name = own ? own : childclass;
    const auto found = classes.find(name);
    if (found == classes.end()) {
      source.refuse(*e, body ? "childclass" : "class",
                    "class '" + name + "' is not defined in <default>");
    }
    if (body) {
      apply_classes(source, *e, name, classes);
      continue;
    }
    const auto kind = found->second.find(e->Name());
    if (kind == found->second.end()) continue;
    for (const auto& [attribute, from] : kind->second) {
      if (e->Attribute(attribute.c_str())) continue;
      e->SetAttribute(attribute.c_str(), from->Attribute(attribute.c_str()));
      source.inherit(*e, attribute.c_str(), *from);
    }
  }
}

}  // namespace

void apply_default_classes(XmlSource& source) {
  XMLElement& mujoco = source.mutable_root();
  std::map<std::string, ClassSettings> classes;
  const XMLElement* top = mujoco.FirstChildElement("default");
  if (top && top->NextSiblingElement("default")) {
    source.refuse(*top->NextSiblingElement("default"), "<mujoco> has one top <default>");
  }
  const char* top_name = top ? top->Attribute("class") : nullptr;
  if (top_name && std::string(top_name) != "main") {
    source.refuse(*top, "class", "the top <default> is class 'main'");
  }
  if (top) {
    read_class(source, *top, "main", {}, classes);
  } else {
    classes["main"] = {};
  }
  for (auto* world = mujoco.FirstChildElement("worldbody"); world;
       world = world->NextSiblingElement("worldbody")) {
    apply_classes(source, *world, "main", classes);
  }
}

}  // namespace unidyn::formats
