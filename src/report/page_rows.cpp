// The rows of a run a report page carries (report/page_rows.hpp).
#include "unidyn/report/page_rows.hpp"

#include <algorithm>
#include <cmath>

namespace unidyn {
namespace {

// In rows [first, last): the rows where column c is least and greatest (its finite values only).
void add_extremes(const ReportRun& run, std::size_t c, std::size_t first, std::size_t last,
                  std::vector<std::size_t>& kept) {
  std::size_t least = last, greatest = last;
  for (std::size_t r = first; r < last; ++r) {
    const double v = run.rows[r][c];
    if (!std::isfinite(v)) continue;
    if (least == last || v < run.rows[least][c]) least = r;
    if (greatest == last || v > run.rows[greatest][c]) greatest = r;
  }
  if (least != last) kept.push_back(least);
  if (greatest != last) kept.push_back(greatest);
}

}  // namespace

std::vector<std::size_t> page_rows(const ReportRun& run) {
  const std::size_t n = run.rows.size();
  std::vector<std::size_t> kept;
  if (n <= kMaxPageRows) {
    kept.resize(n);
    for (std::size_t r = 0; r < n; ++r) kept[r] = r;
    return kept;
  }
  // each stretch gives at most 1 + 2·columns rows
  const std::size_t columns = run.columns.size();
  const std::size_t stretches = std::max<std::size_t>(1, (kMaxPageRows - 1) / (1 + 2 * columns));
  for (std::size_t s = 0; s < stretches; ++s) {
    const std::size_t first = s * n / stretches, last = (s + 1) * n / stretches;
    kept.push_back(first);
    for (std::size_t c = 1; c < columns; ++c) add_extremes(run, c, first, last, kept);
  }
  kept.push_back(n - 1);
  // the rows on either side of each event's time (t is column 0)
  for (const auto& [t, what] : run.events) {
    const auto after =
        std::lower_bound(run.rows.begin(), run.rows.end(), t,
                         [](const std::vector<double>& row, double time) { return row[0] < time; });
    const auto r = static_cast<std::size_t>(after - run.rows.begin());
    if (r < n) kept.push_back(r);
    if (r > 0) kept.push_back(r - 1);
  }
  std::sort(kept.begin(), kept.end());
  kept.erase(std::unique(kept.begin(), kept.end()), kept.end());
  return kept;
}

}  // namespace unidyn
