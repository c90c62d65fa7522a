// The rows of a run that a report page carries. A page holds every row up to kMaxPageRows (a
// 10 s run at the default step has 1 001); a longer run is thinned so that the page stays small
// and its plots draw (past ~150 000 rows the browser's script ran out of stack, and 10^6 rows made
// 68 MB): the run is cut into equal stretches, and of each the page keeps its first row and, for
// every column, the rows where that column is least and greatest — a plot through them has the
// run's envelope, every peak in it — and the last row and the rows around each event. The page
// says how many rows it shows of how many; the CSV of `unidyn simulate` has them all.
#pragma once

#include <cstddef>
#include <vector>

#include "unidyn/report/report_page.hpp"

namespace unidyn {

inline constexpr std::size_t kMaxPageRows = 20000;

// The indices of the rows the page keeps, in order, each once; at most kMaxPageRows plus the
// events' rows.
std::vector<std::size_t> page_rows(const ReportRun& run);

}  // namespace unidyn
