// Pieces of JSON text: string literals and numbers.
#pragma once

#include <fmt/format.h>

#include <cmath>
#include <optional>
#include <string>

namespace unidyn {

// A JSON string literal (names and expressions are printable text: model_checks refuses others).
inline std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

// A number as JSON: the shortest text that reads back as the same double; null when it has none
// (or is not finite: JSON has no NaN or infinity).
inline std::string json_number(const std::optional<double>& x) {
  return x && std::isfinite(*x) ? fmt::format("{}", *x) : std::string("null");
}

}  // namespace unidyn
