// The model pipeline commands on the command line: options in, exit statuses out.
#include "model_commands.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <iostream>

#include "import_command.hpp"
#include "signals.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/commands/report_command.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/io/phase_timings.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"

namespace unidyn::cli {
namespace {

using commands::LoadedModel;

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

// simulate: Ctrl-C (or SIGTERM, SIGHUP) ends the run after the row being written, with the rows
// kept and the summary; the exit status then says which signal.
int run_simulate(const commands::ModelOptions& options, const LoadedModel& model) {
  const InterruptWatch interrupt;
  const commands::SimulationOutcome outcome = commands::simulate_to_csv(
      options, model, [&] { return interrupt.requested() ? interrupt.signal_name() : nullptr; });
  if (outcome.interrupted_by) return interrupt.exit_status();
  return outcome.ok ? 0 : 1;
}

}  // namespace

void add_model_commands(CLI::App& app, ModelCommands& c) {
  commands::ModelOptions& o = c.options;
  c.derive = app.add_subcommand("derive", "Print a model's equations of motion");
  c.derive->add_option("model", c.model, "MODEL file or bundled model name")->required();
  c.derive->add_option("--method", o.method, "lagrange | kane | second-form | newton-euler")
      ->capture_default_str();
  c.derive
      ->add_option("--format", o.format,
                   "text | latex | json | c | python | matlab (a function computing M, f, A, b "
                   "and q'')")
      ->capture_default_str();
  c.derive->add_flag(
      "--standalone", o.standalone,
      "with --format latex: a whole document (article, amsmath) that pdflatex compiles");
  c.derive
      ->add_option("--form", o.form,
                   "textbook (each equation as the book prints it: M q'' terms, then products of "
                   "rates, then the rest) | zees (the same with repeated subexpressions named z1, "
                   "z2, ...) | matrix (M q'' = f + A^T lambda)")
      ->capture_default_str();
  c.derive->add_flag("--timings", c.timings, "each phase's time on standard error");
  add_import_options(*c.derive, c.import);
  c.derive->add_flag("--reduced", o.reduced,
                     "approach II: eliminate the constraints that can be solved for a coordinate");
  c.derive->footer(
      "The textbook form's coefficients are simplified by one process per core; the environment's "
      "UNIDYN_PROCESSES=N sets how many.");

  // the options of a run, simulate's and report's
  const auto run_options = [&](CLI::App* command) {
    command->add_option("model", c.model, "MODEL file or bundled model name")->required();
    command->add_option("--t-end", o.t_end, "end time")->check(kPositive);
    command->add_option("--output-step", o.output_step, "time between rows")->check(kPositive);
    command->add_option("--method", o.integrator, integration_method_choices());
    command->add_option("--rtol", o.rtol, "relative tolerance (dopri5, dop853, cvode)")
        ->check(kPositive);
    command->add_option("--set", o.sets, "NAME=VALUE: a parameter, q or der(q)");
    command->add_flag("--reduced", o.reduced, "simulate the approach-II equations");
    command->add_flag("--project", o.project,
                      "start from every value as given, projected onto the constraints (all "
                      "values may move) instead of computing the values not given");
    command
        ->add_option("--evaluation", o.evaluation,
                     "native (compiled C++, cached; the tape when no compiler) | tape")
        ->check(CLI::IsMember({"native", "tape"}))
        ->capture_default_str();
    add_import_options(*command, c.import);
  };
  c.simulate = app.add_subcommand("simulate", "Simulate a model: CSV rows and a run summary");
  run_options(c.simulate);
  c.simulate->add_option("-o,--output", o.output, "CSV file (default: standard output)");
  c.simulate->add_flag("--poses", o.poses,
                       "add each body's centre and Euler parameters (B.x B.y B.z B.e0 .. B.e3) and "
                       "each particle's position (P.x P.y P.z) to the CSV");
  c.report = app.add_subcommand(
      "report", "One offline HTML page of a model and a run: equations, plots, the motion in 3-D");
  run_options(c.report);
  c.report->add_option("-o,--output", o.output, "HTML file (default: MODEL's name.html)");
  c.report->add_option("--at", o.at,
                       "NAME=VALUE of the operating point whose linearisation and modes the page "
                       "shows, as `unidyn modes --at` (default: the initial state when it is an "
                       "equilibrium or steady motion, else the first equilibrium found)");

  c.check = app.add_subcommand("check", "Newton vs Lagrange agreement, constraint consistency");
  c.check->add_option("model", c.model, "MODEL file or bundled model name")->required();
  c.check->add_option("--set", o.sets, "NAME=VALUE: a parameter, q or der(q)");
  c.check->add_flag("--reduced", o.reduced, "check the approach-II equations");
  c.check->add_flag("--timings", c.timings, "each phase's time on standard error");
  add_import_options(*c.check, c.import);

  c.models = app.add_subcommand("models", "List the bundled book systems, or print one");
  c.models->add_option("name", c.model_name, "a bundled model");
}

int run_model_commands(const ModelCommands& c) {
  if (c.models->parsed()) {
    commands::write_models(std::cout, c.model_name);
    return 0;
  }
  if (!c.derive->parsed() && !c.simulate->parsed() && !c.check->parsed() && !c.report->parsed()) {
    return -1;
  }
  if (c.timings) start_phase_timings();
  const LoadedModel model = commands::load_named_model(c.model, c.import);
  // the timings on standard error however the command ends
  struct Report {
    ~Report() { fmt::print(stderr, "{}", phase_timings_report()); }
  } report;
  try {
    if (c.derive->parsed()) {
      commands::write_derivation(std::cout, c.options, model);
      return 0;
    }
    if (c.simulate->parsed()) return run_simulate(c.options, model);
    if (c.report->parsed()) return commands::run_report(c.options, model, std::cout);
    return commands::write_check(std::cout, c.options, model) ? 0 : 1;
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
