// `unidyn import` on the command line.
#include "import_command.hpp"

#include <iostream>

#include "unidyn/commands/import_command.hpp"

namespace unidyn::cli {

void add_import_command(CLI::App& app, ImportCommand& c) {
  c.import = app.add_subcommand(
      "import",
      "Write a URDF or MJCF robot as a unidyn model (YAML) to read and edit; notes on stderr");
  c.import->add_option("file", c.file, "URDF file (*.urdf) or MJCF file (*.xml, root <mujoco>)")
      ->required();
  c.import->add_option("-o,--output", c.output, "YAML file (default: standard output)");
  add_import_options(*c.import, c.options);
}

void add_import_options(CLI::App& command, formats::ImportOptions& options) {
  command.add_flag("--limits", options.limits,
                   "a URDF or MJCF file's joint limits (<limit lower upper>, a limited joint's "
                   "range) as unilateral contacts NAME_lower, NAME_upper that stop the joint");
}

int run_import_command(const ImportCommand& c) {
  commands::write_import(c.file, c.options, c.output, std::cout, std::cerr);
  return 0;
}

}  // namespace unidyn::cli
