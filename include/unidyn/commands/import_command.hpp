// `unidyn import FILE [-o OUT]`: a file of another format (URDF) as the model language's YAML.
#pragma once

#include <ostream>
#include <string>

#include "unidyn/formats/urdf.hpp"

namespace unidyn::commands {

// Writes the model `file` imports as to `output` (whole or not at all), or to `out` when `output`
// is empty; each note of the import a line on `notes`. Throws ModelError for a file refused
// (file:line:column), std::invalid_argument for a file of no format unidyn imports.
void write_import(const std::string& file, const formats::ImportOptions& options,
                  const std::string& output, std::ostream& out, std::ostream& notes);

}  // namespace unidyn::commands
