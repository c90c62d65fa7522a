// Numbers in error messages: the shortest text that reads back to the same double.
#pragma once

#include <array>
#include <charconv>
#include <string>

namespace unidyn::detail {

inline std::string to_text(double value) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  return std::string(buffer.data(), result.ptr);
}

}  // namespace unidyn::detail
