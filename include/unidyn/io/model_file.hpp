// Reading a model file (YAML, the contract of DESIGN.md) into a System.
#pragma once

#include <cstddef>
#include <string>

#include "unidyn/model/system.hpp"

namespace unidyn {

// The largest model file or text read (4 MiB): anything larger is refused before it is parsed.
inline constexpr std::size_t kMaxModelBytes = 4u << 20;

// Reads and checks a model file. Every mistake throws ModelError naming file:line:column and what
// was expected. Nothing in the file is executed: expressions go through the safe parser only.
System load_model(const std::string& path);

// The bytes of a model file, read once (a pipe or FIFO cannot be read twice): what parse_model
// reads, and what the native-code cache is keyed by. Throws ModelError when it cannot be read.
std::string read_model_text(const std::string& path);

// What of a model file determines its compiled code, for the native-code cache's key: the YAML
// re-emitted in one canonical form (no comments, one layout) without name:, description:,
// reference:, initial: and simulate: (but for simulate:'s stop_when, which is compiled). Equal
// for two files that differ only in those; different whenever the code could differ. Throws
// ModelError for text that is not YAML.
std::string model_code_text(const std::string& text, const std::string& file);

// The same from text (`file` is the name used in error messages).
System parse_model(const std::string& text, const std::string& file);

}  // namespace unidyn
