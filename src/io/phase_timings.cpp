// Phase timings of a command.
#include "unidyn/io/phase_timings.hpp"

#include <fmt/format.h>
#include <chrono>
#include <mutex>
#include <optional>
#include <utility>
#include <vector>

namespace unidyn {
namespace {

using Clock = std::chrono::steady_clock;

struct Recording {
  Clock::time_point start, last;
  std::vector<std::pair<std::string, double>> phases;
};

// the command's one recording (a process runs one command)
std::optional<Recording>& recording() {
  static std::optional<Recording> r;
  return r;
}

// The name of the last phase ended, for a watcher in another thread (never destroyed: a thread
// may still read it while the process exits).
struct LastPhase {
  std::mutex mutex;
  std::string name;
};

LastPhase& last_phase() {
  static LastPhase* last = new LastPhase;
  return *last;
}

}  // namespace

void start_phase_timings() {
  const Clock::time_point now = Clock::now();
  recording() = Recording{now, now, {}};
}

void end_phase(std::string_view phase) {
  {
    LastPhase& last = last_phase();
    const std::lock_guard lock(last.mutex);
    last.name = phase;
  }
  auto& r = recording();
  if (!r) return;
  const Clock::time_point now = Clock::now();
  r->phases.emplace_back(std::string(phase), std::chrono::duration<double>(now - r->last).count());
  r->last = now;
}

std::string last_phase_ended() {
  LastPhase& last = last_phase();
  const std::lock_guard lock(last.mutex);
  return last.name;
}

std::string phase_timings_report() {
  const auto& r = recording();
  if (!r) return "";
  std::string text = "timings (wall clock):\n";
  for (const auto& [phase, seconds] : r->phases) {
    text += fmt::format("  {:<42} {:8.3f} s\n", phase, seconds);
  }
  // what came after the last phase marked (a command whose steps are not marked)
  const Clock::time_point now = Clock::now();
  if (const double rest = std::chrono::duration<double>(now - r->last).count(); rest >= 5e-4) {
    text += fmt::format("  {:<42} {:8.3f} s\n", "the rest", rest);
  }
  return text + fmt::format("  {:<42} {:8.3f} s\n", "in all",
                            std::chrono::duration<double>(now - r->start).count());
}

}  // namespace unidyn
