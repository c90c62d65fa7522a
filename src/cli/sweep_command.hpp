// `unidyn sweep plan|run|gather|emit`: their command-line options, read into the commands layer's
// options (unidyn/commands/sweep_commands.hpp), and the exit statuses.
#pragma once

#include <CLI/CLI.hpp>

#include "unidyn/commands/sweep_commands.hpp"

namespace unidyn::cli {

struct SweepCommand {
  CLI::App* sweep = nullptr;
  CLI::App* plan = nullptr;
  CLI::App* run = nullptr;
  CLI::App* gather = nullptr;
  CLI::App* emit = nullptr;
  commands::SweepOptions options;
};

void add_sweep_command(CLI::App& app, SweepCommand& command);
// The exit status: 0, 1 (gather: runs missing), 2 (bad input throws std::invalid_argument).
int run_sweep_command(const SweepCommand& command);

}  // namespace unidyn::cli
