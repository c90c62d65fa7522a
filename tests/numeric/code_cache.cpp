// The native-code cache's file-system rules (numeric/code_cache.hpp): which directories are
// trusted, the private temporary directory when none is, entries checked against their checksum,
// and the lock that lets one process make an entry at a time.
#include "unidyn/numeric/code_cache.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <thread>

#include "unidyn/numeric/digest.hpp"

namespace unidyn {
namespace {

namespace fs = std::filesystem;

// A fresh directory of the test's, mode 0700.
fs::path fresh_directory(const std::string& name) {
  const fs::path path = fs::path(::testing::TempDir()) / ("unidyn-code-cache-" + name);
  fs::remove_all(path);
  fs::create_directories(path);
  fs::permissions(path, fs::perms::owner_all);
  return path;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

mode_t mode_of(const fs::path& path) {
  struct stat s {};
  EXPECT_EQ(::lstat(path.c_str(), &s), 0) << path;
  return s.st_mode & 07777;
}

// An environment variable set (or unset) for one scope.
class ScopedEnvironment {
 public:
  ScopedEnvironment(const char* name, const char* value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value != nullptr) {
      ::setenv(name, value, 1);
    } else {
      ::unsetenv(name);
    }
  }
  ~ScopedEnvironment() {
    if (old_) {
      ::setenv(name_, old_->c_str(), 1);
    } else {
      ::unsetenv(name_);
    }
  }
  ScopedEnvironment(const ScopedEnvironment&) = delete;
  ScopedEnvironment& operator=(const ScopedEnvironment&) = delete;

 private:
  const char* name_;
  std::optional<std::string> old_;
};

// SHA-256 against the FIPS 180-2 test vectors.
TEST(CodeCache, Sha256OfTheStandardVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

// A directory is trusted when it is ours and closed to others, and each one above it is root's or
// ours and, when others may write into it, sticky (OpenSSH's StrictModes rule).
TEST(CodeCache, WhichDirectoriesAreTrusted) {
  const fs::path mine = fresh_directory("trusted");
  EXPECT_EQ(untrusted_directory_reason(mine), "");
  // writable by others
  fs::permissions(mine, fs::perms::all);
  EXPECT_TRUE(contains(untrusted_directory_reason(mine), "writable by group or others"));
  fs::permissions(mine, fs::perms::owner_all | fs::perms::group_all);
  EXPECT_TRUE(contains(untrusted_directory_reason(mine), "writable by group or others"));
  // below a directory others may write into, without the sticky bit: they could replace it
  fs::permissions(mine, fs::perms::all);
  const fs::path below = mine / "cache";
  fs::create_directory(below);
  fs::permissions(below, fs::perms::owner_all);
  EXPECT_TRUE(contains(untrusted_directory_reason(below), "without the sticky bit"))
      << untrusted_directory_reason(below);
  // with the sticky bit (as /tmp) they cannot
  fs::permissions(mine, fs::perms::all | fs::perms::sticky_bit);
  EXPECT_EQ(untrusted_directory_reason(below), "");
  // through a symbolic link: the directory it resolves to is judged
  const fs::path link = fresh_directory("trusted-link") / "link";
  fs::create_directory_symlink(mine, link);
  EXPECT_TRUE(contains(untrusted_directory_reason(link), "writable by group or others"));
  // a file is not a directory; a missing one cannot be resolved
  std::ofstream(below / "file") << "x";
  EXPECT_TRUE(contains(untrusted_directory_reason(below / "file"), "not a directory"));
  EXPECT_FALSE(untrusted_directory_reason(below / "missing").empty());
  // owned by another user (root can make one)
  if (::geteuid() == 0) {
    const fs::path theirs = fresh_directory("theirs");
    ASSERT_EQ(::chown(theirs.c_str(), 65534, 65534), 0);
    EXPECT_TRUE(contains(untrusted_directory_reason(theirs), "owned by another user"));
  }
}

// An untrusted cache directory is not used: the library goes to a private temporary directory,
// nothing is written where others could write, and the note says why.
TEST(CodeCache, AnUntrustedDirectoryIsNotUsed) {
  const fs::path open_to_all = fresh_directory("open-to-all");
  fs::permissions(open_to_all, fs::perms::all);
  fs::path temporary;
  {
    const CacheLocation location(open_to_all.string());
    EXPECT_FALSE(location.persistent());
    EXPECT_TRUE(contains(location.note(), "not cached")) << location.note();
    EXPECT_TRUE(contains(location.note(), "writable by group or others")) << location.note();
    temporary = location.directory();
    EXPECT_NE(temporary, open_to_all);
    EXPECT_EQ(mode_of(temporary), 0700u);
    EXPECT_EQ(untrusted_directory_reason(temporary), "");
  }
  EXPECT_FALSE(fs::exists(temporary));  // removed with the location
  EXPECT_TRUE(fs::is_empty(open_to_all));
}

// Without HOME, XDG_CACHE_HOME and UNIDYN_CACHE_DIR there is no fixed shared name (once
// /tmp/unidyn-cache, which another user could create first): a private mkdtemp directory in TMPDIR.
TEST(CodeCache, NoHomeMeansAPrivateTemporaryDirectory) {
  const fs::path tmp = fresh_directory("tmpdir");
  const ScopedEnvironment home("HOME", nullptr), xdg("XDG_CACHE_HOME", nullptr),
      own("UNIDYN_CACHE_DIR", nullptr), tmpdir("TMPDIR", tmp.c_str());
  fs::path first, second;
  {
    const CacheLocation a(""), b("");
    EXPECT_FALSE(a.persistent());
    EXPECT_TRUE(contains(a.note(), "HOME")) << a.note();
    first = a.directory();
    second = b.directory();
    EXPECT_EQ(first.parent_path(), tmp);
    EXPECT_NE(first, second);  // unpredictable, one per process and build
    EXPECT_EQ(mode_of(first), 0700u);
  }
  EXPECT_TRUE(fs::is_empty(tmp));
  // relative paths do not count (the XDG base directory specification)
  const ScopedEnvironment relative("XDG_CACHE_HOME", "relative/cache");
  const CacheLocation c("");
  EXPECT_FALSE(c.persistent());
}

// The configured directory is created 0700 (and the missing ones above it), under any umask.
TEST(CodeCache, CreatedPrivate) {
  const fs::path base = fresh_directory("created");
  const mode_t previous = ::umask(0);
  {
    const ScopedEnvironment own("UNIDYN_CACHE_DIR", (base / "x/y").c_str());
    const CacheLocation location("");
    EXPECT_TRUE(location.persistent()) << location.note();
    EXPECT_EQ(location.directory(), base / "x/y");
  }
  ::umask(previous);
  EXPECT_EQ(mode_of(base / "x"), 0700u);
  EXPECT_EQ(mode_of(base / "x/y"), 0700u);
}

// An entry is intact only when its library and checksum are the user's regular files and the
// library's bytes are the ones summed.
TEST(CodeCache, EntriesAreCheckedAgainstTheirChecksum) {
  const fs::path cache = fresh_directory("entries");
  EXPECT_EQ(inspect_entry(cache, "e").state, CacheEntry::State::missing);
  // stored from a build directory: 0600, with its checksum
  {
    const BuildDirectory build(cache);
    EXPECT_EQ(mode_of(build.path()), 0700u);
    write_new_file(build.path() / "library.so", "library bytes");
    store_entry(cache, "e", build.path() / "library.so");
  }
  CacheEntry entry = inspect_entry(cache, "e");
  EXPECT_EQ(entry.state, CacheEntry::State::intact) << entry.why;
  EXPECT_EQ(mode_of(cache / "e.so"), 0600u);
  EXPECT_EQ(mode_of(cache / "e.sum"), 0600u);
  EXPECT_EQ(std::distance(fs::directory_iterator(cache), fs::directory_iterator()), 2);
  // the same size, other bytes
  fs::remove(cache / "e.so");
  write_new_file(cache / "e.so", "LIBRARY BYTES");
  entry = inspect_entry(cache, "e");
  EXPECT_EQ(entry.state, CacheEntry::State::damaged);
  EXPECT_TRUE(contains(entry.why, "do not match")) << entry.why;
  // cut short
  fs::resize_file(cache / "e.so", 3);
  EXPECT_TRUE(contains(inspect_entry(cache, "e").why, "has 3 bytes"));
  // writable by others
  fs::permissions(cache / "e.so", fs::perms::all);
  EXPECT_TRUE(contains(inspect_entry(cache, "e").why, "writable by group or others"));
  // a symbolic link is not followed
  fs::remove(cache / "e.so");
  fs::create_symlink(cache / "e.sum", cache / "e.so");
  EXPECT_EQ(inspect_entry(cache, "e").state, CacheEntry::State::damaged);
  remove_entry(cache, "e");
  EXPECT_EQ(inspect_entry(cache, "e").state, CacheEntry::State::missing);
  // write_new_file never writes through an existing name (nor a link)
  fs::create_symlink(cache / "target", cache / "planted");
  EXPECT_THROW(write_new_file(cache / "planted", "x"), std::runtime_error);
  EXPECT_FALSE(fs::exists(cache / "target"));
}

// An exclusive lock makes the next one wait until it is released.
TEST(CodeCache, OneProcessMakesAnEntryAtATime) {
  const fs::path cache = fresh_directory("lock");
  std::atomic<bool> released{false};
  double waited = 0;
  std::optional<EntryLock> first;
  first.emplace(cache, "e", true);
  std::thread second([&] {
    const EntryLock lock(cache, "e", false);
    EXPECT_TRUE(released.load());
    waited = lock.waited_seconds();
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  released = true;
  first.reset();
  second.join();
  EXPECT_GT(waited, 0.1);
  EXPECT_EQ(mode_of(cache / "e.lock"), 0600u);
}

// A lock held for good (a unidyn stopped with Ctrl-Z while compiling) is waited for with a bound,
// then the wait is given up with the reason (the run goes on on the tape); it used to wait forever.
TEST(CodeCache, ALockHeldForGoodIsWaitedForWithABound) {
  const fs::path cache = fresh_directory("stuck");
  const EntryLock held(cache, "e", true);
  const auto start = std::chrono::steady_clock::now();
  try {
    const EntryLock waiting(cache, "e", true, 0.3);
    ADD_FAILURE() << "a held lock was taken";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("for 0.3 s (compiling this model, or stopped): not "
                                         "waiting longer"),
              std::string::npos)
        << e.what();
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(seconds, 0.3);
  EXPECT_LT(seconds, 2.0);
}

// A build directory left by a process that no longer exists (killed while compiling) is removed
// by the next compilation; one of a live process, and anything else, is left alone.
TEST(CodeCache, AbandonedBuildDirectoriesAreRemoved) {
  const fs::path cache = fresh_directory("abandoned");
  // a pid no process has: past the kernel's pid_max (at most 2^22)
  fs::create_directories(cache / "build-99999999-AbCdEf");
  fs::create_directories(cache / ("build-" + std::to_string(::getppid()) + "-Living"));
  fs::create_directories(cache / "build-notapid-Xyz");
  {
    const BuildDirectory build(cache);
    EXPECT_TRUE(
        build.path().filename().string().starts_with("build-" + std::to_string(::getpid()) + "-"));
  }
  EXPECT_FALSE(fs::exists(cache / "build-99999999-AbCdEf"));
  EXPECT_TRUE(fs::exists(cache / ("build-" + std::to_string(::getppid()) + "-Living")));
  EXPECT_TRUE(fs::exists(cache / "build-notapid-Xyz"));
}

}  // namespace
}  // namespace unidyn
