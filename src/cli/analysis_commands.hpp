// `unidyn equilibria`, `linearize` and `modes`: their command-line options, read into the commands
// layer's options (unidyn/commands/analysis_commands.hpp), and the exit statuses.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

#include "unidyn/commands/analysis_commands.hpp"

namespace unidyn::cli {

struct AnalysisCommands {
  CLI::App* linearize = nullptr;
  CLI::App* modes = nullptr;
  CLI::App* equilibria = nullptr;

  std::string model;  // the MODEL argument
  commands::AnalysisOptions options;
};

void add_analysis_commands(CLI::App& app, AnalysisCommands& commands);

// Runs whichever of the commands was parsed; returns the exit status (0 success, 1 failure, 2 bad
// input), or -1 when none was.
int run_analysis_commands(const AnalysisCommands& commands);

}  // namespace unidyn::cli
