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

// `unidyn ARGS...` with its standard output to `summary`, SIGINT, SIGTERM and SIGHUP at their default and not blocked
// in the child, whatever the test inherited (a shell's background job ignores it, and unidyn
// leaves an ignored SIGINT alone). Its pid, or -1.
pid_t spawn_unidyn(std::vector<std::string> words, const std::string& summary) {
  words.insert(words.begin(), UNIDYN_EXECUTABLE);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, summary.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char*> argv;
  for (auto& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t interrupt;
  sigemptyset(&interrupt);
  sigaddset(&interrupt, SIGINT);
  sigaddset(&interrupt, SIGTERM);
  sigaddset(&interrupt, SIGHUP);
  posix_spawnattr_setsigdefault(&attributes, &interrupt);
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGDEF | POSIX_SPAWN_SETSIGMASK);
  pid_t pid = 0;
  const int error = posix_spawn(&pid, argv[0], &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  return error == 0 ? pid : -1;
}

TEST(Interrupt, CtrlCKeepsTheRowsAndTheSummary) {
  const std::string csv = temp_path("interrupted.csv"), summary = temp_path("summary.txt");
  const pid_t pid = spawn_unidyn({"simulate", "kepler", "--t-end", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
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

// Ctrl-C is looked at every step, not only when a row is written: a run with one row at each end
// (12 s of steps between them) ends within a second of it, with its first row and the summary.
TEST(Interrupt, CtrlCBetweenRowsEndsTheRunAtOnce) {
  const std::string csv = temp_path("sparse.csv"), summary = temp_path("sparse.txt");
  // the native code in the cache first: a compiler still running in the background is another
  // matter (the process waits for it)
  ASSERT_EQ(run("simulate kepler --t-end 1 -o /dev/null").status, 0);
  const pid_t pid = spawn_unidyn(
      {"simulate", "kepler", "--t-end", "1e5", "--output-step", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  const auto sent = std::chrono::steady_clock::now();
  ASSERT_EQ(::kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - sent).count();
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);
  EXPECT_LT(seconds, 1.0);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "INTERRUPTED")) << out;
  EXPECT_TRUE(contains(out, "1 rows written")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

// SIGTERM (a batch system's time limit) as Ctrl-C: the rows whole, the summary naming it, exit
// 143 (it used to kill the process, a torn last row in 3 of 20 trials).
TEST(Interrupt, SigtermKeepsWholeRowsAndTheSummary) {
  const std::string csv = temp_path("terminated.csv"), summary = temp_path("terminated.txt");
  ASSERT_EQ(run("simulate kepler --t-end 1 -o /dev/null").status, 0);  // cached native code
  const pid_t pid = spawn_unidyn({"simulate", "kepler", "--t-end", "1e5", "-o", csv}, summary);
  ASSERT_GT(pid, 0);
  std::this_thread::sleep_for(std::chrono::milliseconds(700));
  ASSERT_EQ(::kill(pid, SIGTERM), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFEXITED(status)) << "ended by the signal, not by the handler";
  EXPECT_EQ(WEXITSTATUS(status), 143);
  const std::string out = read_file(summary);
  EXPECT_TRUE(contains(out, "(SIGTERM)")) << out;
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const Csv rows = parse_csv(text);
  EXPECT_TRUE(contains(out, std::to_string(rows.rows.size()) + " rows written")) << out;
  std::remove(csv.c_str());
  std::remove(summary.c_str());
}

}  // namespace
}  // namespace unidyn
