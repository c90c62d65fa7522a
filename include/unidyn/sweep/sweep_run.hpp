// Running a chunk of a sweep (`unidyn sweep run MANIFEST --rows A:B`) and gathering the results
// (`unidyn sweep gather`). Each run's result is one file, <dir>/run-<index>.csv: its index, seed
// and values, whether it succeeded, its rows and events, the energy's relative drift (empty where
// the energy is not conserved), why it failed, with --modes-at the stability and eigenvalues at
// the operating point, and the last row of its simulation ("final.<column>"); with the manifest's
// times, a second header (run, then the columns) and its rows at those times. A result is written
// whole or not at all (a temporary file, synced, renamed into place), and a run whose result is
// there is not run again: a chunk can be run twice, by two workers at once, or after a crash, and
// the results are the same files. The model is compiled once per chunk (its parameters are
// inputs of the code), native code shared through its cache.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "unidyn/sweep/manifest.hpp"

namespace unidyn {

// Where the results of a manifest go by default: MANIFEST.runs beside it.
std::filesystem::path default_results_directory(const std::string& manifest_path);

// The result file of a run.
std::filesystem::path result_path(const std::filesystem::path& directory, std::size_t index);

struct ChunkReport {
  // made (of them: failed runs, and results there that were not this run's and were made again),
  // and kept
  std::size_t done = 0, skipped = 0, failed = 0, remade = 0;
};

// Runs the manifest's runs [first, last) into `directory` (made when missing), one line per run
// on `log`. Each result ends with a stamp of the manifest's SHA-256, the run's index and seed: a
// result that is whole and made for this run is kept, anything else there (from before a re-plan,
// copied, cut short) is made again. Throws std::invalid_argument when the model file changed
// since the plan or a range is outside the manifest.
ChunkReport run_sweep_rows(const SweepManifest& manifest, const std::string& manifest_sha256,
                           std::size_t first, std::size_t last,
                           const std::filesystem::path& directory, std::ostream& log);

// The runs gather_sweep left out: no result file, or one that is not this run's (stale).
struct GatherReport {
  std::vector<std::size_t> missing, stale;
};

// Which table gather makes: one row per run (its outcome and last row), or one per run and kept
// time (its index, seed, values as set.<name>, ok, then its row at that time: a tidy table).
enum class GatherTable { final_rows, rows_at_times };

// The results as one table on `out`: a comment line with the model, the manifest's SHA-256 and
// the count of runs, the header, then the runs' rows in their order, the missing ones left out.
// Nothing is written when a result is stale: a table is never made from results of another
// manifest or run. Throws std::invalid_argument for rows at times of a manifest without times,
// or a table over 1 GiB.
GatherReport gather_sweep(const SweepManifest& manifest, const std::string& manifest_sha256,
                          const std::filesystem::path& directory, std::ostream& out,
                          GatherTable table = GatherTable::final_rows);

// The rows [first, last) of task `task` when the runs are cut into chunks of `chunk` (the last one
// shorter). Throws std::invalid_argument for a chunk of 0 or a task past the runs.
std::pair<std::size_t, std::size_t> task_rows(std::size_t runs, std::size_t chunk,
                                              std::size_t task);

// A launcher: a Slurm job array script (one task per chunk of `chunk` runs, SLURM_ARRAY_TASK_ID its
// task) or a GNU parallel script, each task `COMMAND sweep run MANIFEST --chunk N --task I`.
std::string slurm_script(const std::string& command, const std::string& manifest_path,
                         std::size_t runs, std::size_t chunk);
std::string parallel_script(const std::string& command, const std::string& manifest_path,
                            std::size_t runs, std::size_t chunk);

}  // namespace unidyn
