// The rows a report page carries: a short run whole; a long one thinned to at most kMaxPageRows,
// with its first and last rows, the rows around its events, and every column's peaks — a spike of
// one row and the least and greatest values, put there by the test, are all on the page.
#include "unidyn/report/page_rows.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace unidyn {
namespace {

// t, sin t, and a column that is 0 but for a spike of one row (and one infinite row).
ReportRun run_of(std::size_t rows, std::size_t spike) {
  ReportRun run;
  run.columns = {"t", "wave", "spike"};
  for (std::size_t r = 0; r < rows; ++r) {
    const double t = 0.01 * static_cast<double>(r);
    run.rows.push_back({t, std::sin(t), r == spike ? 7.0 : 0.0});
  }
  run.rows[rows / 3][2] = std::numeric_limits<double>::infinity();
  return run;
}

bool has(const std::vector<std::size_t>& kept, std::size_t row) {
  return std::binary_search(kept.begin(), kept.end(), row);
}

TEST(PageRows, AShortRunIsWhole) {
  const ReportRun run = run_of(kMaxPageRows, 10);
  const std::vector<std::size_t> kept = page_rows(run);
  ASSERT_EQ(kept.size(), kMaxPageRows);
  for (std::size_t r = 0; r < kMaxPageRows; ++r) EXPECT_EQ(kept[r], r);
}

TEST(PageRows, ALongRunKeepsItsEnvelopeAndEvents) {
  const std::size_t rows = 1'000'003, spike = 612'345;
  ReportRun run = run_of(rows, spike);
  run.events = {{1234.565, "an impact"}};  // between rows 123456 and 123457
  const std::vector<std::size_t> kept = page_rows(run);
  EXPECT_LE(kept.size(), kMaxPageRows + 2);
  EXPECT_GE(kept.size(), (kMaxPageRows - 1) / 7);  // each stretch's first row at least
  EXPECT_TRUE(std::is_sorted(kept.begin(), kept.end()));
  EXPECT_EQ(std::adjacent_find(kept.begin(), kept.end()), kept.end());
  EXPECT_TRUE(has(kept, 0));
  EXPECT_TRUE(has(kept, rows - 1));
  EXPECT_TRUE(has(kept, spike));
  EXPECT_TRUE(has(kept, 123456));
  EXPECT_TRUE(has(kept, 123457));
  // sin t's least and greatest over the run are on the page to within a row's step
  double least = 1, greatest = -1;
  for (const std::size_t r : kept) {
    least = std::min(least, run.rows[r][1]);
    greatest = std::max(greatest, run.rows[r][1]);
  }
  EXPECT_NEAR(least, -1.0, 1e-4);
  EXPECT_NEAR(greatest, 1.0, 1e-4);
}

}  // namespace
}  // namespace unidyn
