// The on-disk cache of compiled native code, and the file-system rules that make it safe to load
// code from it (the threat model is in the README, "Native code and its cache"):
// - a directory is trusted only when it is ours and nobody else can write into it or replace it
//   (OpenSSH's StrictModes rule): the directory is owned by the user and not group- or
//   world-writable; each directory above it is owned by root or the user and, if others may
//   write into it, has the sticky bit;
// - each entry (<name>.so, its checksum <name>.sum, its lock <name>.lock) is opened without
//   following symbolic links and must be a regular file of the user's, not group- or
//   world-writable;
// - an entry is stored complete or not at all: written in a private build directory, synced to
//   disk, then renamed into place, and the directory synced; a library is loaded only after its
//   bytes match the SHA-256 of its checksum file;
// - one process compiles an entry while the others wait (an exclusive flock on <name>.lock; a
//   reader holds it shared while it checks and loads).
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace unidyn {

// The environment variable `name`'s value, or "" when it is not set.
std::string environment_variable(const char* name);

// Why `directory` cannot hold code that we load, or "" when it can. It must exist.
std::string untrusted_directory_reason(const std::filesystem::path& directory);

// Where libraries go: `configured` when given, else $UNIDYN_CACHE_DIR, else $XDG_CACHE_HOME/unidyn,
// else $HOME/.cache/unidyn (absolute paths only), created with mode 0700 when missing. When there
// is none, or it is not trusted, a private temporary directory (mkdtemp under $TMPDIR or /tmp)
// that nothing else uses and that is removed when this object dies; `note` then says why.
class CacheLocation {
 public:
  explicit CacheLocation(const std::string& configured);
  ~CacheLocation();
  CacheLocation(const CacheLocation&) = delete;
  CacheLocation& operator=(const CacheLocation&) = delete;

  const std::filesystem::path& directory() const { return directory_; }
  // Whether entries outlive this process (false: a private temporary directory).
  bool persistent() const { return persistent_; }
  // Why the cache is not used ("" when it is).
  const std::string& note() const { return note_; }

 private:
  std::filesystem::path directory_;
  bool persistent_ = false;
  std::string note_;
};

// A flock on <directory>/<name>.lock: exclusive while an entry is made or removed, shared while
// one is checked and loaded. Released when this object dies. Waited for at most
// kLockWaitSeconds (then std::runtime_error: the caller goes on without native code).
inline constexpr double kLockWaitSeconds = 120.0;
class EntryLock {
 public:
  EntryLock(const std::filesystem::path& directory, const std::string& name, bool exclusive,
            double wait_seconds = kLockWaitSeconds);
  ~EntryLock();
  EntryLock(const EntryLock&) = delete;
  EntryLock& operator=(const EntryLock&) = delete;
  // Seconds spent waiting for another process's lock.
  double waited_seconds() const { return waited_seconds_; }

 private:
  int fd_ = -1;
  double waited_seconds_ = 0;
};

// The state of one entry: its library <name>.so, checked against <name>.sum.
struct CacheEntry {
  enum class State { missing, intact, damaged };
  State state = State::missing;
  std::filesystem::path library;
  std::string why;   // for a damaged entry
  dev_t device = 0;  // the checked library file's identity, compared after loading
  ino_t inode = 0;
};

// Looks at an entry without changing it.
CacheEntry inspect_entry(const std::filesystem::path& directory, const std::string& name);

// Removes an entry's library and checksum (not its lock).
void remove_entry(const std::filesystem::path& directory, const std::string& name);

// Moves a compiled library (in a private build directory on the same file system) into place as
// entry `name`: mode 0600, synced, its checksum written and synced, both renamed, the directory
// synced. Throws std::runtime_error.
void store_entry(const std::filesystem::path& directory, const std::string& name,
                 const std::filesystem::path& compiled_library);

// A private directory for one compilation: mkdtemp(<parent>/build-<pid>-XXXXXX), mode 0700,
// removed with everything in it when this object dies. Those of processes that no longer exist
// (killed while compiling) are removed first.
class BuildDirectory {
 public:
  explicit BuildDirectory(const std::filesystem::path& parent, const std::string& prefix = "build");
  ~BuildDirectory();
  BuildDirectory(const BuildDirectory&) = delete;
  BuildDirectory& operator=(const BuildDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

// Writes `text` to a new file (O_CREAT|O_EXCL|O_NOFOLLOW, mode 0600), synced. Throws
// std::runtime_error.
void write_new_file(const std::filesystem::path& path, std::string_view text);

}  // namespace unidyn
