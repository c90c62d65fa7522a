// Pieces of JSON text: string literals and numbers.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

namespace unidyn {

// A JSON string literal: quotes and backslashes escaped, control characters (a summary's line
// breaks) as \n, \t or \u00XX.
inline std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (static_cast<unsigned char>(c) < 0x20) {
      out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
    } else {
      out += c;
    }
  }
  return out + "\"";
}

// A number as JSON: the shortest text that reads back as the same double; null when it has none
// (or is not finite: JSON has no NaN or infinity).
inline std::string json_number(const std::optional<double>& x) {
  return x && std::isfinite(*x) ? fmt::format("{}", *x) : std::string("null");
}

}  // namespace unidyn
