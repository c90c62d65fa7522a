// `unidyn sweep plan|run|gather|emit`: ensembles of runs of one model (sweep/manifest.hpp,
// sweep/sweep_run.hpp) that Slurm job arrays, GNU parallel or HTCondor drive.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace unidyn::cli {

struct SweepCommand {
  CLI::App* sweep = nullptr;
  CLI::App* plan = nullptr;
  CLI::App* run = nullptr;
  CLI::App* gather = nullptr;
  CLI::App* emit = nullptr;

  std::string model;    // plan: the model; the others: the manifest
  std::string output;   // plan: the manifest; gather: the table; emit: the script
  std::string results;  // run, gather: the results' directory (default MANIFEST.runs)
  std::vector<std::string> grid, random;
  std::vector<std::string> modes_at;  // plan: NAME=VALUE of an operating point
  std::size_t samples = 1;
  std::uint64_t seed = 1;
  double t_end = 0, output_step = 0, rtol = 0;
  std::string method;
  std::string rows;  // run: A:B
  std::size_t chunk = 0, task = 0;
  bool slurm = false, parallel = false;
};

void add_sweep_command(CLI::App& app, SweepCommand& command);
// The exit status: 0, 1 (gather: runs missing), 2 (bad input throws std::invalid_argument).
int run_sweep_command(const SweepCommand& command);

}  // namespace unidyn::cli
