// What `unidyn sweep plan|run|gather|emit` do, as library functions over plain options: ensembles
// of runs of one model (sweep/manifest.hpp, sweep/sweep_run.hpp) that Slurm job arrays, GNU
// parallel or HTCondor drive. Bad input throws std::invalid_argument.
#pragma once

#include <cstddef>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace unidyn::commands {

struct SweepOptions {
  std::string model;    // plan: the model; the others: the manifest
  std::string output;   // plan: the manifest; gather: the table; emit: the script
  std::string results;  // run, gather: the results' directory (default MANIFEST.runs)
  std::vector<std::string> grid, random;  // plan: NAME=FROM:TO:COUNT, NAME=U(A,B) or N(MEAN,SD)
  std::vector<std::string> modes_at;      // plan: NAME=VALUE of an operating point
  std::vector<double> times;              // plan: the times whose rows each run keeps
  bool rows_at_times = false;             // gather: the table of the rows at the times
  std::size_t samples = 1;                // plan: random draws per grid point
  std::uint64_t seed = 1;                 // plan: the draws' seed
  double t_end = 0, output_step = 0, rtol = 0;
  std::string method;
  std::string rows;  // run: A:B
  std::size_t chunk = 0, task = 0;
  bool slurm = false, parallel = false;  // emit: which launcher
};

// `sweep plan`: the manifest written (c.output, default MODEL.sweep.yaml); a line saying so to out.
void plan_sweep_file(const SweepOptions& c, std::ostream& out);

// `sweep run`: the chunk's runs made (the done ones skipped), their progress and a line to out.
void run_sweep_chunk(const SweepOptions& c, std::ostream& out);

// `sweep gather`: the table of the results in the runs' order (or of their rows at the manifest's
// times) (to c.output, else to out), what is
// missing or stale on standard error; whether every run had its result (a stale one: no table).
bool gather_sweep_table(const SweepOptions& c, std::ostream& out);

// `sweep emit`: a launcher script (to c.output, made executable, else to out) that runs `command`
// (the unidyn executable) on the manifest's chunks.
void emit_sweep_script(const SweepOptions& c, const std::string& command, std::ostream& out);

}  // namespace unidyn::commands
