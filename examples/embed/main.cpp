// unidyn embedded in a C++ program, built against the installed package (docs/cpp.md):
// load a model, derive its equations, simulate it, read the results.
//
//   embed MODEL.yaml [T_END]   prints the columns and the last row of the run, tab-separated
#include <cstdio>
#include <string>
#include <vector>

#include "unidyn/equations/kane.hpp"
#include "unidyn/integrate/initial_state.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: embed MODEL.yaml [T_END]\n");
    return 2;
  }
  try {
    // the model, its equations of motion, and their evaluation (the tape; native code is optional)
    const unidyn::System system = unidyn::load_model(argv[1]);
    const unidyn::CompiledSystem compiled(system, unidyn::kane_equations(system));
    // the model's initial state, the values it does not give completed from the constraints
    unidyn::SimulationStart start = unidyn::initial_state(system, {});
    unidyn::complete_initial_state(system, compiled, start);
    // its simulate: settings, the end time from the command line
    unidyn::SimulationOptions options = unidyn::simulation_options(system.simulate);
    if (argc > 2) options.t_end = std::stod(argv[2]);
    std::vector<double> last;
    const unidyn::SimulationSummary summary = unidyn::simulate(
        system, compiled, start, options, [&](const std::vector<double>& row) { last = row; });
    if (!summary.ok) {
      std::fprintf(stderr, "the run failed: %s\n", summary.message.c_str());
      return 1;
    }
    const std::vector<std::string> columns = unidyn::simulation_columns(system);
    for (std::size_t k = 0; k < columns.size(); ++k) {
      std::printf("%s%s", k ? "\t" : "", columns[k].c_str());
    }
    std::printf("\n");
    for (std::size_t k = 0; k < last.size(); ++k) std::printf("%s%.17g", k ? "\t" : "", last[k]);
    std::printf("\n");
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "embed: %s\n", e.what());
    return 2;
  }
}
