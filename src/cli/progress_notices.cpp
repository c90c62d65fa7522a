// Notices that a long command is still working (progress_notices.hpp).
#include "progress_notices.hpp"

#include <fmt/format.h>
#include <pthread.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

#include "unidyn/io/phase_timings.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn::cli {
namespace {

std::atomic<bool> g_ended{false};

// The first delay: 5 s on a terminal, none elsewhere, or what UNIDYN_PROGRESS_AFTER says.
std::optional<double> first_delay() {
  const char* asked = std::getenv("UNIDYN_PROGRESS_AFTER");
  if (asked == nullptr) {
    if (isatty(STDERR_FILENO) != 1) return std::nullopt;
    return 5.0;
  }
  if (std::string(asked) == "never") return std::nullopt;
  char* end = nullptr;
  const double seconds = std::strtod(asked, &end);
  if (end == asked || *end != '\0' || !std::isfinite(seconds) || seconds < 0 || seconds > 1e6) {
    fmt::print(stderr,
               "unidyn: warning: UNIDYN_PROGRESS_AFTER={} is neither a number of seconds (0 to "
               "1e6) nor `never`; no progress notices\n",
               printable(asked));
    return std::nullopt;
  }
  return seconds;
}

// The process's resident memory in MB, from /proc/self/statm (0 where it cannot be read).
double resident_megabytes() {
  std::ifstream statm("/proc/self/statm");
  long total_pages = 0, resident_pages = 0;
  if (!(statm >> total_pages >> resident_pages)) return 0;
  return static_cast<double>(resident_pages) * static_cast<double>(sysconf(_SC_PAGESIZE)) / 1e6;
}

// One notice: the time since the start, the memory, the last step finished.
void print_notice(double seconds) {
  std::string text =
      fmt::format("unidyn: still working after {} s ({:.0f} MB in memory)",
                  seconds < 10 ? fmt::format("{:.1f}", seconds) : fmt::format("{:.0f}", seconds),
                  resident_megabytes());
  if (const std::string phase = last_phase_ended(); !phase.empty()) {
    text += "; last step finished: " + phase;
  }
  fmt::print(stderr, "{}\n", text);
}

// Sleeps until each notice is due (delay, 2·delay, 4·delay, ...) and prints it unless the command
// has ended.
void watch(double delay) {
  const auto start = std::chrono::steady_clock::now();
  double due = delay;
  while (true) {
    std::this_thread::sleep_until(start + std::chrono::duration<double>(due));
    if (g_ended.load()) return;
    print_notice(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    due = due > 0 ? 2 * due : 1.0;
  }
}

}  // namespace

ProgressNotices::ProgressNotices() {
  const std::optional<double> delay = first_delay();
  if (!delay) return;
  // the ending signals go to the command's threads, never to this one (their handlers stop the
  // run between steps)
  sigset_t ending, previous;
  sigemptyset(&ending);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&ending, signal);
  pthread_sigmask(SIG_BLOCK, &ending, &previous);
  // detached: the process ends without waiting for the next notice
  std::thread(watch, *delay).detach();
  pthread_sigmask(SIG_SETMASK, &previous, nullptr);
}

ProgressNotices::~ProgressNotices() {
  g_ended.store(true);
}

}  // namespace unidyn::cli
