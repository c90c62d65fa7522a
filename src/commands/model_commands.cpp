// The model pipeline commands: derive, check, simulate, the bundled models.
#include "unidyn/commands/model_commands.hpp"

#include "unidyn/commands/model_source.hpp"
#include "unidyn/commands/run_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <optional>
#include <sstream>

#include "unidyn/equations/equivalence.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/equations/newton.hpp"
#include "unidyn/equations/reduction.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/csv.hpp"
#include "unidyn/io/equation_report.hpp"
#include "unidyn/io/integrability_text.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/io/phase_timings.hpp"
#include "unidyn/io/potential_text.hpp"
#include "unidyn/io/textbook_equations.hpp"
#include "unidyn/kinematics/integrability.hpp"
#include "unidyn/numeric/code_export.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/dependent_constraints.hpp"
#include "unidyn/numeric/poses.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printable_text.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn::commands {
namespace {

EquationFormat parse_format(const std::string& format) {
  if (format == "text") return EquationFormat::text;
  if (format == "latex") return EquationFormat::latex;
  if (format == "json") return EquationFormat::json;
  throw std::invalid_argument("--format must be text, latex, json, c, python or matlab");
}

// (1.21), (8.18): which velocity constraints are integrable, alone and together;
// and (2.5): which forces given without a potential have one.
void write_integrability_and_potentials(std::ostream& out, const System& system,
                                        EquationFormat format) {
  const std::string prefix = format == EquationFormat::latex ? "% " : "  ";
  for (const std::string& line : integrability_lines(system)) out << prefix << line << '\n';
  for (const std::string& line : potential_lines(system)) out << prefix << line << '\n';
}

// The model's name as an identifier for exported functions: its file's stem, other characters as _.
std::string function_name(const std::string& path) {
  std::string stem = std::filesystem::path(path).stem().string();
  for (char& ch : stem) {
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  }
  if (stem.empty() || std::isdigit(static_cast<unsigned char>(stem.front())))
    stem = "model_" + stem;
  return stem;
}

// `derive --format c|python|matlab`: the equations as a self-contained function.
void write_export(std::ostream& out, const ModelOptions& c, const System& system,
                  const std::string& path) {
  if (c.method != "lagrange" && c.method != "kane") {
    throw std::invalid_argument("--format " + c.format +
                                " exports M, f, A and b: it needs "
                                "--method lagrange or kane");
  }
  const CodeLanguage language = c.format == "c"        ? CodeLanguage::c
                                : c.format == "python" ? CodeLanguage::python
                                                       : CodeLanguage::matlab;
  const EquationsOfMotion eq =
      c.method == "kane" ? kane_equations(system) : lagrange_equations(system);
  out << export_code(system, eq, language, function_name(path));
}

}  // namespace

void write_derivation(std::ostream& out, const ModelOptions& c, const LoadedModel& model) {
  const System system = command_system(c, model.system);
  if (c.format == "c" || c.format == "python" || c.format == "matlab") {
    write_export(out, c, system, model.path);
    return;
  }
  const EquationFormat format = parse_format(c.format);
  if (c.form != "textbook" && c.form != "matrix" && c.form != "zees") {
    throw std::invalid_argument("--form must be textbook, zees or matrix");
  }
  if (c.standalone && format != EquationFormat::latex) {
    throw std::invalid_argument("--standalone makes a LaTeX document: it needs --format latex");
  }
  if (c.method != "lagrange" && c.method != "kane" && c.method != "newton-euler" &&
      c.method != "second-form") {
    throw std::invalid_argument("--method must be lagrange, kane, second-form or newton-euler");
  }
  // a document pdflatex compiles as it is: the equations' display math in an article
  if (c.standalone) {
    out << "\\documentclass{article}\n\\usepackage{amsmath}\n\\begin{document}\n" << std::flush;
  }
  if (c.method == "kane" && c.form != "matrix") {
    // F_r + F*_r = 0 with the partial velocities (M and f with --form matrix)
    const EquationsOfMotion eq = kane_equations(system);
    end_phase("derive (kane)");
    write_kane(out, system, eq, lagrange_second_form(system, newton_equations(system), eq), format);
    end_phase("print");
  } else if (c.method == "lagrange" || c.method == "kane") {
    // M q̈ = f + Aᵀλ by Lagrange's equations, or through partial velocities (the same M and f):
    // as the book prints them, or as the matrices
    const EquationsOfMotion eq =
        c.method == "kane" ? kane_equations(system) : lagrange_equations(system);
    end_phase("derive (" + c.method + ")");
    if (c.form != "matrix" && format != EquationFormat::json) {
      write_textbook_lagrange(out, system, eq, format, c.form == "zees");
    } else {
      write_lagrange(out, system, eq, format);
      end_phase("print");
    }
    if (format != EquationFormat::json) {
      write_integrability_and_potentials(out, system, format);
      end_phase("integrability of the velocity constraints, potentials of the forces");
    }
  } else if (c.method == "newton-euler") {
    write_newton(out, system, newton_equations(system), format);
  } else if (c.method == "second-form") {
    const EquationsOfMotion eq = lagrange_equations(system);
    write_second_form(out, system, eq, lagrange_second_form(system, newton_equations(system), eq),
                      format);
  }
  if (c.standalone) out << "\\end{document}\n";
  out.flush();
}

bool write_check(std::ostream& out, const ModelOptions& c, const LoadedModel& model) {
  const System system = command_system(c, model.system);
  // the initial state first: one that is bad input stops before anything is printed
  CommandStart initial = command_start(c, model.system, system);
  SimulationStart& start = initial.start;
  const EquationsOfMotion lagrange = lagrange_equations(system);
  const NewtonEquations newton = newton_equations(system);
  end_phase("derive (lagrange, newton-euler)");
  const EquivalenceReport report = check_equivalence(system, lagrange, newton);
  end_phase("Newton-Euler = Lagrange (exact evaluation)");
  const auto& q = system.coordinates();
  out << fmt::format(
      "{}: Newton's law projected onto the partial velocities vs Lagrange's equations\n",
      system.name);
  for (std::size_t i = 0; i < q.size(); ++i) {
    out << fmt::format("  [{}] residual simplifies to {}\n", q[i].name,
                       to_text(report.symbolic_residual[i]));
  }
  out << fmt::format("  symbolic agreement: {}\n", report.symbolic_zero ? "yes" : "NO");
  out << fmt::format("  numeric agreement at {} random states: max relative residual {:.3g}\n",
                     report.states, report.numeric_relative_residual);

  // At the initial state (its values not given computed from the constraints): the constraints
  // satisfied and independent, the equations solvable.
  const CompiledSystem compiled(system, lagrange);
  CompiledSystemData data = compiled.make_data();
  bool state_ok = true;
  try {
    const std::vector<std::string> computed =
        complete_command_start(initial, model.system, system, compiled);
    if (!computed.empty()) {
      out << fmt::format("  initial values computed from the constraints: {}\n",
                         printable(fmt::format("{}", fmt::join(computed, ", "))));
    }
  } catch (const InitialStateError& e) {
    out << fmt::format("  {}\n", printable(e.what()));
    state_ok = false;
  }
  if (compiled.constraint_count() > 0) {
    compiled.constraints(start.t0, start.q, start.qdot, start.parameters, data);
    const Eigen::VectorXd velocity =
        data.constraint_matrix * start.qdot + data.constraint_velocity_term;
    // the constraints that hold: all but the unilateral ones that start apart (Ψ > 0)
    std::vector<Eigen::Index> holding;
    // the largest residual as the one tolerance measures it (integrate/initial_state.hpp), and
    // what it is
    double worst = 0;
    std::string worst_text;
    double max_psi = 0, max_velocity = 0;
    const auto note = [&](double value, const char* what, std::size_t k,
                          const Eigen::VectorXd& values) {
      const double relative = relative_residual(
          value, data.constraint_matrix.row(static_cast<Eigen::Index>(k)), values);
      if (relative <= worst) return;
      worst = relative;
      worst_text = fmt::format("{} of {} is {:.3g} ({:.3g} of the state's size as a distance)",
                               what, system.constraints[k].name, value, relative);
    };
    for (std::size_t k = 0; k < compiled.constraint_count(); ++k) {
      const auto K = static_cast<Eigen::Index>(k);
      const bool position = compiled.is_position_constraint()[k];
      const double psi = position ? data.constraint_position[K] : 0.0;
      if (system.constraints[k].unilateral && psi > 0.0 &&
          relative_residual(psi, data.constraint_matrix.row(K), start.q) > kConstraintTolerance) {
        continue;  // apart
      }
      holding.push_back(K);
      max_psi = std::max(max_psi, std::abs(psi));
      max_velocity = std::max(max_velocity, std::abs(velocity[K]));
      note(psi, "Psi", k, start.q);
      note(velocity[K], "A q' + e", k, start.qdot);
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(data.constraint_matrix(holding, Eigen::all));
    out << fmt::format(
        "  constraints at the initial state: max |Psi| = {:.3g}, max |A q' + e| = {:.3g}, "
        "rank A = {} of {}{}\n",
        max_psi, max_velocity, lu.rank(), holding.size(),
        holding.size() < compiled.constraint_count() ? " (unilateral contacts apart left out)"
                                                     : "");
    // dependent rows are accepted (numeric/dependent_constraints.hpp): named, not a failure
    std::vector<std::string> dependent;
    for (const Eigen::Index k : dependent_rows(data.constraint_matrix(holding, Eigen::all))) {
      dependent.push_back(system.constraints[static_cast<std::size_t>(holding[k])].name);
    }
    if (!dependent.empty()) {
      out << fmt::format(
          "  note: '{}' depend{} on the constraints before them at the initial state (a "
          "redundant row, or a singular position): the accelerations are unique, the multipliers "
          "are not; they are given as the minimum-norm ones\n",
          fmt::join(dependent, "', '"), dependent.size() > 1 ? "" : "s");
    }
    if (worst > kConstraintTolerance) {
      out << fmt::format(
          "  the initial state violates the constraints (tolerance {:g} of its size): {}\n",
          kConstraintTolerance, worst_text);
      state_ok = false;
    }
  }
  try {
    Eigen::VectorXd qddot, lambda;
    compiled.solve(start.t0, start.q, start.qdot, start.parameters, qddot, lambda, data);
  } catch (const std::runtime_error& e) {
    out << fmt::format("  the equations of motion cannot be solved at the initial state: {}\n",
                       e.what());
    state_ok = false;
  }
  const bool agree = report.symbolic_zero && report.numeric_relative_residual < 1e-9;
  out << fmt::format("{}\n", agree && state_ok ? "check passed" : "check FAILED");
  return agree && state_ok;
}

SimulationOutcome simulate_to_csv(const ModelOptions& c, const LoadedModel& model,
                                  const std::function<const char*()>& interruption) {
  const System system = command_system(c, model.system);
  CommandStart initial = command_start(c, model.system, system);
  const SimulationStart& start = initial.start;
  const SimulationOptions options = options_for(system, c);
  const auto clock_start = std::chrono::steady_clock::now();
  // the first rows come at once: a model not compiled yet starts on the tape
  const CompiledSystem compiled = command_compiled(c, model, system, true);
  const double derive_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  // the values given stay; the others come from the constraints (or, with --project, every value
  // as given and then projected onto the constraints)
  const std::vector<std::string> computed =
      c.project ? std::vector<std::string>{}
                : complete_command_start(initial, model.system, system, compiled);

  const std::string path = c.output.empty() ? "-" : c.output;
  std::optional<CsvWriter> csv;
  try {
    csv.emplace(path);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // bad input, not a failed run
  }
  std::vector<std::string> columns = simulation_columns(system);
  std::optional<Poses> poses;
  if (c.poses) {
    poses.emplace(system);
    columns.insert(columns.end(), poses->columns().begin(), poses->columns().end());
  }
  csv->header(columns);
  const auto n = static_cast<Eigen::Index>(system.coordinates().size());
  std::vector<double> with_poses;
  const auto run_start = std::chrono::steady_clock::now();
  // an interruption (Ctrl-C) ends the run after the row being written, with the rows kept and the
  // summary
  const char* interrupted = nullptr;
  const auto requested = [&] {
    if (!interrupted && interruption) interrupted = interruption();
    return interrupted != nullptr;
  };
  SimulationOptions watched = options;
  watched.interrupted = requested;
  const SimulationSummary s =
      simulate(system, compiled, start, watched, [&](const std::vector<double>& row) {
        if (requested()) {
          throw std::runtime_error(std::string("interrupted (") + interrupted + ")");
        }
        if (!poses) return csv->row(row);
        with_poses = row;
        poses->append(row[0], Eigen::Map<const Eigen::VectorXd>(row.data() + 1, n),
                      start.parameters, with_poses);
        csv->row(with_poses);
      });
  const double run_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - run_start).count();
  std::string close_error;
  try {
    csv->close();
  } catch (const CsvWriteError& e) {
    close_error = e.what();
  }

  // The summary goes to standard error when the CSV takes standard output.
  std::FILE* out = path == "-" ? stderr : stdout;
  fmt::print(
      out, "{}: {} from t = 0 to {} ({}), {} rows{}{}\n", system.name,
      s.ok          ? (s.stopped ? "simulated until stop_when" : "simulated")
      : interrupted ? "INTERRUPTED"
                    : "FAILED",
      options.t_end, options.method, csv->rows_written(),
      s.event_rows > 0 ? fmt::format(" ({} at events between output times)", s.event_rows) : "",
      path == "-" ? "" : " written to " + printable(path));
  if (interrupted) {
    fmt::print(out, "  interrupted at t = {:.10g} ({})\n", s.failure_time, interrupted);
  } else if (!s.ok) {
    fmt::print(out, "  stopped at t = {:.10g}: {}\n", s.failure_time, printable(s.message));
  }
  if (!close_error.empty()) fmt::print(out, "  FAILED at the end: {}\n", printable(close_error));
  fmt::print(out,
             "  derive + compile {:.3f} s, integrate {:.3f} s; {} steps ({} rejected), {} "
             "right-hand sides\n",
             derive_seconds, run_seconds, s.stats.accepted_steps, s.stats.rejected_steps,
             s.stats.rhs_evaluations);
  fmt::print(out, "  evaluation: {}\n", compiled.evaluation());
  for (const auto& line : start.computed) {
    fmt::print(out, "  parameter computed from --set: {}\n", printable(line));
  }
  if (!computed.empty()) {
    fmt::print(out, "  initial values computed from the constraints: {}\n",
               printable(fmt::format("{}", fmt::join(computed, ", "))));
  }
  // figures of the rows computed: none when the run failed at its start
  if (s.rows > 0) fmt::print(out, "{}", run_figures(system, s));
  for (const auto& phase : s.phases) {
    if (&phase == &s.phases.front()) fmt::print(out, "  phases and events:\n");
    fmt::print(out, "    t = {:.12g}: {}\n", phase.t, printable(phase.what));
  }
  return {s.ok && close_error.empty(), interrupted};
}

void write_models(std::ostream& out, const std::string& name) {
  const auto models = bundled_models();
  if (name.empty()) {
    for (const auto& path : models) {
      std::string title;
      if (std::ifstream in(path); in) {
        for (std::string line; std::getline(in, line);) {
          if (line.starts_with("name:")) {
            title = line.substr(5);
            break;
          }
        }
      }
      out << fmt::format("{:<28}{}\n", path.stem().string(), title);
    }
    return;
  }
  for (const auto& path : models) {
    if (path.stem() == name) {
      std::ifstream in(path);
      out << fmt::format("# {}\n{}", path.string(),
                         std::string(std::istreambuf_iterator<char>(in), {}));
      return;
    }
  }
  throw std::invalid_argument("no bundled model named '" + name + "' (see `unidyn models`)");
}

}  // namespace unidyn::commands
