// An XML file's text beside its tinyxml2 document: where each element and attribute is
// (file:line:column; tinyxml2 gives only an element's line), and its numbers read strictly.
#pragma once

#include <tinyxml2.h>

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn::formats {

// A number as the file typed it (a leading '+' dropped) and its value.
struct Number {
  std::string text;
  double value = 0;
};

class XmlSource {
 public:
  // The document parsed from `text` (kept by reference); a malformed file is refused at the
  // line tinyxml2 names.
  XmlSource(const std::string& text, std::string file);
  XmlSource(const XmlSource&) = delete;
  XmlSource& operator=(const XmlSource&) = delete;

  const tinyxml2::XMLElement& root() const;
  const std::string& file() const { return file_; }

  // Where an element's tag starts ('<'), and where an attribute's value starts (the element's
  // position when it has no such attribute).
  SourcePosition position(const tinyxml2::XMLElement& element) const;
  SourcePosition position(const tinyxml2::XMLElement& element, const char* attribute) const;

  // An attribute given to `element` from another element (MJCF's <default> classes): its
  // position is then that element's attribute. The document is changed through mutable_root().
  void inherit(const tinyxml2::XMLElement& element, const char* attribute,
               const tinyxml2::XMLElement& from);
  tinyxml2::XMLElement& mutable_root();

  // Refuses with a message at the element, or at its attribute.
  [[noreturn]] void refuse(const tinyxml2::XMLElement& element, const std::string& message) const;
  [[noreturn]] void refuse(const tinyxml2::XMLElement& element, const char* attribute,
                           const std::string& message) const;

  // An attribute's text; a missing one is refused ("<joint> needs name=").
  std::string required(const tinyxml2::XMLElement& element, const char* attribute) const;

  // An attribute's `count` whitespace-separated decimal numbers (finite; no hexadecimal, NaN or
  // inf), each refused at its own column when it is not one; nullopt when the attribute is absent.
  std::optional<std::vector<Number>> numbers(const tinyxml2::XMLElement& element,
                                             const char* attribute, std::size_t count) const;
  // The same, a missing attribute refused ("<geom> needs size=").
  std::vector<Number> required_numbers(const tinyxml2::XMLElement& element, const char* attribute,
                                       std::size_t count) const;
  // The same, with `fallback` (count numbers' texts) when the attribute is absent.
  std::vector<Number> numbers_or(const tinyxml2::XMLElement& element, const char* attribute,
                                 const std::vector<const char*>& fallback) const;

 private:
  SourcePosition at_offset(std::size_t offset) const;
  std::optional<std::size_t> attribute_offset(const tinyxml2::XMLElement& element,
                                              const char* attribute) const;
  void locate_elements(const tinyxml2::XMLElement& element, std::size_t& cursor);

  const std::string& text_;
  std::string file_;
  tinyxml2::XMLDocument document_;
  std::vector<std::size_t> line_starts_;
  std::unordered_map<const tinyxml2::XMLElement*, std::size_t> element_offsets_;
  // (element, attribute) → the element that gave the attribute (inherit)
  std::map<std::pair<const tinyxml2::XMLElement*, std::string>, const tinyxml2::XMLElement*>
      inherited_;
};

}  // namespace unidyn::formats
