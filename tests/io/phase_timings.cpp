// Phase timings: nothing unless started; each phase the time since the previous mark, the phases
// adding up to the whole.
#include "unidyn/io/phase_timings.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
#include <string>
#include <thread>

namespace unidyn {
namespace {

// The seconds of the report's line for `phase`, or −1.
double seconds_of(const std::string& report, const std::string& phase) {
  std::istringstream in(report);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("  " + phase + " ", 0) == 0) return std::stod(line.substr(phase.size() + 2));
  }
  return -1;
}

TEST(PhaseTimings, NothingUntilStarted) {
  end_phase("before");
  EXPECT_EQ(phase_timings_report(), "");
}

TEST(PhaseTimings, PhasesInOrderAddUpToTheWhole) {
  start_phase_timings();
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  end_phase("first");
  std::this_thread::sleep_for(std::chrono::milliseconds(10));
  end_phase("second");
  const std::string report = phase_timings_report();
  const double first = seconds_of(report, "first"), second = seconds_of(report, "second"),
               all = seconds_of(report, "in all"),
               rest = std::max(0.0, seconds_of(report, "the rest"));
  // slept 30 ms and 10 ms: at least that long each (the clock is steady)
  EXPECT_GE(first, 0.029);
  EXPECT_GE(second, 0.009);
  EXPECT_LT(report.find("first"), report.find("second"));
  // printed to the millisecond: the parts and the whole agree to the rounding of four numbers
  EXPECT_NEAR(first + second + rest, all, 0.002);
}

}  // namespace
}  // namespace unidyn
