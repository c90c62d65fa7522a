// The analysis commands on the command line: options in, exit statuses out.
#include "analysis_commands.hpp"

#include <iostream>

#include "unidyn/commands/model_source.hpp"

namespace unidyn::cli {

void add_analysis_commands(CLI::App& app, AnalysisCommands& c) {
  commands::AnalysisOptions& o = c.options;
  const auto common = [&](CLI::App* command) {
    command->add_option("model", c.model, "MODEL file or bundled model name")->required();
    command->add_option(
        "--at", o.at,
        "NAME=VALUE of the operating point: q or der(q), VALUE a number or an "
        "expression in the parameters; values not given start at 0 and are completed "
        "from the constraints (without --at: the model's initial state)");
    command->add_option("--set", o.sets, "NAME=NUMBER: a parameter");
    command->add_option("--format", o.format, "text | latex | json")
        ->check(CLI::IsMember({"text", "latex", "json"}))
        ->capture_default_str();
    command->add_option_function<double>(
        "--period", [&o](const double& T) { o.period = T; },
        "T: the period of the motion through the point, analysed over it by Floquet's theory "
        "(for equations that depend on t periodically it is found from their sines and "
        "cosines of multiples of t when not given)");
  };
  c.linearize = app.add_subcommand(
      "linearize", "Linearise the equations of motion about an equilibrium or a steady motion");
  common(c.linearize);
  c.modes = app.add_subcommand(
      "modes", "Eigenvalues, mode shapes, frequencies and the stability of an operating point");
  common(c.modes);
  c.modes->add_option("--sweep", o.sweep,
                      "NAME=FROM:TO:COUNT: eigenvalues at COUNT values of a parameter, or of a "
                      "coordinate or rate of the operating point, as CSV, and where stability "
                      "changes (on standard error)");
  c.equilibria = app.add_subcommand(
      "equilibria",
      "Find the equilibria (or steady motions at given rates or momenta) and their stability");
  c.equilibria->add_option("model", c.model, "MODEL file or bundled model name")->required();
  c.equilibria->add_option("--at", o.at,
                           "NAME=VALUE: a coordinate held at a value, a rate der(q) of the "
                           "steady motions sought (rates not given are 0), or the momentum p(q) "
                           "of a cyclic coordinate");
  c.equilibria
      ->add_option("--cyclic", o.cyclic,
                   "Q,...: cyclic coordinates, held rather than solved for; each rate given "
                   "(der(q)), from its momentum (p(q)), or from the constraints")
      ->delimiter(',');
  c.equilibria->add_option("--set", o.sets, "NAME=NUMBER: a parameter");
  c.equilibria->add_option("--starts", o.starts, "starting points of the search")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  c.equilibria->add_option("--format", o.format, "text | json")
      ->check(CLI::IsMember({"text", "json"}))
      ->capture_default_str();
  c.modes->add_option("-o,--output", o.output,
                      "with --sweep: the CSV file (default: standard output)");
}

int run_analysis_commands(const AnalysisCommands& c) {
  if (!c.linearize->parsed() && !c.modes->parsed() && !c.equilibria->parsed()) return -1;
  const commands::LoadedModel model = commands::load_named_model(c.model);
  if (!c.options.sweep.empty()) return commands::write_mode_sweep(c.options, model) ? 0 : 1;
  commands::write_analysis(std::cout,
                           c.equilibria->parsed() ? "equilibria"
                           : c.modes->parsed()    ? "modes"
                                                  : "linearize",
                           c.options, model);
  return 0;
}

}  // namespace unidyn::cli
