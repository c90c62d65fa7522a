// What `simulate` and `report` share: the system and start the command line asks for, the
// simulation's options, and the summary's figures of a run.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unidyn/commands/model_commands.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/integrate/simulation.hpp"

namespace unidyn::commands {

// With --reduced, the model's approach-II form (the notes on what was eliminated go to standard
// error).
System command_system(const ModelOptions& c, const System& loaded);

// The initial state before its completion: of the system run, and with --reduced, when a value or
// rate is given for a coordinate that approach II eliminated, of the full model too, whose given
// values (the eliminated one's included) the completion keeps. Bad input (an unknown --set name)
// throws here, before anything is printed.
struct CommandStart {
  SimulationStart start;
  std::optional<SimulationStart> full;
};
CommandStart command_start(const ModelOptions& c, const System& full, const System& system);

// Completes the start (integrate/initial_state.hpp) and returns what was computed: with the full
// model's start, from all of its constraints (the eliminated ones included), then restricted to
// the reduced coordinates. Throws InitialStateError naming a violated constraint.
std::vector<std::string> complete_command_start(CommandStart& s, const System& full,
                                                const System& system,
                                                const CompiledSystem& compiled);

// The system compiled for a run: native code unless --evaluation tape, cached under the bytes that
// determine it; with `background`, compiled while the run starts on the tape when not cached.
CompiledSystem command_compiled(const ModelOptions& c, const LoadedModel& model,
                                const System& system, bool background = false);

// The model's simulate: settings with the command line's overrides.
SimulationOptions options_for(const System& system, const ModelOptions& c);

// The summary's first line: "NAME: simulated from t = 0 to T (METHOD), N rows", or FAILED at t with
// the reason.
std::string run_headline(const System& system, const SimulationOptions& options,
                         const SimulationSummary& s);

// The summary's figures of the rows: energy, constraint residuals and each multiplier's range,
// the initial projection, gimbal lock, conserved quantities (lines starting "  ").
std::string run_figures(const System& system, const SimulationSummary& s);

}  // namespace unidyn::commands
