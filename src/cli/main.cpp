// The `unidyn` command. Exit status: 0 success, 1 a run failed, 2 bad input.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <exception>

#include "rotation_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"unidyn: engineering dynamics after O'Reilly, Intermediate Dynamics for Engineers"};
  app.require_subcommand(1);
  unidyn::cli::RotationCommand rotation;
  unidyn::cli::add_rotation_command(app, rotation);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "unidyn: error: {}\n", e.what());
    return 2;
  }

  try {
    if (rotation.rotation->parsed()) return unidyn::cli::run_rotation_command(rotation);
  } catch (const std::exception& e) {
    // Every failure so far is a consequence of the input: a bad kind, count, number or rotation.
    fmt::print(stderr, "unidyn: error: {}\n", e.what());
    return 2;
  }
  return 0;
}
