// `unidyn equilibria`, `linearize` and `modes`: the analysis layer on the command line.
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace unidyn::cli {

struct AnalysisCommands {
  CLI::App* linearize = nullptr;
  CLI::App* modes = nullptr;
  CLI::App* equilibria = nullptr;

  std::string model;
  std::vector<std::string> at;    // NAME=VALUE of the operating point
  std::vector<std::string> sets;  // NAME=NUMBER of parameters
  std::string format = "text";
  std::string sweep;                // modes: PARAM=FROM:TO:COUNT
  std::string output;               // modes --sweep: the CSV file
  std::optional<double> period;     // linearize, modes: --period T (none: found, if any)
  std::size_t starts = 200;         // equilibria: the starting points
  std::vector<std::string> cyclic;  // equilibria: the cyclic coordinates
};

void add_analysis_commands(CLI::App& app, AnalysisCommands& commands);

struct CommandModel;
// The output of `unidyn COMMAND` (linearize, modes or equilibria; not --sweep) with the options
// in `c`. Throws std::invalid_argument for bad input, NotAnOperatingPoint among it.
void write_analysis(std::ostream& out, const std::string& command, const AnalysisCommands& c,
                    const CommandModel& model);

// Runs whichever of the commands was parsed; returns the exit status (0 success, 1 failure, 2 bad
// input), or -1 when none was.
int run_analysis_commands(const AnalysisCommands& commands);

}  // namespace unidyn::cli
