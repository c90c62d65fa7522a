// The native-code cache on disk: trusted directories, locks, complete entries, checksums.
#include "unidyn/numeric/code_cache.hpp"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <thread>

#include "unidyn/numeric/digest.hpp"

namespace unidyn {

std::string environment_variable(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

namespace {

namespace fs = std::filesystem;

std::string system_error(const std::string& what) {
  return what + ": " + std::strerror(errno);
}

// A file descriptor closed when it goes out of scope.
class Descriptor {
 public:
  explicit Descriptor(int fd) : fd_(fd) {}
  ~Descriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

// Why a file opened from the cache is not ours alone, or "".
std::string untrusted_file_reason(const struct stat& s) {
  if (!S_ISREG(s.st_mode)) return "not a regular file";
  if (s.st_uid != ::geteuid())
    return "owned by another user (uid " + std::to_string(s.st_uid) + ")";
  if ((s.st_mode & (S_IWGRP | S_IWOTH)) != 0) return "writable by group or others";
  return "";
}

// Opens an entry file for reading without following a symbolic link; -1 when it does not exist.
// Throws std::runtime_error with the reason when it exists but cannot be trusted.
int open_entry_file(const fs::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    if (errno == ENOENT) return -1;
    throw std::runtime_error(system_error(path.filename().string()));
  }
  struct stat s {};
  std::string why = ::fstat(fd, &s) != 0 ? system_error("fstat") : untrusted_file_reason(s);
  if (!why.empty()) {
    ::close(fd);
    throw std::runtime_error(path.filename().string() + " is " + why);
  }
  return fd;
}

void sync_descriptor(int fd, const fs::path& path) {
  if (::fsync(fd) != 0) throw std::runtime_error(system_error("cannot sync " + path.string()));
}

void sync_directory(const fs::path& directory) {
  const Descriptor fd(::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC));
  if (fd.get() < 0) throw std::runtime_error(system_error("cannot open " + directory.string()));
  sync_descriptor(fd.get(), directory);
}

// Creates `directory` and its missing parents, each with mode 0700 (whatever the umask).
void create_private_directories(const fs::path& directory) {
  std::error_code error;
  if (fs::is_directory(directory, error)) return;
  if (directory.has_parent_path() && directory.parent_path() != directory) {
    create_private_directories(directory.parent_path());
  }
  if (::mkdir(directory.c_str(), 0700) != 0 && errno != EEXIST) {
    throw std::runtime_error(system_error("cannot create " + directory.string()));
  }
}

// The cache directory the user configured, and where the setting came from; "" when none.
std::pair<fs::path, std::string> configured_directory(const std::string& configured) {
  if (!configured.empty()) return {configured, "the cache directory given"};
  if (const std::string d = environment_variable("UNIDYN_CACHE_DIR"); !d.empty()) {
    return {d, "UNIDYN_CACHE_DIR"};
  }
  // the XDG base directory specification ignores relative paths
  if (const std::string d = environment_variable("XDG_CACHE_HOME"); !d.empty() && d[0] == '/') {
    return {fs::path(d) / "unidyn", "XDG_CACHE_HOME"};
  }
  if (const std::string d = environment_variable("HOME"); !d.empty() && d[0] == '/') {
    return {fs::path(d) / ".cache" / "unidyn", "HOME"};
  }
  return {};
}

// The directory for private temporary ones: $TMPDIR when absolute, else /tmp.
fs::path temporary_parent() {
  const std::string d = environment_variable("TMPDIR");
  return !d.empty() && d[0] == '/' ? fs::path(d) : fs::path("/tmp");
}

// Why code kept in `directory` could be replaced by someone else, or "". With `private_directory`
// the directory itself must be the user's and closed to others; otherwise (a parent for mkdtemp)
// it is held to the rule of the directories above.
std::string untrusted_path_reason(const fs::path& directory, bool private_directory) {
  char* resolved = ::realpath(directory.c_str(), nullptr);
  if (resolved == nullptr) return system_error("cannot resolve " + directory.string());
  const fs::path real(resolved);
  std::free(resolved);
  const uid_t me = ::geteuid();
  fs::path prefix;
  for (const fs::path& part : real) {
    prefix /= part;
    struct stat s {};
    if (::lstat(prefix.c_str(), &s) != 0) return system_error("cannot inspect " + prefix.string());
    if (!S_ISDIR(s.st_mode)) return prefix.string() + " is not a directory";
    const bool others_write = (s.st_mode & (S_IWGRP | S_IWOTH)) != 0;
    if (prefix == real && private_directory) {
      if (s.st_uid != me) {
        return real.string() + " is owned by another user (uid " + std::to_string(s.st_uid) + ")";
      }
      if (others_write) return real.string() + " is writable by group or others";
    } else {
      if (s.st_uid != me && s.st_uid != 0) {
        return prefix.string() + " is owned by another user (uid " + std::to_string(s.st_uid) + ")";
      }
      if (others_write && (s.st_mode & S_ISVTX) == 0) {
        return prefix.string() + " is writable by others without the sticky bit";
      }
    }
  }
  return "";
}

}  // namespace

std::string untrusted_directory_reason(const fs::path& directory) {
  return untrusted_path_reason(directory, true);
}

CacheLocation::CacheLocation(const std::string& configured) {
  const auto [directory, source] = configured_directory(configured);
  if (directory.empty()) {
    note_ = "not cached: no cache directory (UNIDYN_CACHE_DIR, XDG_CACHE_HOME and HOME are unset)";
  } else {
    std::string why;
    try {
      create_private_directories(directory);
      why = untrusted_directory_reason(directory);
    } catch (const std::runtime_error& e) {
      why = e.what();
    }
    if (why.empty()) {
      directory_ = directory;
      persistent_ = true;
      return;
    }
    note_ = "not cached: the cache directory from " + source + " is not used: " + why;
  }
  // a private temporary directory, in a parent that is itself trusted
  const fs::path parent = temporary_parent();
  if (const std::string why = untrusted_path_reason(parent, false); !why.empty()) {
    throw std::runtime_error(note_ + "; and no private temporary directory: " + why);
  }
  std::string pattern = (parent / "unidyn-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(system_error(note_ + "; and no private temporary directory"));
  }
  directory_ = pattern;
}

CacheLocation::~CacheLocation() {
  if (persistent_ || directory_.empty()) return;
  std::error_code error;
  fs::remove_all(directory_, error);
}

EntryLock::EntryLock(const fs::path& directory, const std::string& name, bool exclusive,
                     double wait_seconds) {
  const fs::path path = directory / (name + ".lock");
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0600);
  if (fd_ < 0) throw std::runtime_error(system_error("cannot open " + path.string()));
  struct stat s {};
  std::string why = ::fstat(fd_, &s) != 0 ? system_error("fstat") : untrusted_file_reason(s);
  if (why.empty() && (s.st_mode & 0777) != 0600) {
    // made by us under a permissive umask: the mode open() asked for, exactly
    if (::fchmod(fd_, 0600) != 0) why = system_error("chmod");
  }
  if (!why.empty()) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error(path.string() + ": " + why);
  }
  // polled, with a bound: another unidyn compiling the same model lets go within a minute or
  // two, one that is stopped (Ctrl-Z, SIGSTOP) never does
  const int operation = (exclusive ? LOCK_EX : LOCK_SH) | LOCK_NB;
  const auto start = std::chrono::steady_clock::now();
  while (::flock(fd_, operation) != 0) {
    waited_seconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::string message;
    if (errno != EWOULDBLOCK && errno != EINTR) {
      message = system_error("cannot lock " + path.string());
    } else if (waited_seconds_ > wait_seconds) {
      char seconds[32];
      std::snprintf(seconds, sizeof seconds, "%g", wait_seconds);
      message = "another unidyn has held " + path.string() + " for " + seconds +
                " s (compiling this model, or stopped): not waiting longer";
    }
    if (!message.empty()) {
      ::close(fd_);
      fd_ = -1;
      throw std::runtime_error(message);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

EntryLock::~EntryLock() {
  if (fd_ >= 0) ::close(fd_);  // releases the lock
}

CacheEntry inspect_entry(const fs::path& directory, const std::string& name) {
  CacheEntry entry;
  entry.library = directory / (name + ".so");
  const fs::path sum = directory / (name + ".sum");
  try {
    const Descriptor library(open_entry_file(entry.library));
    const Descriptor checksum(open_entry_file(sum));
    if (library.get() < 0 && checksum.get() < 0) return entry;  // missing
    entry.state = CacheEntry::State::damaged;
    if (library.get() < 0 || checksum.get() < 0) {
      entry.why = library.get() < 0 ? "the library is missing" : "its checksum is missing";
      return entry;
    }
    // <name>.sum: "sha256 <64 hex digits> size <bytes>\n"
    char text[256] = {};
    const ssize_t n = ::read(checksum.get(), text, sizeof text - 1);
    char digest[65] = {};
    unsigned long long size = 0;
    if (n <= 0 || std::sscanf(text, "sha256 %64s size %llu", digest, &size) != 2) {
      entry.why = "its checksum file is unreadable";
      return entry;
    }
    struct stat s {};
    if (::fstat(library.get(), &s) != 0) throw std::runtime_error(system_error("fstat"));
    if (static_cast<unsigned long long>(s.st_size) != size) {
      entry.why = "the library has " + std::to_string(s.st_size) + " bytes, its checksum says " +
                  std::to_string(size);
      return entry;
    }
    const FileDigest actual = sha256_of_descriptor(library.get());
    if (actual.sha256 != digest || actual.size != size) {
      entry.why = "the library's bytes do not match its checksum";
      return entry;
    }
    entry.state = CacheEntry::State::intact;
    entry.device = s.st_dev;
    entry.inode = s.st_ino;
  } catch (const std::runtime_error& e) {
    entry.state = CacheEntry::State::damaged;
    entry.why = e.what();
  }
  return entry;
}

void remove_entry(const fs::path& directory, const std::string& name) {
  // unlink removes a symbolic link itself, never what it points to
  ::unlink((directory / (name + ".sum")).c_str());
  ::unlink((directory / (name + ".so")).c_str());
}

void store_entry(const fs::path& directory, const std::string& name,
                 const fs::path& compiled_library) {
  // the compiler's output: ours, made private, synced, and its checksum taken from the same bytes
  const Descriptor library(::open(compiled_library.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC));
  if (library.get() < 0) throw std::runtime_error(system_error(compiled_library.string()));
  if (::fchmod(library.get(), 0600) != 0) throw std::runtime_error(system_error("chmod"));
  sync_descriptor(library.get(), compiled_library);
  const FileDigest digest = sha256_of_descriptor(library.get());
  const fs::path sum = compiled_library.parent_path() / "checksum";
  write_new_file(sum, "sha256 " + digest.sha256 + " size " + std::to_string(digest.size) + "\n");
  // the library first: a library without its checksum is damaged, never loaded
  if (::rename(compiled_library.c_str(), (directory / (name + ".so")).c_str()) != 0 ||
      ::rename(sum.c_str(), (directory / (name + ".sum")).c_str()) != 0) {
    throw std::runtime_error(system_error("cannot store " + name + " in " + directory.string()));
  }
  sync_directory(directory);
}

namespace {

// Removes <parent>/<prefix>-<pid>-XXXXXX of every process that no longer exists: what a run
// killed while compiling left (SIGKILL, a power cut).
void remove_abandoned_build_directories(const fs::path& parent, const std::string& prefix) {
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(parent, error)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with(prefix + "-") || !entry.is_directory(error)) continue;
    const std::string rest = name.substr(prefix.size() + 1);
    const std::size_t dash = rest.find('-');
    if (dash == std::string::npos || dash == 0 || dash > 9) continue;
    if (rest.find_first_not_of("0123456789") != dash) continue;
    const auto pid = static_cast<pid_t>(std::stol(rest.substr(0, dash)));
    if (::kill(pid, 0) != 0 && errno == ESRCH) fs::remove_all(entry.path(), error);
  }
}

}  // namespace

BuildDirectory::BuildDirectory(const fs::path& parent, const std::string& prefix) {
  remove_abandoned_build_directories(parent, prefix);
  std::string pattern = (parent / (prefix + "-" + std::to_string(::getpid()) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr) {
    throw std::runtime_error(system_error("cannot create a build directory in " + parent.string()));
  }
  path_ = pattern;
}

BuildDirectory::~BuildDirectory() {
  std::error_code error;
  fs::remove_all(path_, error);
}

void write_new_file(const fs::path& path, std::string_view text) {
  const Descriptor fd(
      ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600));
  if (fd.get() < 0) throw std::runtime_error(system_error("cannot create " + path.string()));
  for (std::size_t done = 0; done < text.size();) {
    const ssize_t n = ::write(fd.get(), text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw std::runtime_error(system_error("cannot write " + path.string()));
    done += static_cast<std::size_t>(n);
  }
  sync_descriptor(fd.get(), path);
}

}  // namespace unidyn
