// Notices that a long command is still working: a derivation of a long chain takes minutes and
// hundreds of megabytes, and a command that says nothing for that long looks hung. On standard
// error, when it is a terminal (or when UNIDYN_PROGRESS_AFTER asks for them), after 5 s and then
// at doubling intervals: the time, the memory in use and the last step finished, e.g.
//   unidyn: still working after 10 s (612 MB in memory); last step finished: read model
// Standard output is untouched, so the equations and rows printed stay the same bytes.
#pragma once

namespace unidyn::cli {

// The notices while it lives (main, around the command run). UNIDYN_PROGRESS_AFTER=SECONDS sets
// the first delay and prints them whatever standard error is; UNIDYN_PROGRESS_AFTER=never turns
// them off.
class ProgressNotices {
 public:
  ProgressNotices();
  // no notice after this: the command has ended
  ~ProgressNotices();
  ProgressNotices(const ProgressNotices&) = delete;
  ProgressNotices& operator=(const ProgressNotices&) = delete;
};

}  // namespace unidyn::cli
