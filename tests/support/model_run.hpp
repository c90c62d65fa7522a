// Running a bundled model through the whole pipeline, for validation tests: model file →
// Lagrange's equations → compiled system → simulation, with the rows kept in memory.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn::test {

inline std::string model_path(const std::string& name) {
  // appended rather than concatenated: GCC 12 at -O1 misreads `std::string(..) + "/"` as an
  // out-of-bounds copy (-Warray-bounds) once <string> comes from a precompiled header
  std::string path = UNIDYN_MODELS_DIR;
  path.append("/").append(name).append(".yaml");
  return path;
}

struct ModelRun {
  System system;
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  SimulationSummary summary;

  std::size_t index(const std::string& column) const {
    for (std::size_t i = 0; i < columns.size(); ++i) {
      if (columns[i] == column) return i;
    }
    throw std::out_of_range("no column " + column);
  }
  // The value of a column in a row.
  double at(std::size_t row, const std::string& column) const { return rows[row][index(column)]; }
  // The model's value of a parameter (as the file gives it).
  double parameter(const std::string& name) const {
    return system.parameters.at(system.find_parameter(name).value()).value;
  }
  std::vector<double> column(const std::string& name) const {
    std::vector<double> values;
    for (const auto& r : rows) values.push_back(r[index(name)]);
    return values;
  }
  // The rows on the output grid t = k · step (t0 = 0), without the events' own rows between.
  ModelRun on_grid(double step) const {
    ModelRun grid{system, columns, {}, summary};
    for (const auto& r : rows) {
      if (std::abs(r[0] / step - std::round(r[0] / step)) < 1e-9) grid.rows.push_back(r);
    }
    return grid;
  }
};

// The running integral of a column over the rows by Simpson's rule, two intervals at a time (the
// rows equally spaced, as on an output grid without events): entry i is ∫ from the first row's t
// to row i's for even i, NaN for odd i.
inline std::vector<double> running_integral(const ModelRun& run, const std::string& column) {
  std::vector<double> integral(run.rows.size(), std::nan(""));
  if (!run.rows.empty()) integral[0] = 0;
  for (std::size_t i = 2; i < run.rows.size(); i += 2) {
    const double h = run.at(i, "t") - run.at(i - 1, "t");
    integral[i] = integral[i - 2] +
                  h / 3 * (run.at(i - 2, column) + 4 * run.at(i - 1, column) + run.at(i, column));
  }
  return integral;
}

// Simulates a system through the whole pipeline with NAME=VALUE overrides; `adjust` may change the
// options (t_end, output_step, method, rtol) that the model file sets.
// With `complete`, the values the start leaves out are computed from the constraints first, as
// the command line does (integrate/initial_state.hpp).
inline ModelRun run_system(System system,
                           const std::vector<std::pair<std::string, double>>& overrides = {},
                           const std::function<void(SimulationOptions&)>& adjust = {},
                           bool complete = false) {
  ModelRun run{std::move(system), {}, {}, {}};
  SimulationOptions options = simulation_options(run.system.simulate);
  if (adjust) adjust(options);
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  run.columns = simulation_columns(run.system);
  SimulationStart start = initial_state(run.system, overrides);
  if (complete) complete_initial_state(run.system, compiled, start);
  run.summary = simulate(run.system, compiled, start, options,
                         [&](const std::vector<double>& row) { run.rows.push_back(row); });
  return run;
}

// A bundled model, so simulated (with `complete`, its start completed as `unidyn simulate` does).
inline ModelRun run_model(const std::string& name,
                          const std::vector<std::pair<std::string, double>>& overrides = {},
                          const std::function<void(SimulationOptions&)>& adjust = {},
                          bool complete = false) {
  return run_system(load_model(model_path(name)), overrides, adjust, complete);
}

}  // namespace unidyn::test
