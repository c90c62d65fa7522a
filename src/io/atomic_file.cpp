// Whole-or-nothing files: temporary, fsync, rename, directory fsync.
#include "unidyn/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>

namespace unidyn {
namespace fs = std::filesystem;

namespace {

// The directory a path is in ("." for a bare name).
fs::path directory_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

}  // namespace

void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path temporary =
      directory_of(path) /
      ("." + path.filename().string() + "." + std::to_string(::getpid()) + ".tmp");
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw std::runtime_error("cannot write " + temporary.string());
  const auto give_up = [&](const std::string& why) {
    std::remove(temporary.c_str());
    throw std::runtime_error(why);
  };
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n <= 0) {
      ::close(fd);
      give_up("cannot write " + temporary.string());
    }
    written += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) give_up("cannot write " + temporary.string());
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    give_up("cannot rename into " + path.string());
  }
  if (const int dir = ::open(directory_of(path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
      dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
}

void expect_writable(const fs::path& path) {
  std::error_code error;
  if (fs::is_directory(path, error)) {
    throw std::invalid_argument("cannot write " + path.string() + ": it is a directory");
  }
  if (::access(directory_of(path).c_str(), W_OK | X_OK) != 0) {
    throw std::invalid_argument("cannot write " + path.string() +
                                ": its directory is not writable or does not exist");
  }
}

}  // namespace unidyn
