// The sweep commands: plan, run chunks, gather, launchers (sweep/manifest.hpp,
// sweep/sweep_run.hpp).
#include "unidyn/commands/sweep_commands.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "unidyn/analysis/operating_point.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/io/atomic_file.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/sweep/manifest.hpp"
#include "unidyn/sweep/sweep_run.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::commands {
namespace {

namespace fs = std::filesystem;

// A file written whole or not at all, or bad input naming it.
void write_text(const std::string& path, const std::string& text) {
  try {
    write_atomically(path, text);
  } catch (const std::runtime_error&) {
    throw std::invalid_argument("cannot write " + printable(path));
  }
}

// --rows A:B (either side may be left out: from the first, to the last run).
std::pair<std::size_t, std::size_t> parse_rows(const std::string& text, std::size_t runs) {
  const std::size_t colon = text.find(':');
  const auto bad = [&] {
    return std::invalid_argument("--rows " + text + ": expected A:B (run indices, B excluded)");
  };
  if (colon == std::string::npos) throw bad();
  const auto index = [&](std::string_view part, std::size_t otherwise) {
    if (part.empty()) return otherwise;
    std::size_t value = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), value);
    if (error != std::errc() || end != part.data() + part.size()) throw bad();
    return value;
  };
  return {index(std::string_view(text).substr(0, colon), 0),
          index(std::string_view(text).substr(colon + 1), runs)};
}

// --results, else MANIFEST.runs.
fs::path results_directory(const SweepOptions& c) {
  return c.results.empty() ? default_results_directory(c.model) : fs::path(c.results);
}

}  // namespace

void plan_sweep_file(const SweepOptions& c, std::ostream& out) {
  const LoadedModel model = load_named_model(c.model);
  std::vector<GridAxis> grid;
  std::vector<RandomAxis> random;
  for (const auto& text : c.grid) grid.push_back(parse_grid_axis(text));
  for (const auto& text : c.random) random.push_back(parse_random_axis(text));
  if (grid.empty() && random.empty()) {
    throw std::invalid_argument("a sweep needs --grid NAME=FROM:TO:COUNT or --random NAME=U(A,B)");
  }
  SweepManifest manifest =
      plan_sweep(fs::absolute(model.path).lexically_normal().string(), model.text,
                 {c.t_end, c.output_step, c.rtol, c.method}, grid, random, c.samples, c.seed);
  // every name is one a run can set (a parameter, q or der(q)), the options are a run's options,
  // and the first run's start can be made: checked now rather than on every node
  std::vector<std::pair<std::string, double>> first;
  for (std::size_t k = 0; k < manifest.names.size(); ++k) {
    first.emplace_back(manifest.names[k], manifest.runs.front().values[k]);
  }
  const SimulationStart start = initial_state(model.system, first);
  const SimulationOptions options = simulation_options(model.system.simulate, manifest.options);
  check_kept_times(c.times, start.t0, options.t_end, options.output_step);
  manifest.times = c.times;
  manifest.modes_at = c.modes_at;
  parse_given_values(model.system, manifest.modes_at);
  const std::string path =
      c.output.empty() ? fs::path(model.path).stem().string() + ".sweep.yaml" : c.output;
  write_text(path, manifest_text(manifest));
  out << fmt::format("sweep of {}: {} runs of {} planned in {}\n", model.system.name,
                     manifest.runs.size(), fmt::join(manifest.names, ", "), printable(path));
}

void run_sweep_chunk(const SweepOptions& c, std::ostream& out) {
  if (!c.rows.empty() && c.chunk > 0) throw std::invalid_argument("give --rows or --chunk/--task");
  // only the task's runs are read and held; the range is checked against the count read
  constexpr std::size_t all = SIZE_MAX;
  const std::size_t task_first = c.chunk > 0 && c.task <= all / c.chunk ? c.task * c.chunk : all;
  const auto [wanted_first, wanted_last] =
      c.chunk > 0      ? std::pair{task_first, task_first + std::min(c.chunk, all - task_first)}
      : c.rows.empty() ? std::pair<std::size_t, std::size_t>{0, all}
                       : parse_rows(c.rows, all);
  const SweepManifest manifest = read_manifest(c.model, {wanted_first, wanted_last});
  const auto [first, last] =
      c.chunk > 0 ? task_rows(manifest.run_count, c.chunk, c.task)
                  : std::pair{wanted_first, wanted_last == all ? manifest.run_count : wanted_last};
  const fs::path directory = results_directory(c);
  const ChunkReport report = run_sweep_rows(manifest, manifest.sha256, first, last, directory, out);
  out << fmt::format(
      "runs {} to {}: {} made ({} of them failed, {} made again over a stale result), {} "
      "already done, in {}\n",
      first, last, report.done, report.failed, report.remade, report.skipped,
      printable(directory.string()));
}

bool gather_sweep_table(const SweepOptions& c, std::ostream& out) {
  const SweepManifest manifest = read_manifest(c.model);
  const fs::path directory = results_directory(c);
  std::ostringstream table;
  const GatherReport report =
      gather_sweep(manifest, manifest.sha256, directory, table,
                   c.rows_at_times ? GatherTable::rows_at_times : GatherTable::final_rows);
  // at most ten run numbers, then "..."
  const auto some = [](const std::vector<std::size_t>& runs) {
    const std::vector<std::size_t> shown(
        runs.begin(), runs.begin() + static_cast<long>(std::min<std::size_t>(runs.size(), 10)));
    return fmt::format("{}{}", fmt::join(shown, ", "), runs.size() > 10 ? ", ..." : "");
  };
  if (!report.stale.empty()) {
    fmt::print(stderr,
               "{} of {} results are not this manifest's or not whole (a re-plan, a copy, a cut "
               "file): {}; no table written. `unidyn sweep run` makes them again\n",
               report.stale.size(), manifest.runs.size(), some(report.stale));
    return false;
  }
  if (c.output.empty()) {
    out << table.str();
  } else {
    write_text(c.output, table.str());
  }
  if (report.missing.empty()) {
    fmt::print(stderr, "gathered all {} runs\n", manifest.runs.size());
    return true;
  }
  fmt::print(stderr, "{} of {} runs have no result yet: {}\n", report.missing.size(),
             manifest.runs.size(), some(report.missing));
  return false;
}

void emit_sweep_script(const SweepOptions& c, const std::string& command, std::ostream& out) {
  const SweepManifest manifest = read_manifest(c.model, {0, 0});  // the count alone
  if (c.slurm == c.parallel) throw std::invalid_argument("sweep emit: give --slurm or --parallel");
  const std::size_t chunk = c.chunk > 0 ? c.chunk : 10;
  const std::string manifest_path = fs::absolute(c.model).lexically_normal().string();
  const std::string script =
      c.slurm ? slurm_script(command, manifest_path, manifest.run_count, chunk)
              : parallel_script(command, manifest_path, manifest.run_count, chunk);
  if (c.output.empty()) {
    out << script;
  } else {
    write_text(c.output, script);
    fs::permissions(c.output, fs::perms::owner_exec | fs::perms::group_exec, fs::perm_options::add);
  }
}

}  // namespace unidyn::commands
