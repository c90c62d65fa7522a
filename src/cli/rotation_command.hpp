// `unidyn rotation ...`: conversions between parametrisations of a rotation.
#pragma once

#include <CLI/CLI.hpp>

namespace unidyn::cli {

// Adds `rotation convert` and `rotation show` to the application. Their work runs from the
// returned function after parsing; it returns the process exit status.
struct RotationCommand {
  CLI::App* rotation = nullptr;
  CLI::App* convert = nullptr;
  CLI::App* show = nullptr;
  std::vector<std::string> from;
  std::string to;
  bool degrees = false;  // angles typed and printed in degrees
};
void add_rotation_command(CLI::App& app, RotationCommand& command);
int run_rotation_command(const RotationCommand& command);

}  // namespace unidyn::cli
