// `unidyn derive`, `simulate`, `check`, `models`: the model pipeline on the command line.
#pragma once

#include <CLI/CLI.hpp>
#include <ostream>
#include <string>
#include <vector>

namespace unidyn::cli {

struct CommandModel;

struct ModelCommands {
  CLI::App* derive = nullptr;
  CLI::App* simulate = nullptr;
  CLI::App* check = nullptr;
  CLI::App* models = nullptr;
  CLI::App* report = nullptr;

  std::string model;
  std::string method = "lagrange";
  std::string format = "text";
  std::string form = "textbook";
  bool standalone = false;
  std::string output;
  std::vector<std::string> sets;
  double t_end = 0, output_step = 0, rtol = 0;
  std::string integrator;
  std::string model_name;
  bool reduced = false;
  bool timings = false;  // derive, check: each phase's time on standard error
  // simulate: the old start — every value as given, then projected onto the constraints
  bool project = false;
  bool poses =
      false;  // simulate: each body's centre and Euler parameters, each particle's position
  std::string evaluation = "native";  // simulate: native (when a compiler is present) or tape
  std::vector<std::string> at;  // report: NAME=VALUE of the operating point to linearise about
};

void add_model_commands(CLI::App& app, ModelCommands& commands);

// `unidyn derive`'s output for the model (its options in `c`: method, format, form, standalone,
// reduced). Throws std::invalid_argument for options that do not go together.
void write_derivation(std::ostream& out, const ModelCommands& c, const CommandModel& model);

// Runs whichever of the commands was parsed; returns the exit status (0 success, 1 the run failed,
// 2 bad input), or -1 when none of them was.
int run_model_commands(const ModelCommands& commands);

}  // namespace unidyn::cli
