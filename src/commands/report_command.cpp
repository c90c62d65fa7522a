// The report command: a run with poses, the check, the page.
#include "unidyn/commands/report_command.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "analysis_report.hpp"
#include "floquet_report.hpp"
#include "unidyn/analysis/exact_state_matrix.hpp"
#include "unidyn/analysis/time_dependence.hpp"
#include "unidyn/commands/run_setup.hpp"
#include "unidyn/equations/equivalence.hpp"
#include "unidyn/equations/newton.hpp"
#include "unidyn/io/atomic_file.hpp"
#include "unidyn/numeric/constraint_forces.hpp"
#include "unidyn/numeric/poses.hpp"
#include "unidyn/report/report_page.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::commands {
namespace {

// Newton–Euler against Lagrange (`unidyn check`'s first part), in one sentence.
std::string check_text(const System& system, const EquationsOfMotion& lagrange) {
  const EquivalenceReport report = check_equivalence(system, lagrange, newton_equations(system));
  return fmt::format(
      "Newton-Euler (Newton's law projected onto the partial velocities) and Lagrange's equations: "
      "the residuals simplify to 0: {}; at {} random states the largest relative residual is "
      "{:.3g}",
      report.symbolic_zero ? "yes" : "NO", report.states, report.numeric_relative_residual);
}

// A LaTeX text without its comment lines (the page shows what they say as tables).
std::string without_comments(const std::string& latex) {
  std::string out;
  std::istringstream lines(latex);
  for (std::string line; std::getline(lines, line);) {
    if (!line.starts_with("%")) out += line + "\n";
  }
  return out;
}

// The linearisation about a point and its modes, for the page: ẋ = A x as `modes --format latex`
// writes it.
ReportOperatingPoint linearised(const std::string& label, const System& system,
                                const EquationsOfMotion& lagrange, const OperatingPoint& point,
                                const Linearization& linearization,
                                const std::vector<GivenValue>& given) {
  const ExactLinearization exact{exact_second_order(system, lagrange, given),
                                 exact_state_matrix(system, lagrange, given, point, linearization)};
  return {label,
          without_comments(analysis_latex(system, point, linearization, nullptr, exact)),
          linearization.coordinates,
          analyse_modes(linearization),
          std::nullopt,
          0.0};
}

// A driven system's periodic motion through a point, for the page: ẋ = A(t) x and the monodromy
// matrix as `modes --format latex` writes them, the Floquet multipliers.
ReportOperatingPoint periodic(const std::string& label, const System& system,
                              const CompiledSystem& compiled, const OperatingPoint& point,
                              const DrivePeriod& drive) {
  const PeriodicLinearization P = linearize_periodic(system, compiled, point, drive);
  return {label,
          without_comments(periodic_latex(system, point, P, nullptr)),
          P.at_start.coordinates,
          {},
          analyse_floquet(P),
          drive.period};
}

// The point the page linearises about: the one given with --at (bad input when it is not an
// operating point); else the initial state, when it is an equilibrium or a steady motion; else
// the first equilibrium found. Without one, why not.
void add_operating_point(ReportModel& report, const ModelOptions& c, const System& system,
                         const CompiledSystem& compiled, const SimulationStart& start) {
  // a driven system's points are periodic motions, over the period of its drive
  const TimeDependence dependence = time_dependence(system, report.equations);
  std::optional<DrivePeriod> drive;
  if (dependence.depends) {
    try {
      drive = drive_period(system, compiled, dependence, start.parameters);
    } catch (const NotPeriodic& e) {
      if (!c.at.empty()) throw;
      report.no_operating_point = e.what();
      return;
    }
  }
  const auto about = [&](const std::string& label, const OperatingPoint& point,
                         const std::vector<GivenValue>& given) {
    return drive ? periodic(label, system, compiled, point, *drive)
                 : linearised(label, system, report.equations, point,
                              linearize(system, compiled, point), given);
  };
  if (!c.at.empty()) {
    const std::vector<GivenValue> given = parse_given_values(system, c.at);
    const OperatingPoint point = operating_point(system, compiled, given, start.parameters);
    report.operating_point =
        about("the operating point given: " + printable(fmt::format("{}", fmt::join(c.at, ", "))),
              point, given);
    return;
  }
  std::vector<GivenValue> initial;
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    initial.push_back({q[i].name, given_number(start.q[k])});
    initial.push_back({"der(" + q[i].name + ")", given_number(start.qdot[k])});
  }
  try {
    const OperatingPoint point = operating_point(system, compiled, initial, start.parameters);
    report.operating_point = about("the initial state", point, initial);
    return;
  } catch (const std::exception& e) {
    report.no_operating_point = std::string("the initial state is not one: ") + e.what();
  }
  if (report.equilibria && !report.equilibria->equilibria.empty()) {
    const Equilibrium& first = report.equilibria->equilibria.front();
    std::vector<GivenValue> given;
    for (std::size_t i = 0; i < q.size(); ++i) {
      given.push_back({q[i].name, given_number(first.point.q[static_cast<Eigen::Index>(i)])});
    }
    report.operating_point = linearised("the first equilibrium found", system, report.equations,
                                        first.point, first.linearization, given);
  }
}

}  // namespace

int run_report(const ModelOptions& c, const LoadedModel& model, std::ostream& out) {
  const std::optional<WebAssets> assets = web_assets();
  if (!assets) {
    throw std::runtime_error(
        "this unidyn was built without the report's web assets (npm was not found when it was "
        "built): install Node.js and npm (scripts/setup.sh) and build it again");
  }
  const System system = command_system(c, model.system);
  CommandStart initial = command_start(c, model.system, system);
  const SimulationOptions options = options_for(system, c);
  const std::string path =
      c.output.empty() ? std::filesystem::path(model.path).stem().string() + ".html" : c.output;
  // checked now, written whole at the end (a Ctrl-C on the way leaves the previous page)
  try {
    expect_writable(path);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(printable(e.what()));
  }

  // the run, with every body's and particle's pose
  const CompiledSystem compiled = command_compiled(c, model, system);
  if (!c.project) complete_command_start(initial, model.system, system, compiled);
  const SimulationStart& start = initial.start;
  Poses poses(system);
  ConstraintForces forces(system);
  ReportRun run;
  run.columns = simulation_columns(system);
  // where the multipliers are in a row
  const auto lambda_at = static_cast<std::size_t>(
      std::find(run.columns.begin(), run.columns.end(),
                system.constraints.empty() ? "" : "lambda(" + system.constraints[0].name + ")") -
      run.columns.begin());
  run.columns.insert(run.columns.end(), poses.columns().begin(), poses.columns().end());
  run.columns.insert(run.columns.end(), forces.columns().begin(), forces.columns().end());
  run.force_owners = forces.owners();
  const auto n = static_cast<Eigen::Index>(system.coordinates().size());
  const auto m = static_cast<Eigen::Index>(system.constraints.size());
  const SimulationSummary s =
      simulate(system, compiled, start, options, [&](const std::vector<double>& row) {
        run.rows.push_back(row);
        const Eigen::Map<const Eigen::VectorXd> q(row.data() + 1, n), qdot(row.data() + 1 + n, n);
        poses.append(row[0], q, start.parameters, run.rows.back());
        if (forces.columns().empty()) return;
        const Eigen::Map<const Eigen::VectorXd> lambda(row.data() + lambda_at, m);
        forces.append(row[0], q, qdot, lambda, start.parameters, run.rows.back());
      });
  run.summary = run_headline(system, options, s);
  if (s.rows > 0) run.summary += run_figures(system, s);
  if (!forces.unavailable().empty()) {
    run.summary += "  constraint forces not drawn: " + forces.unavailable() + "\n";
  }
  for (const auto& phase : s.phases) run.events.emplace_back(phase.t, phase.what);

  // the equations and their check
  const EquationsOfMotion lagrange = lagrange_equations(system);
  ReportModel report{system, lagrange, start.parameters, check_text(system, lagrange), {}, 0, "",
                     {},     ""};
  // the equilibria, from fewer starts than `unidyn equilibria` takes: a page is made in seconds
  EquilibriumSearch search;
  search.starts = report.equilibrium_starts = 100;
  try {
    report.equilibria = find_equilibria(system, compiled, {}, start.parameters, search);
  } catch (const std::invalid_argument& e) {
    report.equilibria_not_sought = e.what();
  }
  add_operating_point(report, c, system, compiled, start);
  const std::string page = report_page(report, run, *assets);
  try {
    write_atomically(path, page);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(printable(e.what()));
  }
  out << fmt::format("report of {} written to {} ({:.0f} kB): {} rows{}\n", system.name,
                     printable(path), static_cast<double>(page.size()) / 1024.0, s.rows,
                     s.ok ? "" : ", the run FAILED: " + printable(s.message));
  return s.ok ? 0 : 1;
}

}  // namespace unidyn::commands
