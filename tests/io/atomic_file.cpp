// Files written whole or not at all (io/atomic_file): a reader sees the old file or the new one,
// and a process ended by a signal while it writes leaves the old file and nothing beside it.
#include "unidyn/io/atomic_file.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

namespace unidyn {
namespace {

namespace fs = std::filesystem;

std::string read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

// A directory of its own for one test, removed after it.
struct Directory {
  fs::path path = fs::temp_directory_path() / ("unidyn-atomic-" + std::to_string(::getpid()));
  Directory() {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~Directory() { fs::remove_all(path); }
  std::size_t entries() const {
    std::size_t count = 0;
    for ([[maybe_unused]] const auto& entry : fs::directory_iterator(path)) ++count;
    return count;
  }
};

TEST(AtomicFile, ReplacesTheOldFileWhole) {
  const Directory directory;
  const fs::path page = directory.path / "page.html";
  write_atomically(page, "old\n");
  write_atomically(page, "new\n");
  EXPECT_EQ(read_file(page), "new\n");
  EXPECT_EQ(directory.entries(), 1u);
}

// As the command line's handler does: the files being written removed, then the default action.
extern "C" void end_like_the_command_line(int signal) {
  remove_unfinished_files();
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// SIGTERM while a large file is being written (a child process, caught once its temporary
// exists): the child ends by the signal, the old file is intact and no temporary is left.
TEST(AtomicFile, ASignalWhileWritingLeavesTheOldFileAndNoTemporary) {
  const Directory directory;
  const fs::path page = directory.path / "page.html";
  write_atomically(page, "the previous page\n");
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGTERM, end_like_the_command_line);
    write_atomically(page, std::string(std::size_t{256} << 20, 'x'));
    ::_exit(0);
  }
  const fs::path temporary = directory.path / (".page.html." + std::to_string(child) + ".tmp");
  bool caught_writing = false;
  for (int k = 0; k < 200000 && !caught_writing; ++k) {
    std::error_code error;
    caught_writing = fs::exists(temporary, error);
    if (!caught_writing) std::this_thread::sleep_for(std::chrono::microseconds(50));
  }
  ::kill(child, SIGTERM);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(caught_writing) << "the temporary file was never seen";
  ASSERT_TRUE(WIFSIGNALED(status)) << "the write ended before the signal";
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_FALSE(fs::exists(temporary));
  EXPECT_EQ(read_file(page), "the previous page\n");
  EXPECT_EQ(directory.entries(), 1u);
}

}  // namespace
}  // namespace unidyn
