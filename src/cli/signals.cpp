// The signals that end a command (signals.hpp).
#include "signals.hpp"

#include <csignal>
#include <iterator>

#include "unidyn/io/atomic_file.hpp"
#include "unidyn/numeric/native_code.hpp"

namespace unidyn::cli {
namespace {

constexpr int kEndingSignals[] = {SIGINT, SIGTERM, SIGHUP};
volatile std::sig_atomic_t g_interrupted = 0;

// Outside a simulation: the compilers stopped and the files being written removed (their old
// versions stay), then the signal's default action.
extern "C" void on_ending_signal(int signal) {
  stop_native_compilers();
  remove_unfinished_files();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// During a simulation: noted and the compilers stopped; the next one ends the process.
extern "C" void on_interrupt(int signal) {
  g_interrupted = signal;
  stop_native_compilers();
  std::signal(signal, SIG_DFL);
}

// `handler` for each ending signal that is not ignored; the previous handlers in `previous`.
void handle_ending_signals(void (*handler)(int), void (*previous[])(int)) {
  for (std::size_t k = 0; k < std::size(kEndingSignals); ++k) {
    previous[k] = std::signal(kEndingSignals[k], handler);
    if (previous[k] == SIG_IGN) std::signal(kEndingSignals[k], SIG_IGN);
  }
}

}  // namespace

void end_commands_on_signals() {
  void (*previous[std::size(kEndingSignals)])(int);
  handle_ending_signals(on_ending_signal, previous);
}

InterruptWatch::InterruptWatch() {
  g_interrupted = 0;
  handle_ending_signals(on_interrupt, previous_);
}

InterruptWatch::~InterruptWatch() {
  for (std::size_t k = 0; k < std::size(kEndingSignals); ++k) {
    std::signal(kEndingSignals[k], previous_[k]);
  }
}

bool InterruptWatch::requested() const {
  return g_interrupted != 0;
}

int InterruptWatch::exit_status() const {
  return 128 + g_interrupted;
}

const char* InterruptWatch::signal_name() const {
  return g_interrupted == SIGINT    ? "SIGINT, Ctrl-C"
         : g_interrupted == SIGTERM ? "SIGTERM"
                                    : "SIGHUP";
}

}  // namespace unidyn::cli
