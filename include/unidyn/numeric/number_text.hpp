// Numbers in error messages and summaries.
#pragma once

#include <array>
#include <charconv>
#include <string>

namespace unidyn::detail {

// The shortest text that reads back to the same double.
inline std::string to_text(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

// Numbers in summaries and messages about a state: twelve significant digits (or `digits`), so that
// a value computed as -3 + 0.9 reads -2.1.
inline std::string to_short_text(double value, int digits = 12) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                    std::chars_format::general, digits);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace unidyn::detail
