// Escaping control characters, and the rule for names that reach a terminal or a CSV header.
#include "unidyn/symbolic/printable_text.hpp"

#include <cstdio>

namespace unidyn {
namespace {

// One UTF-8 sequence at text[i]: its code point and length, or length 0 when it is not UTF-8
// (overlong forms, surrogates and values past U+10FFFF included).
std::pair<char32_t, std::size_t> decode(std::string_view text, std::size_t i) {
  const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
  const unsigned char b0 = byte(i);
  if (b0 < 0x80) return {b0, 1};
  std::size_t length = 0;
  char32_t code = 0, least = 0;
  if ((b0 & 0xE0) == 0xC0) {
    length = 2, code = b0 & 0x1F, least = 0x80;
  } else if ((b0 & 0xF0) == 0xE0) {
    length = 3, code = b0 & 0x0F, least = 0x800;
  } else if ((b0 & 0xF8) == 0xF0) {
    length = 4, code = b0 & 0x07, least = 0x10000;
  } else {
    return {0, 0};
  }
  if (i + length > text.size()) return {0, 0};
  for (std::size_t k = 1; k < length; ++k) {
    if ((byte(i + k) & 0xC0) != 0x80) return {0, 0};
    code = (code << 6) | (byte(i + k) & 0x3F);
  }
  if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return {0, 0};
  return {code, length};
}

bool is_control(char32_t c) {
  return c < 0x20 || c == 0x7F || (c >= 0x80 && c < 0xA0) || c == 0x061C || c == 0x200E ||
         c == 0x200F || (c >= 0x202A && c <= 0x202E) || (c >= 0x2066 && c <= 0x2069);
}

std::string hex(const char* format, unsigned value) {
  char buffer[16];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

}  // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size();) {
    const auto [code, length] = decode(text, i);
    if (length == 0) {
      out += hex("\\x%02X", static_cast<unsigned char>(text[i]));
      ++i;
      continue;
    }
    if (!is_control(code)) {
      out.append(text.substr(i, length));
    } else if (code == '\n') {
      out += "\\n";
    } else if (code == '\t') {
      out += "\\t";
    } else if (code == '\r') {
      out += "\\r";
    } else if (code == 0x1B) {
      out += "\\e";
    } else if (code < 0x80) {
      out += hex("\\x%02X", static_cast<unsigned>(code));
    } else {
      out += hex("\\u{%04X}", static_cast<unsigned>(code));
    }
    i += length;
  }
  return out;
}

std::string unprintable_name_reason(std::string_view text, bool csv_column) {
  if (text.empty()) return "is empty";
  for (std::size_t i = 0; i < text.size();) {
    const auto [code, length] = decode(text, i);
    if (length == 0) return "is not UTF-8 text";
    if (is_control(code)) {
      return "holds the control character " + printable(text.substr(i, length)) +
             " (names are printable text)";
    }
    i += length;
  }
  if (csv_column && std::string_view("=+-@").find(text[0]) != std::string_view::npos) {
    return std::string("starts with '") + text[0] +
           "', which a spreadsheet takes for a formula (a CSV column's name must not)";
  }
  return "";
}

}  // namespace unidyn
