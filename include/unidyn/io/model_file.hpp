// Reading a model file (YAML, the contract of DESIGN.md) into a System.
#pragma once

#include <string>

#include "unidyn/model/system.hpp"

namespace unidyn {

// Reads and checks a model file. Every mistake throws ModelError naming file:line:column and what
// was expected. Nothing in the file is executed: expressions go through the safe parser only.
System load_model(const std::string& path);

// The bytes of a model file, read once (a pipe or FIFO cannot be read twice): what parse_model
// reads, and what the native-code cache is keyed by. Throws ModelError when it cannot be read.
std::string read_model_text(const std::string& path);

// The same from text (`file` is the name used in error messages).
System parse_model(const std::string& text, const std::string& file);

}  // namespace unidyn
