// Running a chunk of a sweep, gathering its results, and the launchers (sweep/sweep_run.hpp).
#include "unidyn/sweep/sweep_run.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "unidyn/analysis/floquet.hpp"
#include "unidyn/analysis/linearization.hpp"
#include "unidyn/analysis/modes.hpp"
#include "unidyn/analysis/time_dependence.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/io/atomic_file.hpp"
#include "unidyn/io/csv.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/digest.hpp"
#include "unidyn/numeric/shell_quoting.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn {
namespace {

namespace fs = std::filesystem;

// The header of a result file: the run, its values, its outcome, then its last row.
std::string result_header(const SweepManifest& m, const std::vector<std::string>& columns) {
  std::string out = "run,seed";
  for (const auto& name : m.names) out += "," + csv_field(name);
  out += ",ok,rows,events,energy_drift,message";
  if (!m.modes_at.empty()) out += ",stability,eigenvalues";
  for (const auto& c : columns) out += "," + csv_field("final." + c);
  return out + "\n";
}

// The modes of the manifest's operating point with a run's parameters: its verdict and
// eigenvalues ("a±bi" each, separated by spaces), or why there are none.
// A driven system's point (equations that depend on t periodically) gets its Floquet verdict and
// multipliers ("multipliers: μ1 μ2 ..."), over the drive's period at the run's parameters.
struct ModesAt {
  const System& system;
  const CompiledSystem& compiled;  // of Lagrange's equations, as the analysis commands use
  std::vector<GivenValue> given;
  TimeDependence dependence;
};

// The Floquet verdict and multipliers of a periodic motion, as modes_fields writes them.
std::string floquet_fields(const ModesAt& at, const OperatingPoint& point,
                           const DrivePeriod& period) {
  const FloquetAnalysis floquet =
      analyse_floquet(linearize_periodic(at.system, at.compiled, point, period));
  std::string values = "multipliers:";
  for (const FloquetMultiplier& m : floquet.multipliers) {
    const std::complex<double> mu = m.multiplier;
    values += fmt::format(" {:.6g}", mu.real());
    if (mu.imag() != 0.0)
      values += fmt::format("{}{:.6g}i", mu.imag() < 0 ? "-" : "+", std::abs(mu.imag()));
  }
  return "," + csv_field(to_string(floquet.verdict)) + "," + csv_field(values);
}
std::string modes_fields(const ModesAt& at,
                         const std::vector<std::pair<std::string, double>>& sets) {
  try {
    // the operating point's values are the manifest's; a run's q and der(q) are its start's
    std::vector<std::pair<std::string, double>> parameters;
    for (const auto& [name, value] : sets) {
      if (at.system.find_parameter(name)) parameters.emplace_back(name, value);
    }
    const std::vector<double> p = initial_state(at.system, parameters).parameters;
    const OperatingPoint point = operating_point(at.system, at.compiled, at.given, p);
    if (at.dependence.depends) {
      if (const auto period = drive_period(at.system, at.compiled, at.dependence, p)) {
        return floquet_fields(at, point, *period);
      }
    }
    const ModeAnalysis modes = analyse_modes(linearize(at.system, at.compiled, point));
    std::string values;
    for (const Mode& mode : modes.modes) {
      values += (values.empty() ? "" : " ") + eigenvalue_text(mode, modes.tolerance);
    }
    return "," + csv_field(to_string(modes.verdict)) + "," + csv_field(values);
  } catch (const std::exception& e) {
    return ",none," + csv_field(e.what());
  }
}

// The header of a result's rows at the manifest's times: the run, then the rows' columns.
std::string rows_at_header(const std::vector<std::string>& columns) {
  std::string out = "run";
  for (const auto& c : columns) out += "," + csv_field(c);
  return out + "\n";
}

// A run's rows at the manifest's times (increasing): the first row at each, to 1e-9 of the span
// (as the output grid makes them); a time the run did not reach (it failed before) has none.
class RowsAtTimes {
 public:
  RowsAtTimes(const std::vector<double>& times, std::size_t index, double span)
      : times_(times), index_(index), tolerance_(1e-9 * std::max(1.0, std::abs(span))) {}
  void offer(const std::vector<double>& row) {
    while (next_ < times_.size() && row[0] > times_[next_] + tolerance_) ++next_;
    if (next_ == times_.size() || std::abs(row[0] - times_[next_]) > tolerance_) return;
    text_ += std::to_string(index_);
    for (const double v : row) text_ += fmt::format(",{}", v);
    text_ += "\n";
    ++next_;
  }
  const std::string& text() const { return text_; }

 private:
  const std::vector<double>& times_;
  std::size_t index_, next_ = 0;
  double tolerance_;
  std::string text_;
};

// One run: its start from the manifest's values, the simulation, its result row (and its rows at
// the manifest's times).
struct RunRow {
  std::string text, rows_at;
  bool ok = false;
};
RunRow run_one(const SweepManifest& m, const SweepRun& run, const System& system,
               const CompiledSystem& compiled, std::size_t columns, const ModesAt* modes) {
  std::vector<std::pair<std::string, double>> sets;
  for (std::size_t k = 0; k < m.names.size(); ++k) sets.emplace_back(m.names[k], run.values[k]);
  std::string row = std::to_string(run.index) + "," + std::to_string(run.seed);
  for (const double v : run.values) row += fmt::format(",{}", v);
  std::vector<double> last;
  SimulationSummary s;
  const SimulationOptions options = simulation_options(system.simulate, m.options);
  RowsAtTimes at(m.times, run.index, options.t_end);
  try {
    SimulationStart start = initial_state(system, sets);
    complete_initial_state(system, compiled, start);
    s = simulate(system, compiled, start, options, [&](const std::vector<double>& values) {
      last = values;
      at.offer(values);
    });
  } catch (const std::exception& e) {
    // a start that cannot be made (the constraints, gimbal lock) is this run's failure
    s.ok = false;
    s.message = e.what();
  }
  row += fmt::format(",{},{},{},{},{}", s.ok ? 1 : 0, s.rows, s.phases.size(),
                     s.has_energy && s.energy_not_conserved.empty()
                         ? fmt::format("{}", s.energy_relative_drift)
                         : "",
                     csv_field(s.message));
  if (modes) row += modes_fields(*modes, sets);
  for (std::size_t c = 0; c < columns; ++c) {
    row += c < last.size() ? fmt::format(",{}", last[c]) : ",";
  }
  return {row + "\n", at.text(), s.ok};
}

// The last line of a result file: the manifest (its SHA-256) and the run it was made for,
// written with the rest (atomically), so that a file whole and made for this run ends with it.
std::string result_stamp(const std::string& manifest_sha256, const SweepRun& run) {
  return fmt::format("# unidyn sweep result of manifest sha256 {}, run {}, seed {}\n",
                     manifest_sha256, run.index, run.seed);
}

// A result file's parts: the header and row of its run, and (with the manifest's times) the
// header and rows at those times, each ending with its newline.
struct ResultParts {
  std::string header, row, rows_at_header, rows_at;
};

// The parts of the result file at `path` when it is whole and was made for this run of this
// manifest: the header, the row starting with the run's index and seed, with times the header of
// the rows at them and those rows (each starting with the run's index), then the stamp. None when
// it is not (missing, cut short, copied from another run or from before a re-plan).
std::optional<ResultParts> valid_result(const fs::path& path, const SweepManifest& m,
                                        const std::string& manifest_sha256, const SweepRun& run) {
  std::error_code error;
  const auto size = fs::file_size(path, error);
  // a result is one row of numbers, and at most kMostKeptTimes more
  if (error || size > (m.times.empty() ? 1u << 20 : 1u << 28)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string stamp = result_stamp(manifest_sha256, run);
  // the stamp on a line of its own: a row cut short of its newline is not whole
  const std::size_t body = text.size() - stamp.size();
  if (!text.ends_with(stamp) || body == 0 || text[body - 1] != '\n') return std::nullopt;
  std::vector<std::string> lines;  // each with its newline
  for (std::size_t at = 0, end = 0; at < body; at = end + 1) {
    end = text.find('\n', at);
    lines.push_back(text.substr(at, end - at + 1));
  }
  const std::string run_start = fmt::format("{},", run.index);
  const bool with_times = !m.times.empty();
  if (lines.size() < (with_times ? 3u : 2u) || (!with_times && lines.size() != 2) ||
      !lines[1].starts_with(run_start + fmt::format("{},", run.seed)) ||
      (with_times && !lines[2].starts_with("run,"))) {
    return std::nullopt;
  }
  ResultParts parts{lines[0], lines[1], with_times ? lines[2] : "", ""};
  for (std::size_t k = 3; k < lines.size(); ++k) {
    if (!lines[k].starts_with(run_start)) return std::nullopt;
    parts.rows_at += lines[k];
  }
  return parts;
}

}  // namespace

fs::path default_results_directory(const std::string& manifest_path) {
  return fs::path(manifest_path + ".runs");
}

fs::path result_path(const fs::path& directory, std::size_t index) {
  return directory / fmt::format("run-{:07}.csv", index);
}

ChunkReport run_sweep_rows(const SweepManifest& m, const std::string& manifest_sha256,
                           std::size_t first, std::size_t last, const fs::path& directory,
                           std::ostream& log) {
  if (first > last || last > m.run_count) {
    throw std::invalid_argument(
        fmt::format("--rows {}:{} is outside the manifest's {} runs", first, last, m.run_count));
  }
  // the runs held (those a manifest was read for): run k at k − held_from
  const std::size_t held_from = m.runs.empty() ? first : m.runs.front().index;
  if (first < held_from || last - held_from > m.runs.size()) {
    throw std::logic_error("run_sweep_rows: the manifest was not read for these runs");
  }
  // the model as planned, compiled once for the chunk (native code through its cache)
  const std::string text = read_model_text(m.model);
  if (sha256_hex(text) != m.model_sha256) {
    throw std::invalid_argument(m.model +
                                " changed since the sweep was planned (its SHA-256 is "
                                "not the manifest's): plan the sweep again");
  }
  const System system = parse_model(text, m.model);
  CompileOptions compile;
  compile.native = true;
  compile.native_options.key = "full\n" + model_code_text(text, m.model);
  const CompiledSystem compiled(system, kane_equations(system), compile);
  const std::vector<std::string> columns = simulation_columns(system);
  const std::string header = result_header(m, columns);
  const std::string at_header = m.times.empty() ? "" : rows_at_header(columns);
  // the operating point's modes, when asked: Lagrange's equations on the tape, as `unidyn modes`
  std::optional<CompiledSystem> lagrange;
  std::optional<ModesAt> modes;
  if (!m.modes_at.empty()) {
    const EquationsOfMotion equations = lagrange_equations(system);
    lagrange.emplace(system, equations);
    modes.emplace(ModesAt{system, *lagrange, parse_given_values(system, m.modes_at),
                          time_dependence(system, equations)});
  }
  fs::create_directories(directory);
  ChunkReport report;
  for (std::size_t k = first; k < last; ++k) {
    const fs::path path = result_path(directory, k);
    // a result made for this run of this manifest is kept; anything else there is made again
    const SweepRun& run = m.runs[k - held_from];
    if (valid_result(path, m, manifest_sha256, run)) {
      ++report.skipped;
      continue;
    }
    const bool stale = fs::exists(path);
    const RunRow row = run_one(m, run, system, compiled, columns.size(), modes ? &*modes : nullptr);
    write_atomically(
        path, header + row.text + at_header + row.rows_at + result_stamp(manifest_sha256, run));
    ++report.done;
    if (stale) {
      ++report.remade;
      log << "run " << k << ": the result there was not this manifest's or not whole: made again\n";
    }
    if (!row.ok) ++report.failed;
    log << "run " << k << (row.ok ? "" : " (FAILED)") << " written to " << path.string() << "\n";
  }
  return report;
}

namespace {

// The largest table gather makes (it is held whole until every result is known to be valid).
constexpr std::size_t kMostTableBytes = std::size_t{1} << 30;

// The first `count` fields of a result row (numbers: no field before the message has a comma),
// with the comma after them.
std::string leading_fields(const std::string& row, std::size_t count) {
  std::size_t end = 0;
  for (std::size_t k = 0; k < count && end != std::string::npos; ++k) end = row.find(',', end + 1);
  return row.substr(0, end == std::string::npos ? row.size() : end + 1);
}

// The tidy table's header: the run, its seed and values (set.<name>), ok, the rows' columns.
std::string rows_at_table_header(const SweepManifest& m, const std::string& rows_at_header) {
  std::string out = "run,seed";
  for (const auto& name : m.names) out += "," + csv_field("set." + name);
  return out + ",ok" + rows_at_header.substr(3);
}

// A run's lines of the tidy table: its index, seed, values and ok, then each of its rows.
std::string rows_at_lines(const SweepManifest& m, const ResultParts& result) {
  const std::string run = leading_fields(result.row, m.names.size() + 3);
  std::string out;
  for (std::size_t at = 0, end = 0; at < result.rows_at.size(); at = end + 1) {
    end = result.rows_at.find('\n', at);
    const std::size_t comma = result.rows_at.find(',', at);
    out += run + result.rows_at.substr(comma + 1, end - comma);
  }
  return out;
}

}  // namespace

GatherReport gather_sweep(const SweepManifest& m, const std::string& manifest_sha256,
                          const fs::path& directory, std::ostream& out, GatherTable table) {
  if (table == GatherTable::rows_at_times && m.times.empty()) {
    throw std::invalid_argument(
        "--times: the manifest keeps no rows at times (plan the sweep with --times T1,T2,...)");
  }
  GatherReport report;
  std::string header, rows;
  for (const SweepRun& run : m.runs) {
    const fs::path path = result_path(directory, run.index);
    const auto result = valid_result(path, m, manifest_sha256, run);
    if (!result) {
      (fs::exists(path) ? report.stale : report.missing).push_back(run.index);
      continue;
    }
    if (table == GatherTable::final_rows) {
      if (header.empty()) header = result->header;
      rows += result->row;
    } else {
      if (header.empty()) header = rows_at_table_header(m, result->rows_at_header);
      rows += rows_at_lines(m, *result);
    }
    if (rows.size() > kMostTableBytes) {
      throw std::invalid_argument(fmt::format(
          "the table would be over {} MiB: gather fewer times, or read the result files",
          kMostTableBytes >> 20));
    }
  }
  // no table from results that are not this manifest's
  if (!report.stale.empty()) return report;
  out << "# unidyn sweep of " << m.model << ", manifest sha256 " << manifest_sha256 << ", "
      << m.runs.size() << " runs" << (table == GatherTable::final_rows ? "" : ", rows at times")
      << "\n"
      << header << rows;
  return report;
}

std::pair<std::size_t, std::size_t> task_rows(std::size_t runs, std::size_t chunk,
                                              std::size_t task) {
  if (chunk == 0) throw std::invalid_argument("--chunk must be at least 1");
  const std::size_t first = task * chunk;
  if (first >= runs) {
    throw std::invalid_argument(
        fmt::format("task {} of chunks of {} is past the manifest's {} runs", task, chunk, runs));
  }
  return {first, std::min(first + chunk, runs)};
}

namespace {

// The lines every launcher has after its #! and #SBATCH lines: what it is (the manifest's path made
// printable: a newline in it cannot end the comment), and the two paths as shell variables, each
// quoted as one word — the commands below only ever expand them inside double quotes, so nothing in
// a path is run (a directory named inj'$(touch PWNED)' is a name).
std::string launcher_preamble(const std::string& what, const std::string& command,
                              const std::string& manifest_path) {
  return "# " + what + "\n# Then: unidyn sweep gather " + printable(manifest_path) +
         "\nset -euo pipefail\nexport UNIDYN=" + shell_quoted(command) +
         "\nexport MANIFEST=" + shell_quoted(manifest_path) + "\n";
}

}  // namespace

std::string slurm_script(const std::string& command, const std::string& manifest_path,
                         std::size_t runs, std::size_t chunk) {
  const std::size_t tasks = (runs + chunk - 1) / chunk;
  return fmt::format(
             "#!/bin/bash\n"
             "#SBATCH --job-name=unidyn-sweep\n"
             "#SBATCH --array=0-{last}\n"
             "#SBATCH --ntasks=1\n"
             "#SBATCH --cpus-per-task=1\n",
             fmt::arg("last", tasks == 0 ? 0 : tasks - 1)) +
         launcher_preamble(
             fmt::format("A Slurm job array of the sweep: {} runs in {} tasks of up to {}. Submit "
                         "with `sbatch` from a directory every node sees; a task run again "
                         "(requeued, or by hand) skips the runs it finds done.",
                         runs, tasks, chunk),
             command, manifest_path) +
         fmt::format(
             "\"$UNIDYN\" sweep run \"$MANIFEST\" --chunk {} --task \"$SLURM_ARRAY_TASK_ID\"\n",
             chunk);
}

std::string parallel_script(const std::string& command, const std::string& manifest_path,
                            std::size_t runs, std::size_t chunk) {
  const std::size_t tasks = (runs + chunk - 1) / chunk;
  // GNU parallel runs its command through a shell: the variables are expanded there, inside
  // double quotes, never spliced into its text
  return "#!/bin/bash\n" +
         launcher_preamble(fmt::format("The sweep by GNU parallel: {} runs in {} tasks of up to "
                                       "{}, one per core; run it again to finish what an "
                                       "interrupted one left.",
                                       runs, tasks, chunk),
                           command, manifest_path) +
         fmt::format(
             "seq 0 {} | parallel --halt now,fail=1 '\"$UNIDYN\" sweep run \"$MANIFEST\" --chunk "
             "{} --task {{}}'\n",
             tasks == 0 ? 0 : tasks - 1, chunk);
}

}  // namespace unidyn
