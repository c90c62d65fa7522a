// The signals that end a command: SIGINT (Ctrl-C), SIGTERM (kill, a batch system's time limit) and
// SIGHUP (the terminal closed).
//
// Outside a simulation they end the process as by default, after stopping every compiler it runs
// (each in a process group of its own, so Ctrl-C at the terminal does not reach it): none is left
// behind compiling for a process that is gone; the build directory it leaves is removed by the next
// compilation. A file being written whole (a report's page) is not left half-made beside the old
// one: its temporary is removed. During a simulation (InterruptWatch) the first one is noted, so
// that the run ends after the step being taken with its rows whole and its summary; the compilers
// are stopped at once, so the process does not wait for one at its end. A second signal ends the
// process at once. A signal that was ignored (a background job, nohup) is left ignored.
#pragma once

namespace unidyn::cli {

// Installs the process's handlers (main, once).
void end_commands_on_signals();

class InterruptWatch {
 public:
  InterruptWatch();
  ~InterruptWatch();
  InterruptWatch(const InterruptWatch&) = delete;
  InterruptWatch& operator=(const InterruptWatch&) = delete;
  bool requested() const;
  // 128 + the signal, as a shell reports a command it ended
  int exit_status() const;
  // "SIGINT, Ctrl-C", "SIGTERM" or "SIGHUP"
  const char* signal_name() const;

 private:
  void (*previous_[3])(int);
};

}  // namespace unidyn::cli
