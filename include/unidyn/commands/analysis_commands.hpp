// What `unidyn equilibria`, `linearize` and `modes` do, as library functions over plain options:
// the command line (src/cli) and the Python module (python/) call these.
#pragma once

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace unidyn::commands {

struct LoadedModel;

struct AnalysisOptions {
  std::vector<std::string> at;      // NAME=VALUE of the operating point
  std::vector<std::string> sets;    // NAME=NUMBER of parameters
  std::string format = "text";      // text | latex | json
  std::string sweep;                // modes: PARAM=FROM:TO:COUNT
  std::string output;               // modes --sweep: the CSV file
  std::optional<double> period;     // linearize, modes: --period T (none: found, if any)
  std::size_t starts = 200;         // equilibria: the starting points
  std::vector<std::string> cyclic;  // equilibria: the cyclic coordinates
};

// The output of `unidyn COMMAND` (linearize, modes or equilibria; not --sweep) with the options
// in `c`. Throws std::invalid_argument for bad input, NotAnOperatingPoint among it.
void write_analysis(std::ostream& out, const std::string& command, const AnalysisOptions& c,
                    const LoadedModel& model);

// `unidyn modes --sweep`: the eigenvalues (or, for a periodic motion, the Floquet multipliers) at
// each value as CSV to c.output (standard output when empty), where stability changes on standard
// error; whether every value was analysed.
bool write_mode_sweep(const AnalysisOptions& c, const LoadedModel& model);

}  // namespace unidyn::commands
