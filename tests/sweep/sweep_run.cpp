// Running a sweep's chunks (sweep/sweep_run.hpp): each result the same as the run made directly
// with its values, a chunk run again or overlapping another skipped and unchanged, a failed run
// recorded, a model changed since the plan refused, the table in the runs' order with the
// missing ones named, and the tasks' rows of the launchers.
#include "unidyn/sweep/sweep_run.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/model_run.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

namespace fs = std::filesystem;

std::string read(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A scratch copy of a bundled model and a plan of it.
struct Sweep {
  fs::path dir;
  std::string model;
  SweepManifest manifest;

  explicit Sweep(const std::string& name, const std::vector<std::string>& grid, double t_end) {
    dir = fs::path(testing::TempDir()) / ("sweep_" + name + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    model = (dir / (name + ".yaml")).string();
    fs::copy_file(test::model_path(name), model);
    std::vector<GridAxis> axes;
    for (const auto& text : grid) axes.push_back(parse_grid_axis(text));
    manifest = plan_sweep(model, read(model), {t_end, 0, 0, ""}, axes, {}, 1, 1);
  }
  ~Sweep() { fs::remove_all(dir); }
};

TEST(SweepRun, EachResultIsTheRunMadeDirectly) {
  Sweep s("double-pendulum", {"theta1=0.2:0.8:4", "m2=1:2:2"}, 1.0);
  std::ostringstream log;
  const ChunkReport report = run_sweep_rows(s.manifest, "h", 0, 8, s.dir / "runs", log);
  EXPECT_EQ(report.done, 8u);
  EXPECT_EQ(report.failed, 0u);
  // run 5: theta1 = 0.2 + 2 (0.6/3) (0.6000000000000001), m2 = 2, simulated here without the sweep
  const std::vector<double>& values = s.manifest.runs[5].values;
  const System system = load_model(s.model);
  const CompiledSystem compiled(system, kane_equations(system));
  SimulationStart start = initial_state(system, {{"theta1", values[0]}, {"m2", values[1]}});
  complete_initial_state(system, compiled, start);
  std::vector<double> last;
  simulate(system, compiled, start, simulation_options(system.simulate, s.manifest.options),
           [&](const std::vector<double>& row) { last = row; });
  const std::string result = read(result_path(s.dir / "runs", 5));
  const std::string expected =
      fmt::format("5,{},{},{},1,101,0,", s.manifest.runs[5].seed, values[0], values[1]);
  EXPECT_EQ(result.find(expected), result.find('\n') + 1) << result;
  std::string tail;
  for (const double v : last) tail += fmt::format(",{}", v);
  const std::string stamp = fmt::format(
      "# unidyn sweep result of manifest sha256 h, run 5, seed {}\n", s.manifest.runs[5].seed);
  EXPECT_EQ(result.substr(result.size() - stamp.size() - tail.size() - 1), tail + "\n" + stamp)
      << result;
}

// The text lines of `text`.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

// Rows kept at the manifest's times are the run's own rows there (every row of the run simulated
// here, the one at each time picked by its t): the tidy table has one line per run and time, with
// the run's values and ok; a run that failed at its start has none.
TEST(SweepRun, RowsAtTimesAreTheRunsOwnRows) {
  Sweep s("double-pendulum", {"theta1=0.3:0.9:3"}, 1.0);
  s.manifest.times = {0.0, 0.37, 1.0};
  std::ostringstream log, table;
  run_sweep_rows(s.manifest, "h", 0, 3, s.dir / "runs", log);
  gather_sweep(s.manifest, "h", s.dir / "runs", table, GatherTable::rows_at_times);
  const auto got = lines(table.str());
  ASSERT_EQ(got.size(), 2u + 9u) << table.str();
  EXPECT_EQ(got[1].substr(0, 33), "run,seed,set.theta1,ok,t,theta1,t");
  const System system = load_model(s.model);
  const CompiledSystem compiled(system, kane_equations(system));
  for (std::size_t k = 0; k < 3; ++k) {
    SimulationStart start = initial_state(system, {{"theta1", s.manifest.runs[k].values[0]}});
    complete_initial_state(system, compiled, start);
    std::vector<std::vector<double>> rows;
    simulate(system, compiled, start, simulation_options(system.simulate, s.manifest.options),
             [&](const std::vector<double>& row) { rows.push_back(row); });
    for (std::size_t i = 0; i < 3; ++i) {
      const double wanted = s.manifest.times[i];
      const auto row = std::min_element(rows.begin(), rows.end(), [&](auto& a, auto& b) {
        return std::abs(a[0] - wanted) < std::abs(b[0] - wanted);
      });
      std::string expected =
          fmt::format("{},{},{},1", k, s.manifest.runs[k].seed, s.manifest.runs[k].values[0]);
      for (const double v : *row) expected += fmt::format(",{}", v);
      EXPECT_EQ(got[2 + 3 * k + i], expected);
    }
  }
  // the default table is still one row per run; a failed start keeps no rows
  std::ostringstream finals;
  gather_sweep(s.manifest, "h", s.dir / "runs", finals);
  EXPECT_EQ(lines(finals.str()).size(), 5u);
  Sweep gimbal("heavy-top", {"theta=0:0.1:2"}, 0.1);
  gimbal.manifest.times = {0.0, 0.1};
  run_sweep_rows(gimbal.manifest, "h", 0, 2, gimbal.dir / "runs", log);
  std::ostringstream tidy;
  gather_sweep(gimbal.manifest, "h", gimbal.dir / "runs", tidy, GatherTable::rows_at_times);
  const auto rows = lines(tidy.str());
  ASSERT_EQ(rows.size(), 4u) << tidy.str();
  EXPECT_EQ(rows[2].substr(0, 2), "1,");
  // rows at times of a manifest planned without them: refused
  s.manifest.times.clear();
  EXPECT_THROW(gather_sweep(s.manifest, "h", s.dir / "runs", table, GatherTable::rows_at_times),
               std::invalid_argument);
}

TEST(SweepRun, ChunksRunAgainOrOverlappingChangeNothing) {
  Sweep s("double-pendulum", {"theta1=0.1:1:6"}, 0.5);
  std::ostringstream log;
  run_sweep_rows(s.manifest, "h", 0, 4, s.dir / "runs", log);
  const std::string before = read(result_path(s.dir / "runs", 2));
  const auto written = fs::last_write_time(result_path(s.dir / "runs", 2));
  // a temporary file a killed worker left does not count as a result
  std::ofstream(s.dir / "runs" / ".run-0000004.csv.999.tmp") << "half a row";
  const ChunkReport again = run_sweep_rows(s.manifest, "h", 2, 6, s.dir / "runs", log);
  EXPECT_EQ(again.skipped, 2u);
  EXPECT_EQ(again.done, 2u);
  EXPECT_EQ(read(result_path(s.dir / "runs", 2)), before);
  EXPECT_EQ(fs::last_write_time(result_path(s.dir / "runs", 2)), written);
  std::ostringstream table;
  const GatherReport gathered = gather_sweep(s.manifest, "h", s.dir / "runs", table);
  EXPECT_TRUE(gathered.missing.empty() && gathered.stale.empty());
  const auto rows = lines(table.str());
  ASSERT_EQ(rows.size(), 8u);  // the comment, the header, six runs in order
  EXPECT_EQ(rows[0], "# unidyn sweep of " + s.model + ", manifest sha256 h, 6 runs");
  for (std::size_t k = 0; k < 6; ++k) EXPECT_EQ(rows[k + 2].substr(0, 2), std::to_string(k) + ",");
}

TEST(SweepRun, MissingRunsAreNamedAndAFailedRunIsARecord) {
  // runs 0 and 2 not run yet: named
  Sweep s("double-pendulum", {"theta1=0.1:0.2:3"}, 0.1);
  std::ostringstream log, table;
  run_sweep_rows(s.manifest, "h", 1, 2, s.dir / "runs", log);
  EXPECT_EQ(gather_sweep(s.manifest, "h", s.dir / "runs", table).missing,
            (std::vector<std::size_t>{0, 2}));
  // the heavy top started at θ = 0, the 3-1-3 angles' gimbal lock: its start fails, recorded
  Sweep gimbal("heavy-top", {"theta=0:0.1:2"}, 0.1);
  const ChunkReport report = run_sweep_rows(gimbal.manifest, "h", 0, 2, gimbal.dir / "runs", log);
  EXPECT_EQ(report.failed, 1u);
  const std::string failed = read(result_path(gimbal.dir / "runs", 0));
  EXPECT_NE(failed.find(",0,0,0,"), std::string::npos) << failed;
  EXPECT_NE(failed.find("gimbal lock"), std::string::npos) << failed;
}

// The bead on the hoop at the bottom, φ = π (φ from the top, φ'' = (Ω² cos φ + g/R0) sin φ): δφ'' =
// (Ω² − g/R0) δφ, stable with λ = ±i √(g/R0 − Ω²) below Ω² = g/R0 and unstable with
// λ = ±√(Ω² − g/R0) above it — per run, with the run's Ω.
TEST(SweepRun, EachRunsModesAtTheOperatingPoint) {
  Sweep s("rotating-hoop", {"Omega=2:6:3"}, 0.1);
  s.manifest.modes_at = {"phi=pi"};
  std::ostringstream log;
  run_sweep_rows(s.manifest, "h", 0, 3, s.dir / "runs", log);
  const System system = load_model(s.model);
  const SimulationStart start = initial_state(system, {});
  const double g = start.parameters[*system.find_parameter("g")];
  const double R0 = start.parameters[*system.find_parameter("R0")];
  const auto six = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return std::string(text);
  };
  for (std::size_t k = 0; k < 3; ++k) {
    const double omega = 2.0 + 2.0 * static_cast<double>(k);
    const double square = omega * omega - g / R0;
    const std::string expected =
        square < 0 ? ",linearly stable,0\u00b1" + six(std::sqrt(-square)) + "i,"
                   : ",unstable," + six(std::sqrt(square)) + " " + six(-std::sqrt(square)) + ",";
    const std::string result = read(result_path(s.dir / "runs", k));
    EXPECT_NE(result.find(expected), std::string::npos) << expected << "\n" << result;
  }
  EXPECT_NE(read(result_path(s.dir / "runs", 0)).find(",stability,eigenvalues,"),
            std::string::npos);
}

// A driven system's point is a periodic motion: its Floquet verdict and multipliers per run, over
// the drive's period at the run's Omega (Kapitza's inverted pendulum: falls below Ω = 198.2,
// stands above; tests/analysis/floquet.cpp checks the boundary against the Mathieu equation).
TEST(SweepRun, ADrivenPointGetsItsFloquetMultipliers) {
  Sweep s("driven-pendulum", {"Omega=150:250:2"}, 0.01);
  s.manifest.modes_at = {"phi=0"};
  std::ostringstream log;
  run_sweep_rows(s.manifest, "h", 0, 2, s.dir / "runs", log);
  const std::string falls = read(result_path(s.dir / "runs", 0));
  const std::string stands = read(result_path(s.dir / "runs", 1));
  EXPECT_NE(falls.find(",unstable,multipliers: 1.21"), std::string::npos) << falls;
  EXPECT_NE(stands.find(",linearly stable,multipliers: 0.99"), std::string::npos) << stands;
}

TEST(SweepRun, AModelChangedSinceThePlanIsRefused) {
  Sweep s("double-pendulum", {"theta1=0.1:0.2:2"}, 0.1);
  std::ofstream(s.model, std::ios::app) << "# edited\n";
  std::ostringstream log;
  EXPECT_THROW(run_sweep_rows(s.manifest, "h", 0, 2, s.dir / "runs", log), std::invalid_argument);
  EXPECT_THROW(run_sweep_rows(s.manifest, "h", 0, 3, s.dir / "runs", log), std::invalid_argument);
}

TEST(SweepRun, TasksCoverTheRunsOnce) {
  std::vector<int> covered(23, 0);
  for (std::size_t task = 0; task < 5; ++task) {
    const auto [first, last] = task_rows(23, 5, task);
    for (std::size_t k = first; k < last; ++k) ++covered[k];
  }
  EXPECT_EQ(covered, std::vector<int>(23, 1));
  EXPECT_THROW(task_rows(23, 5, 5), std::invalid_argument);
  EXPECT_THROW(task_rows(23, 0, 0), std::invalid_argument);
  const std::string slurm = slurm_script("/bin/unidyn", "/m.sweep.yaml", 23, 5);
  EXPECT_NE(slurm.find("#SBATCH --array=0-4\n"), std::string::npos);
  EXPECT_NE(slurm.find("export UNIDYN='/bin/unidyn'\nexport MANIFEST='/m.sweep.yaml'\n"),
            std::string::npos);
  EXPECT_NE(slurm.find("\"$UNIDYN\" sweep run \"$MANIFEST\" --chunk 5 --task "
                       "\"$SLURM_ARRAY_TASK_ID\""),
            std::string::npos);
  EXPECT_NE(parallel_script("/bin/unidyn", "/m.sweep.yaml", 23, 5).find("seq 0 4 | parallel"),
            std::string::npos);
}

// A result is kept only when it is whole and was made for its run of this manifest: results from
// before a re-plan (another manifest hash), copied from another run, cut short (also of the last
// row's newline alone) or empty are made again by `run`, and `gather` writes no table while one is
// there.
TEST(SweepRun, StaleOrBrokenResultsAreMadeAgainAndNeverGathered) {
  Sweep s("double-pendulum", {"theta1=0.1:0.4:4"}, 0.1);
  std::ostringstream log;
  const fs::path runs = s.dir / "runs";
  run_sweep_rows(s.manifest, "old", 0, 4, runs, log);
  // the same files under a new manifest (a re-plan): stale, all four
  std::ostringstream table;
  const GatherReport stale = gather_sweep(s.manifest, "new", runs, table);
  EXPECT_EQ(stale.stale, (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_EQ(table.str(), "");
  const ChunkReport remade = run_sweep_rows(s.manifest, "new", 0, 4, runs, log);
  EXPECT_EQ(remade.done, 4u);
  EXPECT_EQ(remade.remade, 4u);
  EXPECT_EQ(remade.skipped, 0u);
  // run 1's result copied over run 2's, run 3's cut short, run 0's emptied, run 1's row cut of its
  // newline (the stamp whole after it)
  fs::copy_file(result_path(runs, 1), result_path(runs, 2), fs::copy_options::overwrite_existing);
  const std::string whole = read(result_path(runs, 3));
  std::ofstream(result_path(runs, 3), std::ios::trunc) << whole.substr(0, whole.size() / 2);
  std::ofstream(result_path(runs, 0), std::ios::trunc);
  std::string one = read(result_path(runs, 1));
  one.erase(one.rfind("\n# unidyn sweep result"), 1);
  std::ofstream(result_path(runs, 1), std::ios::trunc) << one;
  EXPECT_EQ(gather_sweep(s.manifest, "new", runs, table).stale,
            (std::vector<std::size_t>{0, 1, 2, 3}));
  const ChunkReport again = run_sweep_rows(s.manifest, "new", 0, 4, runs, log);
  EXPECT_EQ(again.remade, 4u);
  EXPECT_EQ(again.skipped, 0u);
  EXPECT_EQ(read(result_path(runs, 3)), whole);
  const GatherReport gathered = gather_sweep(s.manifest, "new", runs, table);
  EXPECT_TRUE(gathered.stale.empty() && gathered.missing.empty());
}

}  // namespace
}  // namespace unidyn
