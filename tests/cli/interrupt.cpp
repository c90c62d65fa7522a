// Ctrl-C during a simulation: the run ends at the next row with every row before it kept and
// counted, the summary printed with "interrupted at t = …", and exit status 130.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>

#include "cli_support.hpp"

extern char** environ;

namespace unidyn {
namespace {

using namespace cli_test;

TEST(Interrupt, CtrlCKeepsTheRowsAndTheSummary) {
  const std::string csv = temp_path("interrupted.csv"), summary = temp_path("summary.txt");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, summary.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> words{
      UNIDYN_EXECUTABLE, "simulate", "kepler", "--t-end", "1e5", "-o", csv};
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  // SIGINT at its default and not blocked in the child, whatever the test inherited (a shell's
  // background job ignores it, and unidyn leaves an ignored SIGINT alone)
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  posix_spawnattr_setsigdefault(&attributes, &interrupt);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  ASSERT_EQ(posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ), 0);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  // interrupted once it is writing rows (its size from a stat: reading a file written at hundreds
  // of MB/s chases its end until the run is over)
  const auto written = [&] {
    std::error_code error;
    const auto size = std::filesystem::file_size(csv, error);
    return error ? std::uintmax_t{0} : size;
  };
  for (int wait = 0; wait < 200 && written() < 10000; ++wait) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by a signal, not by the handler";
  EXPECT_EQ(WEXITSTATUS(status), 130);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "INTERRUPTED")) << out;
  EXPECT_TRUE(contains(out, "interrupted at t = ")) << out;
  EXPECT_TRUE(contains(out, "energy: initial")) << out;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);
  EXPECT_TRUE(contains(out, std::to_string(rows.rows.size()) + " rows written")) << out;
  EXPECT_LT(rows.rows.back()[0], 1e5);
  // the steps taken until then are counted
  EXPECT_FALSE(contains(out, "; 0 steps")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

}  // namespace
}  // namespace unidyn
