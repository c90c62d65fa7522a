// The analysis commands: an operating point, its linearisation, its modes, and sweeps of them.
#include "unidyn/commands/analysis_commands.hpp"

#include <fmt/format.h>

#include <cmath>

#include "analysis_report.hpp"
#include "floquet_report.hpp"
#include "unidyn/analysis/equilibria.hpp"
#include "unidyn/analysis/exact_state_matrix.hpp"
#include "unidyn/analysis/floquet_sweep.hpp"
#include "unidyn/analysis/parameter_sweep.hpp"
#include "unidyn/analysis/time_dependence.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/csv.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/sweep/manifest.hpp"

namespace unidyn::commands {
namespace {

// --set: parameters only (the operating point's values go with --at).
std::vector<std::pair<std::string, double>> parameter_sets(const System& system,
                                                           const std::vector<std::string>& sets) {
  const auto overrides = parse_sets(sets);
  for (const auto& [name, value] : overrides) {
    if (!system.find_parameter(name)) {
      throw std::invalid_argument("--set " + name +
                                  ": not a parameter (give coordinates and rates with --at)");
    }
  }
  return overrides;
}

// --sweep PARAM=FROM:TO:COUNT (a sweep's grid axis of at least two values).
struct SweepRange {
  std::string parameter;
  double from = 0, to = 0;
  std::size_t count = 0;
};
SweepRange parse_sweep(const std::string& text) {
  GridAxis axis;
  try {
    axis = parse_grid_axis(text);
  } catch (const std::invalid_argument&) {
    axis.count = 0;
  }
  if (axis.count < 2) {
    throw std::invalid_argument("--sweep " + text +
                                ": expected NAME=FROM:TO:COUNT (numbers, COUNT an integer >= 2)");
  }
  return {axis.name, axis.from, axis.to, axis.count};
}

// Where stability changes, on standard error; `growing`, `settling`: what happens above a
// boundary where stability is lost, regained.
void print_boundaries(const std::string& parameter,
                      const std::vector<StabilityBoundary>& boundaries,
                      const std::string& growing = "a mode grows above it",
                      const std::string& settling = "the last growing mode decays above it") {
  for (const StabilityBoundary& b : boundaries) {
    fmt::print(stderr, "stability changes at {} = {:.12g}: {}\n", parameter, b.value,
               b.becomes_stable ? settling : growing);
  }
  if (boundaries.empty()) fmt::print(stderr, "stability does not change in the range\n");
}

// The --period given, if any.
std::optional<double> period_given(const AnalysisOptions& c) {
  return c.period;
}

// modes --sweep of a driven system: the Floquet multipliers, one CSV row per value.
int run_floquet_sweep(const AnalysisOptions& c, const System& system,
                      const CompiledSystem& compiled, const TimeDependence& dependence,
                      const std::vector<GivenValue>& given,
                      const std::vector<std::pair<std::string, double>>& sets) {
  const SweepRange range = parse_sweep(c.sweep);
  const FloquetSweep sweep =
      sweep_floquet(system, compiled, dependence, given, sets, range.parameter, range.from,
                    range.to, range.count, period_given(c));
  const std::vector<std::string> header = floquet_sweep_header(sweep);
  CsvWriter csv(c.output.empty() ? "-" : c.output);
  csv.header(header);
  int failures = 0;
  for (const FloquetSweepPoint& p : sweep.points) {
    csv.row(floquet_sweep_row(p, (header.size() - 4) / 2));
    if (!p.failure.empty()) {
      ++failures;
      fmt::print(stderr, "{} = {}: {}\n", range.parameter, p.value, p.failure);
    }
  }
  csv.close();
  fmt::print(stderr,
             "a periodic motion: Floquet multipliers over one period at each value; stability "
             "changes where the largest |mu| crosses 1\n");
  print_boundaries(range.parameter, sweep.boundaries,
                   "a multiplier leaves the unit circle above it (|mu| > 1)",
                   "every multiplier is back on or inside the unit circle above it");
  return failures == 0 ? 0 : 1;
}

// modes --sweep: one CSV row per value, the stability boundaries on standard error.
int run_sweep(const AnalysisOptions& c, const System& system, const CompiledSystem& compiled,
              const std::vector<GivenValue>& given,
              const std::vector<std::pair<std::string, double>>& sets) {
  const SweepRange range = parse_sweep(c.sweep);
  const ParameterSweep sweep = sweep_modes(system, compiled, given, sets, range.parameter,
                                           range.from, range.to, range.count);
  std::size_t size = 0;
  for (const SweepPoint& p : sweep.points) size = std::max(size, p.eigenvalues.size());
  std::vector<std::string> header{range.parameter, "growth"};
  for (std::size_t k = 1; k <= size; ++k) {
    header.push_back(fmt::format("re{}", k));
    header.push_back(fmt::format("im{}", k));
  }
  CsvWriter csv(c.output.empty() ? "-" : c.output);
  csv.header(header);
  int failures = 0;
  for (const SweepPoint& p : sweep.points) {
    std::vector<double> row{p.value, p.growth};
    for (std::size_t k = 0; k < size; ++k) {
      const bool has = k < p.eigenvalues.size();
      row.push_back(has ? p.eigenvalues[k].real() : NAN);
      row.push_back(has ? p.eigenvalues[k].imag() : NAN);
    }
    csv.row(row);
    if (!p.failure.empty()) {
      ++failures;
      fmt::print(stderr, "{} = {}: {}\n", range.parameter, p.value, p.failure);
    }
  }
  csv.close();
  print_boundaries(range.parameter, sweep.boundaries);
  return failures == 0 ? 0 : 1;
}

// The period of the motion through the point: the one given (--period: equations that change
// with t must repeat after it; any motion through the point must come back after it, which
// linearize_periodic checks), else that of equations that depend on t periodically; nothing for
// equations that do not depend on t (or whose drive stands still at these values). Throws
// NotPeriodic for a dependence that is not periodic.
std::optional<DrivePeriod> drive_of(const System& system, const CompiledSystem& compiled,
                                    const TimeDependence& dependence,
                                    const std::vector<double>& parameters,
                                    std::optional<double> period) {
  if (!dependence.depends && !period) return std::nullopt;
  return drive_period(system, compiled, dependence, parameters, period);
}

// linearize, modes of a periodic motion: A(t0), the monodromy matrix, with modes the multipliers.
void write_periodic(std::ostream& out, const std::string& command, const AnalysisOptions& c,
                    const System& system, const CompiledSystem& compiled,
                    const OperatingPoint& point, const DrivePeriod& drive) {
  const PeriodicLinearization periodic = linearize_periodic(system, compiled, point, drive);
  const bool modes = command == "modes";
  const FloquetAnalysis floquet = modes ? analyse_floquet(periodic) : FloquetAnalysis{};
  const auto write = c.format == "json"    ? periodic_json
                     : c.format == "latex" ? periodic_latex
                                           : periodic_text;
  out << write(system, point, periodic, modes ? &floquet : nullptr);
}

}  // namespace

// linearize, modes about an equilibrium or a steady motion: A (in closed form where it can be),
// with modes the eigenvalues and the verdict.
void write_linearization(std::ostream& out, const std::string& command, const AnalysisOptions& c,
                         const System& system, const EquationsOfMotion& equations,
                         const CompiledSystem& compiled, const OperatingPoint& point,
                         const std::vector<GivenValue>& given) {
  const Linearization linearization = linearize(system, compiled, point);
  const bool modes = command == "modes";
  const ModeAnalysis analysis = modes ? analyse_modes(linearization) : ModeAnalysis{};
  const ExactLinearization exact{
      exact_second_order(system, equations, given),
      exact_state_matrix(system, equations, given, point, linearization)};
  if (c.format == "json" || c.format == "latex") {
    out << (c.format == "json" ? analysis_json : analysis_latex)(
        system, point, linearization, modes ? &analysis : nullptr, exact);
    return;
  }
  out << operating_point_text(system, point, linearization) << linearization_text(linearization)
      << exact_text(system, linearization, exact);
  if (modes) out << modes_text(linearization, analysis);
}

void write_analysis(std::ostream& out, const std::string& command, const AnalysisOptions& c,
                    const LoadedModel& model) {
  const System& system = model.system;
  const bool equilibria = command == "equilibria";
  const auto sets = parameter_sets(system, c.sets);
  // without --at, linearize and modes are about the model's initial state
  const bool initial = c.at.empty() && !equilibria;
  const std::vector<GivenValue> given =
      initial ? initial_values(system, sets)
              : parse_given_values(system, c.at, equilibria && !c.cyclic.empty());
  const EquationsOfMotion equations = lagrange_equations(system);
  const CompiledSystem compiled(system, equations);
  const TimeDependence dependence = time_dependence(system, equations);
  const std::vector<double> parameters = initial_state(system, sets).parameters;
  if (equilibria) {
    const auto found = find_equilibria(system, compiled, given, parameters,
                                       {.starts = c.starts, .cyclic = c.cyclic});
    out << (c.format == "json" ? equilibria_json(system, found)
                               : equilibria_text(system, found, c.starts));
    return;
  }
  const std::optional<DrivePeriod> drive =
      drive_of(system, compiled, dependence, parameters, period_given(c));
  OperatingPoint point = operating_point(system, compiled, given, parameters);
  if (initial) point.source = "the model's initial state (no --at given)";
  try {
    if (drive) {
      write_periodic(out, command, c, system, compiled, point, *drive);
    } else {
      write_linearization(out, command, c, system, equations, compiled, point, given);
    }
  } catch (const NotAnOperatingPoint& e) {
    if (!initial) throw;
    throw NotAnOperatingPoint(std::string("no --at given, and the model's initial state is not an "
                                          "operating point: ") +
                              e.what());
  }
}

bool write_mode_sweep(const AnalysisOptions& c, const LoadedModel& model) {
  if (c.format != "text") throw std::invalid_argument("--sweep writes CSV: drop --format");
  const System& system = model.system;
  const auto sets = parameter_sets(system, c.sets);
  const std::vector<GivenValue> given = parse_given_values(system, c.at);
  const EquationsOfMotion equations = lagrange_equations(system);
  const CompiledSystem compiled(system, equations);
  const TimeDependence dependence = time_dependence(system, equations);
  if (const auto period = period_given(c); period && !(std::isfinite(*period) && *period > 0)) {
    throw std::invalid_argument("--period " + detail::to_short_text(*period) +
                                ": expected a positive number of seconds");
  }
  if (dependence.depends || period_given(c)) {
    // a dependence that is not periodic is refused once, not at every value
    if (!dependence.not_periodic.empty() && !period_given(c)) {
      drive_period(system, compiled, dependence, initial_state(system, sets).parameters);
    }
    return run_floquet_sweep(c, system, compiled, dependence, given, sets) == 0;
  }
  return run_sweep(c, system, compiled, given, sets) == 0;
}

}  // namespace unidyn::commands
