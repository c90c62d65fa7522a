// Whole-or-nothing files: temporary, fsync, rename, directory fsync.
#include "unidyn/io/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace unidyn {
namespace fs = std::filesystem;

namespace {

// The directory a path is in ("." for a bare name).
fs::path directory_of(const fs::path& path) {
  return path.parent_path().empty() ? fs::path(".") : path.parent_path();
}

// The temporary files being written, for remove_unfinished_files(): fixed slots a signal handler
// may read (a slot's state is free, being filled, or naming a file).
enum SlotState : int { kFree, kFilling, kNaming };
struct UnfinishedSlot {
  std::atomic<int> state{kFree};
  char path[4096];
};
UnfinishedSlot g_unfinished[8];
static_assert(std::atomic<int>::is_always_lock_free);

// One temporary file named in a slot while it lives (no slot free, or a path too long: not named,
// and a signal may leave it behind).
class UnfinishedFile {
 public:
  explicit UnfinishedFile(const fs::path& temporary) {
    const std::string& text = temporary.native();
    if (text.size() >= sizeof(UnfinishedSlot::path)) return;
    for (auto& slot : g_unfinished) {
      int free = kFree;
      if (!slot.state.compare_exchange_strong(free, kFilling)) continue;
      std::memcpy(slot.path, text.c_str(), text.size() + 1);
      slot.state.store(kNaming);
      slot_ = &slot;
      return;
    }
  }
  ~UnfinishedFile() {
    if (slot_ != nullptr) slot_->state.store(kFree);
  }
  UnfinishedFile(const UnfinishedFile&) = delete;
  UnfinishedFile& operator=(const UnfinishedFile&) = delete;

 private:
  UnfinishedSlot* slot_ = nullptr;
};

}  // namespace

void write_atomically(const fs::path& path, const std::string& text) {
  const fs::path temporary = directory_of(path) / ("." + path.filename().string() + "." +
                                                   std::to_string(::getpid()) + ".tmp");
  // named before it exists: a signal from here to the rename removes it
  const UnfinishedFile unfinished(temporary);
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

void remove_unfinished_files() noexcept {
  for (auto& slot : g_unfinished) {
    if (slot.state.load() == kNaming) ::unlink(slot.path);
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
