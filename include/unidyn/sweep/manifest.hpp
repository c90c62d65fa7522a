// A sweep's manifest (`unidyn sweep plan`): one model, the simulate options every run shares, and
// one row per run with its own values of the names swept (parameters, coordinates q, rates der(q))
// and its own seed. Runs on a grid (NAME=FROM:TO:COUNT, every combination, the first name slowest)
// and/or drawn at random (NAME=U(A,B) uniform, NAME=N(MEAN,SD) normal; --samples per grid point)
// from one seed: the same plan gives the same manifest, byte for byte. Each run's seed is
// SplitMix64 of the plan's seed and the run's index, for whatever later draws per run.
//
// The manifest is a YAML file (it is read back with the model language's reader), with the model
// as an absolute path and the SHA-256 of its bytes: a run refuses a model that changed since.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "unidyn/integrate/simulation.hpp"

namespace unidyn {

// The simulate options of every run (0 or "": the model's own `simulate:`).
using SweepOptions = SimulationOverrides;

struct SweepRun {
  std::size_t index = 0;
  std::uint64_t seed = 0;
  std::vector<double> values;  // one per name
};

struct SweepManifest {
  std::string model;         // absolute path of the model file
  std::string model_sha256;  // of its bytes when planned
  SweepOptions options;
  std::vector<std::string> names;
  std::uint64_t seed = 0;
  std::vector<SweepRun> runs;
  // the runs in the file (a manifest read for a range of them holds those in `runs`)
  std::size_t run_count = 0;
  // NAME=VALUE of an operating point (as `unidyn modes --at`): when given, each run also reports
  // the eigenvalues and stability of its linearisation there, with the run's parameters.
  std::vector<std::string> modes_at;
  // times whose rows each run keeps beside its last (`sweep gather --times`), increasing; each a
  // row's time — the output step's multiples from the start, or t_end: nothing is interpolated
  std::vector<double> times;
  // read_manifest: the SHA-256 of the file's bytes it read (one open file for both, so the runs
  // and the digest their results are stamped with cannot come from two versions of the file)
  std::string sha256;
};

// NAME=FROM:TO:COUNT: COUNT values evenly from FROM to TO (both included; COUNT 1: FROM).
struct GridAxis {
  std::string name;
  double from = 0, to = 0;
  std::size_t count = 0;
};
// NAME=U(A,B) or NAME=N(MEAN,SD).
struct RandomAxis {
  std::string name;
  bool normal = false;
  double a = 0, b = 0;
};

// Throw std::invalid_argument naming the text and the form expected.
GridAxis parse_grid_axis(const std::string& text);
RandomAxis parse_random_axis(const std::string& text);

// The runs: every grid point (one when there is no grid) times `samples` random draws (one when
// nothing is random). Throws std::invalid_argument for a name given twice or a plan of more than
// 10^7 runs.
SweepManifest plan_sweep(const std::string& model_path, const std::string& model_bytes,
                         const SweepOptions& options, const std::vector<GridAxis>& grid,
                         const std::vector<RandomAxis>& random, std::size_t samples,
                         std::uint64_t seed);

// The manifest as its file's text (numbers in their shortest exact form).
std::string manifest_text(const SweepManifest& manifest);

// The runs a manifest is read for: those numbered first to last − 1 (a task's).
struct RunRange {
  std::size_t first = 0;
  std::size_t last = SIZE_MAX;
};

// A manifest file read back: its header, and its runs in `keep` (every run is checked for its
// place and counted in run_count; only those kept are parsed and held, so a task of a 10^7-run
// manifest needs the memory of its own runs). Throws ModelError (file:line:column) when it is
// not one: each run is one line `  - [index, seed, values...]`, as manifest_text writes it.
SweepManifest read_manifest(const std::string& path, RunRange keep = {});

// The most times a run keeps rows at.
inline constexpr std::size_t kMostKeptTimes = 1000;

// Throws std::invalid_argument unless `times` are at most kMostKeptTimes, increasing, and each
// the time of a row of a run from t0 to t_end with rows every output_step: t0 + k output_step
// (to 1e-9 of a step) or t_end.
void check_kept_times(const std::vector<double>& times, double t0, double t_end,
                      double output_step);

// SplitMix64 of the plan's seed and a run's index.
std::uint64_t run_seed(std::uint64_t seed, std::size_t index);

}  // namespace unidyn
