// Positions in an XML file's text and its numbers, read strictly.
#include "xml_source.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>

namespace unidyn::formats {
namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

// A name character of XML (enough to find where a tag's or an attribute's name ends).
bool ends_name(char c) {
  return is_space(c) || c == '=' || c == '>' || c == '/';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

// A decimal number: [+-] digits ['.' digits] or [+-] '.' digits, then [(e|E) [+-] digits].
bool is_decimal(const std::string& token) {
  std::size_t at = token.size() > 0 && (token[0] == '+' || token[0] == '-') ? 1 : 0;
  const auto digits = [&] {
    const std::size_t start = at;
    while (at < token.size() && is_digit(token[at])) ++at;
    return at - start;
  };
  std::size_t mantissa = digits();
  if (at < token.size() && token[at] == '.') {
    ++at;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (at < token.size() && (token[at] == 'e' || token[at] == 'E')) {
    ++at;
    if (at < token.size() && (token[at] == '+' || token[at] == '-')) ++at;
    if (digits() == 0) return false;
  }
  return at == token.size();
}

}  // namespace

// The document, and each element's offset in the text (tinyxml2 gives only its line).
XmlSource::XmlSource(const std::string& text, std::string file)
    : text_(text), file_(std::move(file)) {
  line_starts_.push_back(0);
  for (std::size_t i = 0; i < text_.size(); ++i) {
    if (text_[i] == '\n') line_starts_.push_back(i + 1);
  }
  if (document_.Parse(text_.data(), text_.size()) != tinyxml2::XML_SUCCESS) {
    // the line tinyxml2 names, at its first character that is not a space
    const int line = std::max(document_.ErrorLineNum(), 1);
    std::size_t at = line_starts_[std::min<std::size_t>(static_cast<std::size_t>(line) - 1,
                                                        line_starts_.size() - 1)];
    while (at < text_.size() && (text_[at] == ' ' || text_[at] == '\t')) ++at;
    // tinyxml2's "Error=NAME ErrorID=N (0xN) Line number=L: detail": the name and the detail
    const std::string detail = document_.ErrorStr();
    const std::size_t colon = detail.find(": ");
    throw ModelError(at_offset(at), std::string("malformed XML: ") + document_.ErrorName() +
                                        (colon == std::string::npos ? "" : detail.substr(colon)));
  }
  if (document_.RootElement() == nullptr) {
    throw ModelError({file_, 1, 1}, "malformed XML: no element");
  }
  std::size_t cursor = 0;
  locate_elements(*document_.RootElement(), cursor);
}

const tinyxml2::XMLElement& XmlSource::root() const {
  return *document_.RootElement();
}

tinyxml2::XMLElement& XmlSource::mutable_root() {
  return *document_.RootElement();
}

void XmlSource::inherit(const tinyxml2::XMLElement& element, const char* attribute,
                        const tinyxml2::XMLElement& from) {
  inherited_[{&element, attribute}] = &from;
}

// Elements come in the text in document order: each one's '<name' is found after the last one's,
// on the line tinyxml2 gives.
void XmlSource::locate_elements(const tinyxml2::XMLElement& element, std::size_t& cursor) {
  const std::size_t line = static_cast<std::size_t>(std::max(element.GetLineNum(), 1)) - 1;
  const std::string tag = std::string("<") + element.Name();
  std::size_t at = std::max(cursor, line_starts_[std::min(line, line_starts_.size() - 1)]);
  for (at = text_.find(tag, at); at != std::string::npos; at = text_.find(tag, at + 1)) {
    const std::size_t after = at + tag.size();
    if (after < text_.size() && ends_name(text_[after])) break;
  }
  cursor = at == std::string::npos ? cursor : at + 1;
  element_offsets_[&element] = at == std::string::npos ? cursor : at;
  for (const auto* child = element.FirstChildElement(); child;
       child = child->NextSiblingElement()) {
    locate_elements(*child, cursor);
  }
}

SourcePosition XmlSource::at_offset(std::size_t offset) const {
  const auto next = std::upper_bound(line_starts_.begin(), line_starts_.end(), offset);
  const std::size_t line = static_cast<std::size_t>(next - line_starts_.begin());
  return {file_, static_cast<int>(line), static_cast<int>(offset - line_starts_[line - 1] + 1)};
}

SourcePosition XmlSource::position(const tinyxml2::XMLElement& element) const {
  return at_offset(element_offsets_.at(&element));
}

// The start tag read again from '<name': attributes name="value" or name='value' up to '>'.
std::optional<std::size_t> XmlSource::attribute_offset(const tinyxml2::XMLElement& element,
                                                       const char* attribute) const {
  std::size_t at = element_offsets_.at(&element) + 1 + std::strlen(element.Name());
  while (at < text_.size()) {
    while (at < text_.size() && is_space(text_[at])) ++at;
    if (at >= text_.size() || text_[at] == '>' || text_[at] == '/') return std::nullopt;
    const std::size_t name_start = at;
    while (at < text_.size() && !ends_name(text_[at])) ++at;
    const std::string name = text_.substr(name_start, at - name_start);
    while (at < text_.size() && (is_space(text_[at]) || text_[at] == '=')) ++at;
    if (at >= text_.size()) return std::nullopt;
    const std::size_t close = text_.find(text_[at], at + 1);
    if (close == std::string::npos) return std::nullopt;
    if (name == attribute) return at + 1;
    at = close + 1;
  }
  return std::nullopt;
}

SourcePosition XmlSource::position(const tinyxml2::XMLElement& element,
                                   const char* attribute) const {
  if (const auto from = inherited_.find({&element, attribute}); from != inherited_.end()) {
    return position(*from->second, attribute);
  }
  const auto offset = attribute_offset(element, attribute);
  return offset ? at_offset(*offset) : position(element);
}

void XmlSource::refuse(const tinyxml2::XMLElement& element, const std::string& message) const {
  throw ModelError(position(element), message);
}

void XmlSource::refuse(const tinyxml2::XMLElement& element, const char* attribute,
                       const std::string& message) const {
  throw ModelError(position(element, attribute), message);
}

std::string XmlSource::required(const tinyxml2::XMLElement& element, const char* attribute) const {
  const char* value = element.Attribute(attribute);
  if (value == nullptr) {
    refuse(element, std::string("<") + element.Name() + "> needs " + attribute + "=\"...\"");
  }
  return value;
}

// Each whitespace-separated token a decimal number, refused at its own column when it is not.
std::vector<Number> XmlSource::required_numbers(const tinyxml2::XMLElement& element,
                                                const char* attribute, std::size_t count) const {
  required(element, attribute);
  return *numbers(element, attribute, count);
}

std::optional<std::vector<Number>> XmlSource::numbers(const tinyxml2::XMLElement& element,
                                                      const char* attribute,
                                                      std::size_t count) const {
  const char* value = element.Attribute(attribute);
  if (value == nullptr) return std::nullopt;
  const SourcePosition where = position(element, attribute);
  const std::string what = std::string(element.Name()) + " " + attribute;
  std::vector<Number> found;
  const std::string text = value;
  for (std::size_t at = 0; at < text.size();) {
    if (is_space(text[at])) {
      ++at;
      continue;
    }
    std::size_t end = at;
    while (end < text.size() && !is_space(text[end])) ++end;
    const std::string token = text.substr(at, end - at);
    const SourcePosition token_where = where.advanced(static_cast<int>(at));
    const double x = is_decimal(token) ? std::strtod(token.c_str(), nullptr) : NAN;
    if (!std::isfinite(x)) {
      throw ModelError(token_where, what + ": '" + token + "' is not a finite decimal number");
    }
    if (found.size() == count) {
      throw ModelError(token_where, what + ": expected " + std::to_string(count) + " numbers");
    }
    found.push_back({token[0] == '+' ? token.substr(1) : token, x});
    at = end;
  }
  if (found.size() != count) {
    throw ModelError(where, what + ": expected " + std::to_string(count) + " numbers, found " +
                                std::to_string(found.size()));
  }
  return found;
}

std::vector<Number> XmlSource::numbers_or(const tinyxml2::XMLElement& element,
                                          const char* attribute,
                                          const std::vector<const char*>& fallback) const {
  if (auto found = numbers(element, attribute, fallback.size())) return *found;
  std::vector<Number> numbers;
  for (const char* text : fallback) numbers.push_back({text, std::strtod(text, nullptr)});
  return numbers;
}

}  // namespace unidyn::formats
