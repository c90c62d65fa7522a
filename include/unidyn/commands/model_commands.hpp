// What `unidyn derive`, `check`, `simulate` and `models` do, as library functions over plain
// options: the command line (src/cli) and the Python module (python/) call these.
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace unidyn::commands {

struct LoadedModel;

// The options of derive, check, simulate and report (0 or "" for the model's own value).
struct ModelOptions {
  std::string method = "lagrange";  // derive: lagrange | kane | second-form | newton-euler
  std::string format = "text";      // derive: text | latex | json | c | python | matlab
  std::string form = "textbook";    // derive: textbook | zees | matrix
  bool standalone = false;          // derive --format latex: a whole document
  std::string output;               // simulate: the CSV file; report: the HTML file
  std::vector<std::string> sets;    // NAME=VALUE: a parameter, q or der(q)
  double t_end = 0, output_step = 0, rtol = 0;
  std::string integrator;  // simulate, report: the integration method
  bool reduced = false;    // approach II: the constraints solved for a coordinate eliminated
  // simulate: the old start — every value as given, then projected onto the constraints
  bool project = false;
  bool poses =
      false;  // simulate: each body's centre and Euler parameters, each particle's position
  std::string evaluation = "native";  // simulate: native (when a compiler is present) or tape
  std::vector<std::string> at;  // report: NAME=VALUE of the operating point to linearise about
};

// `unidyn derive`'s output for the model (its options in `c`: method, format, form, standalone,
// reduced). Throws std::invalid_argument for options that do not go together.
void write_derivation(std::ostream& out, const ModelOptions& c, const LoadedModel& model);

// `unidyn check`: Newton–Euler against Lagrange, and the initial state against the constraints
// and the equations; whether it passed.
bool write_check(std::ostream& out, const ModelOptions& c, const LoadedModel& model);

// `unidyn simulate`: the rows as CSV to c.output (standard output when empty), the summary to
// standard output (to standard error when the rows take standard output). `interruption` is
// asked after every row: a reason (e.g. "SIGINT, Ctrl-C") ends the run there, its rows kept.
struct SimulationOutcome {
  bool ok = true;                        // the run reached its end and every row was written
  const char* interrupted_by = nullptr;  // the interruption's reason, if one ended it
};
SimulationOutcome simulate_to_csv(const ModelOptions& c, const LoadedModel& model,
                                  const std::function<const char*()>& interruption = {});

// `unidyn models [NAME]`: the bundled models with their titles, or the text of one (a name that
// is none is bad input, std::invalid_argument).
void write_models(std::ostream& out, const std::string& name);

}  // namespace unidyn::commands
