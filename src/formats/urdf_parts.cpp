// What a URDF import ignores, and numbers as the model's text.
#include "urdf_parts.hpp"

#include <cstring>

namespace unidyn::formats {

void Ignored::add(const XmlSource& source, const tinyxml2::XMLElement& element,
                  const std::string& why) {
  const std::string name = element.Name();
  auto [kind, first] = kinds_.try_emplace(name, Kind{source.position(element), why, 0});
  if (first) order_.push_back(name);
  ++kind->second.count;
}

// "file:line:column: <collision> ignored (3 in the file, the first here)"
std::vector<std::string> Ignored::notes() const {
  std::vector<std::string> notes;
  for (const auto& name : order_) {
    const Kind& kind = kinds_.at(name);
    notes.push_back(kind.first.str() + ": <" + name + "> " + kind.why +
                    (kind.count > 1
                         ? " (" + std::to_string(kind.count) + " in the file, the first here)"
                         : ""));
  }
  return notes;
}

void ignore_others(const XmlSource& source, const tinyxml2::XMLElement& element,
                   std::initializer_list<const char*> known, Ignored& ignored) {
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    bool is_known = false;
    for (const char* name : known) is_known = is_known || std::strcmp(child->Name(), name) == 0;
    if (!is_known) ignored.add(source, *child, "ignored");
  }
}

std::string vector_text(const std::vector<Number>& numbers) {
  std::string text = "[";
  for (const Number& x : numbers) text += (text.size() > 1 ? ", " : "") + x.text;
  return text + "]";
}

}  // namespace unidyn::formats
