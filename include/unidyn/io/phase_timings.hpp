// Where a command's time goes, phase by phase (`unidyn derive --timings`): a wall clock read at
// the end of each phase, reported on standard error so that the equations printed stay the same.
#pragma once

#include <string>
#include <string_view>

namespace unidyn {

// Starts recording: the clock from now, the phases marked after this reported.
void start_phase_timings();

// Ends the phase named: the time since the previous mark (or the start) is its (when recording
// was started). The name is kept in any case, for last_phase_ended().
void end_phase(std::string_view phase);

// The name of the last phase ended ("" before the first), from any thread: what a progress notice
// says the command has done.
std::string last_phase_ended();

// One line per phase, in the order they ended ("  read model          0.012 s"), "the rest" since
// the last one when that shows in milliseconds, and the total; empty when recording was not
// started.
std::string phase_timings_report();

}  // namespace unidyn
