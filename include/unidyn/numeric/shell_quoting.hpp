// Text as one word for a POSIX shell: in single quotes, where nothing is special, each ' written
// '\'' (close, an escaped quote, reopen). Newlines, $(), backticks and spaces stay literal.
#pragma once

#include <string>
#include <string_view>

namespace unidyn {

inline std::string shell_quoted(std::string_view text) {
  std::string out = "'";
  for (const char c : text) {
    if (c == '\'') {
      out += "'\\''";
    } else {
      out += c;
    }
  }
  return out + "'";
}

}  // namespace unidyn
