// `unidyn report MODEL [-o FILE.html]`: simulate as `simulate` does and write the report's page
// (report/report_page.hpp).
#pragma once

#include <ostream>

#include "unidyn/commands/model_commands.hpp"
#include "unidyn/commands/model_source.hpp"

namespace unidyn::commands {

// 0 when the run succeeded, 1 when it failed (the page shows the rows computed and why it
// stopped) or the build has no web assets; bad input throws std::invalid_argument. What was
// written goes to `out` in one line.
int run_report(const ModelOptions& c, const LoadedModel& model, std::ostream& out);

}  // namespace unidyn::commands
