// The model pipeline commands.
#include "model_commands.hpp"

#include "command_model.hpp"
#include "report_command.hpp"
#include "signals.hpp"
#include "simulation_setup.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
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
#include "unidyn/numeric/poses.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printable_text.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn::cli {
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
void write_export(std::ostream& out, const ModelCommands& c, const System& system,
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

void write_derivation(std::ostream& out, const ModelCommands& c, const CommandModel& model) {
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

namespace {

int run_check(const ModelCommands& c, const CommandModel& model) {
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
  fmt::print("{}: Newton's law projected onto the partial velocities vs Lagrange's equations\n",
             system.name);
  for (std::size_t i = 0; i < q.size(); ++i) {
    fmt::print("  [{}] residual simplifies to {}\n", q[i].name,
               to_text(report.symbolic_residual[i]));
  }
  fmt::print("  symbolic agreement: {}\n", report.symbolic_zero ? "yes" : "NO");
  fmt::print("  numeric agreement at {} random states: max relative residual {:.3g}\n",
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
      fmt::print("  initial values computed from the constraints: {}\n",
                 printable(fmt::format("{}", fmt::join(computed, ", "))));
    }
  } catch (const InitialStateError& e) {
    fmt::print("  {}\n", printable(e.what()));
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
    fmt::print(
        "  constraints at the initial state: max |Psi| = {:.3g}, max |A q' + e| = {:.3g}, "
        "rank A = {} of {}{}\n",
        max_psi, max_velocity, lu.rank(), holding.size(),
        holding.size() < compiled.constraint_count() ? " (unilateral contacts apart left out)"
                                                     : "");
    if (static_cast<std::size_t>(lu.rank()) != holding.size()) {
      fmt::print("  the constraints are not independent at the initial state\n");
      state_ok = false;
    }
    if (worst > kConstraintTolerance) {
      fmt::print("  the initial state violates the constraints (tolerance {:g} of its size): {}\n",
                 kConstraintTolerance, worst_text);
      state_ok = false;
    }
  }
  try {
    Eigen::VectorXd qddot, lambda;
    compiled.solve(start.t0, start.q, start.qdot, start.parameters, qddot, lambda, data);
  } catch (const std::runtime_error& e) {
    fmt::print("  the equations of motion cannot be solved at the initial state: {}\n", e.what());
    state_ok = false;
  }
  const bool agree = report.symbolic_zero && report.numeric_relative_residual < 1e-9;
  fmt::print("{}\n", agree && state_ok ? "check passed" : "check FAILED");
  return agree && state_ok ? 0 : 1;
}

int run_simulate(const ModelCommands& c, const CommandModel& model) {
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
  // Ctrl-C ends the run after the row being written, with the rows kept and the summary
  const InterruptWatch interrupt;
  SimulationOptions watched = options;
  watched.interrupted = [&] { return interrupt.requested(); };
  const SimulationSummary s =
      simulate(system, compiled, start, watched, [&](const std::vector<double>& row) {
        if (interrupt.requested()) {
          throw std::runtime_error(std::string("interrupted (") + interrupt.signal_name() + ")");
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
      s.ok                    ? (s.stopped ? "simulated until stop_when" : "simulated")
      : interrupt.requested() ? "INTERRUPTED"
                              : "FAILED",
      options.t_end, options.method, csv->rows_written(),
      s.event_rows > 0 ? fmt::format(" ({} at events between output times)", s.event_rows) : "",
      path == "-" ? "" : " written to " + printable(path));
  if (interrupt.requested()) {
    fmt::print(out, "  interrupted at t = {:.10g} ({})\n", s.failure_time, interrupt.signal_name());
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
  if (interrupt.requested()) return interrupt.exit_status();
  return s.ok && close_error.empty() ? 0 : 1;
}

int run_models(const ModelCommands& c) {
  const auto models = bundled_models();
  if (c.model_name.empty()) {
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
      fmt::print("{:<28}{}\n", path.stem().string(), title);
    }
    return 0;
  }
  for (const auto& path : models) {
    if (path.stem() == c.model_name) {
      std::ifstream in(path);
      fmt::print("# {}\n{}", path.string(), std::string(std::istreambuf_iterator<char>(in), {}));
      return 0;
    }
  }
  throw std::invalid_argument("no bundled model named '" + c.model_name +
                              "' (see `unidyn models`)");
}

// A positive, finite number (0 means "the model's value" in ModelCommands, so 0 or less given on
// the command line must be refused rather than ignored).
const CLI::Validator kPositive(
    [](std::string& text) -> std::string {
      double x = 0;
      const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), x);
      const bool ok = ec == std::errc() && ptr == text.data() + text.size() && std::isfinite(x);
      return ok && x > 0 ? "" : "expected a positive number, got '" + text + "'";
    },
    "POSITIVE");

}  // namespace

void add_model_commands(CLI::App& app, ModelCommands& c) {
  c.derive = app.add_subcommand("derive", "Print a model's equations of motion");
  c.derive->add_option("model", c.model, "MODEL file or bundled model name")->required();
  c.derive->add_option("--method", c.method, "lagrange | kane | second-form | newton-euler")
      ->capture_default_str();
  c.derive
      ->add_option("--format", c.format,
                   "text | latex | json | c | python | matlab (a function computing M, f, A, b "
                   "and q'')")
      ->capture_default_str();
  c.derive->add_flag(
      "--standalone", c.standalone,
      "with --format latex: a whole document (article, amsmath) that pdflatex compiles");
  c.derive
      ->add_option("--form", c.form,
                   "textbook (each equation as the book prints it: M q'' terms, then products of "
                   "rates, then the rest) | zees (the same with repeated subexpressions named z1, "
                   "z2, ...) | matrix (M q'' = f + A^T lambda)")
      ->capture_default_str();
  c.derive->add_flag("--timings", c.timings, "each phase's time on standard error");
  c.derive->add_flag("--reduced", c.reduced,
                     "approach II: eliminate the constraints that can be solved for a coordinate");
  c.derive->footer(
      "The textbook form's coefficients are simplified by one process per core; the environment's "
      "UNIDYN_PROCESSES=N sets how many.");

  // the options of a run, simulate's and report's
  const auto run_options = [&](CLI::App* command) {
    command->add_option("model", c.model, "MODEL file or bundled model name")->required();
    command->add_option("--t-end", c.t_end, "end time")->check(kPositive);
    command->add_option("--output-step", c.output_step, "time between rows")->check(kPositive);
    command->add_option("--method", c.integrator, integration_method_choices());
    command->add_option("--rtol", c.rtol, "relative tolerance (dopri5, dop853, cvode)")
        ->check(kPositive);
    command->add_option("--set", c.sets, "NAME=VALUE: a parameter, q or der(q)");
    command->add_flag("--reduced", c.reduced, "simulate the approach-II equations");
    command->add_flag("--project", c.project,
                      "start from every value as given, projected onto the constraints (all "
                      "values may move) instead of computing the values not given");
    command
        ->add_option("--evaluation", c.evaluation,
                     "native (compiled C++, cached; the tape when no compiler) | tape")
        ->check(CLI::IsMember({"native", "tape"}))
        ->capture_default_str();
  };
  c.simulate = app.add_subcommand("simulate", "Simulate a model: CSV rows and a run summary");
  run_options(c.simulate);
  c.simulate->add_option("-o,--output", c.output, "CSV file (default: standard output)");
  c.simulate->add_flag("--poses", c.poses,
                       "add each body's centre and Euler parameters (B.x B.y B.z B.e0 .. B.e3) and "
                       "each particle's position (P.x P.y P.z) to the CSV");
  c.report = app.add_subcommand(
      "report", "One offline HTML page of a model and a run: equations, plots, the motion in 3-D");
  run_options(c.report);
  c.report->add_option("-o,--output", c.output, "HTML file (default: MODEL's name.html)");
  c.report->add_option("--at", c.at,
                       "NAME=VALUE of the operating point whose linearisation and modes the page "
                       "shows, as `unidyn modes --at` (default: the initial state when it is an "
                       "equilibrium or steady motion, else the first equilibrium found)");

  c.check = app.add_subcommand("check", "Newton vs Lagrange agreement, constraint consistency");
  c.check->add_option("model", c.model, "MODEL file or bundled model name")->required();
  c.check->add_option("--set", c.sets, "NAME=VALUE: a parameter, q or der(q)");
  c.check->add_flag("--reduced", c.reduced, "check the approach-II equations");
  c.check->add_flag("--timings", c.timings, "each phase's time on standard error");

  c.models = app.add_subcommand("models", "List the bundled book systems, or print one");
  c.models->add_option("name", c.model_name, "a bundled model");
}

int run_model_commands(const ModelCommands& c) {
  if (c.models->parsed()) return run_models(c);
  if (!c.derive->parsed() && !c.simulate->parsed() && !c.check->parsed() && !c.report->parsed()) {
    return -1;
  }
  if (c.timings) start_phase_timings();
  const CommandModel model = read_command_model(c.model);
  // the timings on standard error however the command ends
  struct Report {
    ~Report() { fmt::print(stderr, "{}", phase_timings_report()); }
  } report;
  try {
    if (c.derive->parsed()) {
      write_derivation(std::cout, c, model);
      return 0;
    }
    if (c.simulate->parsed()) return run_simulate(c, model);
    if (c.report->parsed()) return run_report(c, model, std::cout);
    return run_check(c, model);
  } catch (const ExpressionTooLarge& e) {
    // an expansion of the derivation past its budget: point at the model's largest expression
    const System& system = model.system;
    if (system.largest_expression_terms <= 1) throw;
    throw ModelError(
        system.largest_expression,
        std::string(e.what()) + "; the model's largest power of a sum is here (up to " +
            fmt::format("{:.3g}", system.largest_expression_terms) + " terms expanded)");
  }
}

}  // namespace unidyn::cli
