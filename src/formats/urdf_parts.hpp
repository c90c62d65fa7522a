// The parts of a URDF import shared by its files: what was ignored, numbers as YAML text, and the
// lines of a link's body (its inertia and its visual).
#pragma once

#include <initializer_list>
#include <map>
#include <string>
#include <vector>

#include "xml_source.hpp"

namespace unidyn::formats {

// Elements unidyn does not read, one note per kind of element at its first occurrence.
class Ignored {
 public:
  // `why` ends the note ("ignored", "not applied: ...").
  void add(const XmlSource& source, const tinyxml2::XMLElement& element, const std::string& why);
  std::vector<std::string> notes() const;

 private:
  struct Kind {
    SourcePosition first;
    std::string why;
    int count = 0;
  };
  std::map<std::string, Kind> kinds_;
  std::vector<std::string> order_;  // the kinds in the order first met
};

// Every child element of `element` whose name is not in `known` is ignored.
void ignore_others(const XmlSource& source, const tinyxml2::XMLElement& element,
                   std::initializer_list<const char*> known, Ignored& ignored);

// "[a, b, c]" of the numbers as typed.
std::string vector_text(const std::vector<Number>& numbers);

// What a link's body is written from.
struct LinkContext {
  const XmlSource& source;
  std::vector<std::string>& notes;
  Ignored& ignored;
  const std::map<std::string, const tinyxml2::XMLElement*>& materials;  // <robot>'s, by name
};

// The body lines of a link after its `joint:` (indented under the body `name`): mass, inertia
// and centre from <inertial> (mass: 0 without one: a frame), and visual from <visual>.
std::vector<std::string> link_body_lines(const LinkContext& context,
                                         const tinyxml2::XMLElement& link, const std::string& name);

}  // namespace unidyn::formats
