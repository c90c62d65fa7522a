// `unidyn derive`, `simulate`, `check`, `models`, `report`: their command-line options, read into
// the commands layer's options (unidyn/commands/model_commands.hpp), and the exit statuses.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "unidyn/commands/model_commands.hpp"
#include "unidyn/formats/urdf.hpp"

namespace unidyn::cli {

struct ModelCommands {
  CLI::App* derive = nullptr;
  CLI::App* simulate = nullptr;
  CLI::App* check = nullptr;
  CLI::App* models = nullptr;
  CLI::App* report = nullptr;

  std::string model;       // the MODEL argument
  std::string model_name;  // models: the bundled model to print
  bool timings = false;    // derive, check: each phase's time on standard error
  commands::ModelOptions options;
  formats::ImportOptions import;  // --limits
};

void add_model_commands(CLI::App& app, ModelCommands& commands);

// Runs whichever of the commands was parsed; returns the exit status (0 success, 1 the run failed,
// 2 bad input), or -1 when none of them was.
int run_model_commands(const ModelCommands& commands);

}  // namespace unidyn::cli
