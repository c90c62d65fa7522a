// `unidyn import FILE [-o OUT]`: its command-line options and exit status.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "unidyn/formats/urdf.hpp"

namespace unidyn::cli {

struct ImportCommand {
  CLI::App* import = nullptr;
  std::string file;                // the URDF or MJCF file
  std::string output;              // -o: the YAML file (default: standard output)
  formats::ImportOptions options;  // --limits
};

// The options of an import, on every command that reads a URDF or MJCF file (--limits).
void add_import_options(CLI::App& command, formats::ImportOptions& options);

void add_import_command(CLI::App& app, ImportCommand& command);

// 0 once written (a file refused throws ModelError: exit 2).
int run_import_command(const ImportCommand& command);

}  // namespace unidyn::cli
