// Native code: the tapes' source, compiled by the system compiler, kept in the cache under the
// SHA-256 of its key, and loaded with dlopen only after the library has shown its key and
// signature.
#include "unidyn/numeric/native_code.hpp"
#include "unidyn/numeric/shell_quoting.hpp"

#include <dlfcn.h>
#include <pthread.h>
#include <signal.h>
#include <spawn.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "unidyn/numeric/code_cache.hpp"
#include "unidyn/numeric/digest.hpp"

#ifndef UNIDYN_VERSION
#define UNIDYN_VERSION "unknown"
#endif

namespace unidyn {
namespace {

namespace fs = std::filesystem;

// The compiler as the shell finds it (through PATH when it has no slash), resolved to its file.
fs::path resolve_executable(const std::string& command) {
  std::vector<fs::path> candidates;
  if (command.find('/') != std::string::npos) {
    candidates.emplace_back(command);
  } else {
    std::stringstream path(environment_variable("PATH"));
    for (std::string directory; std::getline(path, directory, ':');) {
      candidates.push_back(fs::path(directory.empty() ? "." : directory) / command);
    }
  }
  for (const fs::path& candidate : candidates) {
    if (::access(candidate.c_str(), X_OK) != 0) continue;
    char* resolved = ::realpath(candidate.c_str(), nullptr);
    if (resolved == nullptr) continue;
    const fs::path file(resolved);
    std::free(resolved);
    return file;
  }
  return {};
}

// The compiler's identity: its resolved file, size and time of change. A changed compiler (an
// upgrade, another alternative) gives other code, so another key.
std::string compiler_identity(const std::string& compiler) {
  const fs::path file = resolve_executable(compiler);
  struct stat s {};
  if (file.empty() || ::stat(file.c_str(), &s) != 0) return compiler + " (not found)";
  return compiler + " = " + file.string() + " " + std::to_string(s.st_size) + " bytes, changed " +
         std::to_string(s.st_mtim.tv_sec) + "." + std::to_string(s.st_mtim.tv_nsec);
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// What a library must say of itself before it is called: its key (SHA-256 of the key text), its
// signature (one line per function: name, inputs, outputs) and, when freshly compiled, the SHA-256
// of the functions' source ("" when any will do: a cached library of this key).
struct Identity {
  std::string key;
  std::string signature;
  std::string source;
};

// The C++ definitions through which a library says what it is.
std::string identity_definitions(const Identity& identity) {
  std::string text = "\nextern \"C\" const char unidyn_library_key[] = \"" + identity.key + "\";\n";
  text += "extern \"C\" const char unidyn_library_source[] = \"" + identity.source + "\";\n";
  text += "extern \"C\" const char unidyn_library_signature[] =\n";
  std::stringstream lines(identity.signature);
  for (std::string line; std::getline(lines, line);) text += "    \"" + line + "\\n\"\n";
  return text + "    \"\";\n";
}

// A library that does not prove to be the one expected.
class Refused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// This process already has another library loaded under the entry's file name (only two keys that
// share a name can do that): dlopen would return it again, so the entry cannot be loaded here.
class NameTaken : public NativeCodeError {
 public:
  using NativeCodeError::NativeCodeError;
};

// dlopen the checked library file and compare what it says of itself with `expected` before any
// of its functions is looked up. Throws Refused (nothing kept loaded) when anything differs.
void* load_checked(const CacheEntry& entry, const Identity& expected) {
  // dlopen returns a library already loaded under this name, whatever the file now holds
  void* handle = ::dlopen(entry.library.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NOLOAD);
  const bool already_loaded = handle != nullptr;
  if (!already_loaded) handle = ::dlopen(entry.library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr) {
    const char* why = ::dlerror();
    throw Refused(std::string("it does not load: ") + (why != nullptr ? why : "unknown error"));
  }
  const auto text = [&](const char* symbol) -> std::string {
    const void* address = ::dlsym(handle, symbol);
    return address != nullptr ? static_cast<const char*>(address) : "(none)";
  };
  std::string why;
  struct stat s {};
  if (!already_loaded && (::stat(entry.library.c_str(), &s) != 0 || s.st_dev != entry.device ||
                          s.st_ino != entry.inode)) {
    why = "the file changed while it was loaded";
  } else if (text("unidyn_library_key") != expected.key) {
    why = "its key is " + text("unidyn_library_key") + ", not " + expected.key;
  } else if (text("unidyn_library_signature") != expected.signature) {
    why = "its signature differs";
  } else if (!already_loaded && !expected.source.empty() &&
             text("unidyn_library_source") != expected.source) {
    why = "its source is not the one just compiled";
  }
  if (why.empty()) return handle;
  ::dlclose(handle);
  if (already_loaded) {
    throw NameTaken("native code: this process has another library loaded from " +
                    entry.library.string() + " (" + why + ")");
  }
  throw Refused(why);
}

// The compilers running now, by process group (0: a free slot), and whether the process has
// asked them to stop: lock-free atomics, which a signal handler may read and write.
std::atomic<pid_t> g_compilers[16];
static_assert(std::atomic<pid_t>::is_always_lock_free);
std::atomic<bool> g_compilers_stopped{false};
// Compilers spawned and not yet in a slot: a stop waits for them (a process ended by the signal
// between the spawn and the slot would leave its compiler running for nobody).
std::atomic<int> g_compilers_starting{0};
static_assert(std::atomic<int>::is_always_lock_free);

// One compiler's process group in a free slot while it runs (none free: it cannot be stopped
// early, and is waited for as before).
class RunningCompiler {
 public:
  explicit RunningCompiler(pid_t group) {
    for (auto& slot : g_compilers) {
      pid_t free = 0;
      if (slot.compare_exchange_strong(free, group)) {
        slot_ = &slot;
        break;
      }
    }
    // a stop asked for between the check before spawning and here
    if (g_compilers_stopped.load()) ::kill(-group, SIGKILL);
  }
  ~RunningCompiler() {
    if (slot_ != nullptr) slot_->store(0);
  }
  RunningCompiler(const RunningCompiler&) = delete;
  RunningCompiler& operator=(const RunningCompiler&) = delete;

 private:
  std::atomic<pid_t>* slot_ = nullptr;
};

// `sh -c command`'s exit status (-1 when it could not run, -2 when it was stopped), in a process
// group of its own: stop_native_compilers() kills the shell and every compiler it started. Not
// std::system: that ignores SIGINT in the whole process while the command runs, and the compiler
// may run in a thread of its own while a simulation, which Ctrl-C must still stop, goes on.
int run_shell(const std::string& command) {
  // From the spawn to the slot: the ending signals are held in this thread (a handler run here
  // would wait for this very thread), and one taken by another thread waits for the slot.
  sigset_t ending, previous;
  sigemptyset(&ending);
  for (const int signal : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&ending, signal);
  ::pthread_sigmask(SIG_BLOCK, &ending, &previous);
  ++g_compilers_starting;
  const auto started = [&] {
    --g_compilers_starting;
    ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  };
  if (g_compilers_stopped.load()) {
    started();
    return -2;
  }
  const char* arguments[] = {"sh", "-c", command.c_str(), nullptr};
  posix_spawnattr_t attributes;
  ::posix_spawnattr_init(&attributes);
  ::posix_spawnattr_setpgroup(&attributes, 0);
  // the compiler with the signal mask this process had, not the one held here
  ::posix_spawnattr_setsigmask(&attributes, &previous);
  ::posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  pid_t child = 0;
  const int error = ::posix_spawn(&child, "/bin/sh", nullptr, &attributes,
                                  const_cast<char* const*>(arguments), environ);
  ::posix_spawnattr_destroy(&attributes);
  if (error != 0) {
    started();
    return -1;
  }
  const RunningCompiler running(child);
  started();
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  if (WIFSIGNALED(status) && g_compilers_stopped.load()) return -2;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Compiles `source` in the private directory `build`; returns the library's path.
fs::path compile(const std::string& compiler, const std::string& flags, const std::string& source,
                 const fs::path& build, double& seconds) {
  const fs::path cpp = build / "library.cpp", library = build / "library.so",
                 log = build / "compiler.log";
  write_new_file(cpp, source);
  const std::string command = shell_quoted(compiler) + " " + flags + " -o " +
                              shell_quoted(library.string()) + " " + shell_quoted(cpp.string()) +
                              " > " + shell_quoted(log.string()) + " 2>&1";
  const auto start = std::chrono::steady_clock::now();
  const int status = run_shell(command);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (status == -2) throw NativeCodeError("native code: the compiler was stopped (a signal)");
  std::error_code error;
  if (status != 0 || !fs::exists(library, error)) {
    const std::string diagnostics = read_text(log);
    throw NativeCodeError("native code: '" + compiler + " " + flags + "' failed (status " +
                          std::to_string(status) + ")" +
                          (diagnostics.empty() ? "" : ": " + diagnostics.substr(0, 2000)));
  }
  return library;
}

// The entry of a file outside the cache (a private temporary directory): intact by construction.
CacheEntry private_entry(const fs::path& library) {
  CacheEntry entry;
  entry.library = library;
  struct stat s {};
  if (::stat(library.c_str(), &s) != 0) throw NativeCodeError("native code: " + library.string());
  entry.state = CacheEntry::State::intact;
  entry.device = s.st_dev;
  entry.inode = s.st_ino;
  return entry;
}

std::string seconds_text(double seconds) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", seconds);
  return buffer;
}

// The x86-64 micro-architecture level of this processor as a compiler flag (GCC's and Clang's
// -march=x86-64-v2, -v3, -v4), unless the flags name a target already. The code is the tape's
// straight-line arithmetic, IEEE without contraction at any level, so the numbers are the same;
// what changes is the encoding: with AVX-512's 32 vector registers (v4) the recorded
// articulated-body algorithm of a 7-DoF arm (1 820 operations, most values live across several
// joints) runs in 0.33 µs instead of 0.54 µs with SSE2's 16 (bench/, one machine). The level is
// part of the flags, and so of the cache's key: a processor of another level (a cluster's other
// nodes sharing a cache directory) compiles its own library rather than loading one it cannot run.
std::string with_instruction_set(const std::string& flags) {
  if (flags.find("-march=") != std::string::npos || flags.find("-mcpu=") != std::string::npos) {
    return flags;
  }
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
  __builtin_cpu_init();
  const bool v2 = __builtin_cpu_supports("sse4.2") && __builtin_cpu_supports("popcnt") &&
                  __builtin_cpu_supports("ssse3");
  const bool v3 = v2 && __builtin_cpu_supports("avx") && __builtin_cpu_supports("avx2") &&
                  __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2") &&
                  __builtin_cpu_supports("fma") && __builtin_cpu_supports("f16c");
  const bool v4 = v3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                  __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                  __builtin_cpu_supports("avx512vl");
  if (v4) return flags + " -march=x86-64-v4";
  if (v3) return flags + " -march=x86-64-v3";
  if (v2) return flags + " -march=x86-64-v2";
#endif
  return flags;
}

}  // namespace

std::shared_ptr<const NativeLibrary> NativeLibrary::build(
    const std::vector<std::pair<std::string, const Tape*>>& functions,
    const NativeOptions& options) {
  // The functions' source, their signature, and the compiler.
  std::string body;  // (no header: the functions are the compiler's builtins)
  Identity identity;
  for (const auto& [name, tape] : functions) {
    body += "\n" + tape_source(*tape, name);
    identity.signature += name + " " + std::to_string(tape->input_count()) + " " +
                          std::to_string(tape->output_count()) + "\n";
  }
  identity.source = sha256_hex(body);
  std::string compiler = options.compiler;
  if (compiler.empty()) compiler = environment_variable("CXX");
  if (compiler.empty()) compiler = "c++";
  const std::string flags = with_instruction_set(options.flags);
  // The key: everything that determines the library — the source itself too, so that a library
  // is only ever the one this process would compile (another build of unidyn may order the same
  // equations' operations otherwise, and its numbers would differ from the tape's in their last
  // bits).
  const std::string key_text = "unidyn native code v3\nunidyn " UNIDYN_VERSION "\ncompiler " +
                               compiler_identity(compiler) + "\nflags " + flags + "\n" +
                               identity.signature + "source " + identity.source + "\nkey\n" +
                               (options.key.empty() ? body : options.key);
  identity.key = sha256_hex(key_text);
  const std::string name = options.entry_name ? options.entry_name(key_text) : identity.key;
  const std::string source =
      "// generated by unidyn: compiled equations\n" + body + identity_definitions(identity);

  std::shared_ptr<NativeLibrary> library(new NativeLibrary);
  library->source_bytes_ = source.size();
  const auto note = [&](const std::string& text) {
    library->notes_ += (library->notes_.empty() ? "" : "; ") + text;
  };
  const auto accept = [&](void* handle, const CacheEntry& entry) {
    library->handle_ = handle;
    library->path_ = entry.library.string();
    return library;
  };
  try {
    const CacheLocation location(options.cache_directory);
    note(location.note());
    if (options.only_cached && !location.persistent()) throw NotCached("native code: no cache");
    if (!location.persistent()) {
      // compiled and loaded from a private temporary directory, removed after loading
      library->kept_ = false;
      const CacheEntry entry = private_entry(
          compile(compiler, flags, source, location.directory(), library->compile_seconds_));
      return accept(load_checked(entry, identity), entry);
    }
    const fs::path& directory = location.directory();
    // A cached library: checked and loaded while nobody may replace it.
    {
      const EntryLock shared(directory, name, false);
      if (shared.waited_seconds() > 0.01) {
        note("waited " + seconds_text(shared.waited_seconds()) + " s for another compilation");
      }
      const CacheEntry entry = inspect_entry(directory, name);
      if (entry.state == CacheEntry::State::intact) {
        try {
          library->cached_ = true;
          return accept(load_checked(entry, {identity.key, identity.signature, ""}), entry);
        } catch (const Refused&) {
          library->cached_ = false;  // decided below, under the exclusive lock
        }
      }
    }
    if (options.only_cached) throw NotCached("native code: not cached yet");
    // Made by one process at a time: the others wait for it here and then find it cached.
    const EntryLock exclusive(directory, name, true);
    if (exclusive.waited_seconds() > 0.01) {
      note("waited " + seconds_text(exclusive.waited_seconds()) + " s for another compilation");
    }
    CacheEntry entry = inspect_entry(directory, name);
    std::string refused = entry.state == CacheEntry::State::damaged ? entry.why : "";
    if (entry.state == CacheEntry::State::intact) {
      try {
        library->cached_ = true;
        return accept(load_checked(entry, {identity.key, identity.signature, ""}), entry);
      } catch (const Refused& why) {
        library->cached_ = false;
        refused = why.what();
      }
    }
    if (!refused.empty()) {
      remove_entry(directory, name);
      note("the cached library " + name + ".so was refused (" + refused + ") and compiled again");
    }
    const BuildDirectory build(directory);
    store_entry(directory, name,
                compile(compiler, flags, source, build.path(), library->compile_seconds_));
    entry = inspect_entry(directory, name);
    if (entry.state != CacheEntry::State::intact) {
      throw NativeCodeError("native code: the library just stored is damaged: " + entry.why);
    }
    try {
      return accept(load_checked(entry, identity), entry);
    } catch (const Refused& why) {
      remove_entry(directory, name);
      throw NativeCodeError("native code: the library just compiled is refused: " +
                            std::string(why.what()));
    }
  } catch (const Refused& why) {
    throw NativeCodeError("native code: the library just compiled is refused: " +
                          std::string(why.what()));
  } catch (const NativeCodeError&) {
    throw;
  } catch (const std::runtime_error& e) {
    throw NativeCodeError(std::string("native code: ") + e.what());
  }
}

void stop_native_compilers() noexcept {
  g_compilers_stopped.store(true);
  for (auto& slot : g_compilers) {
    if (const pid_t group = slot.load(); group > 0) ::kill(-group, SIGKILL);
  }
  // a compiler being spawned by another thread: it sees the stop when it takes its slot (at most
  // ~2 s waited for, in steps of 1 ms: nanosleep is async-signal-safe)
  const timespec step{0, 1'000'000};
  for (int k = 0; k < 2000 && g_compilers_starting.load() > 0; ++k) ::nanosleep(&step, nullptr);
}

NativeLibrary::~NativeLibrary() {
  if (handle_ != nullptr) ::dlclose(handle_);
}

NativeFunction NativeLibrary::function(const std::string& name) const {
  void* symbol = ::dlsym(handle_, name.c_str());
  if (symbol == nullptr) throw NativeCodeError("native code: no function " + name + " in " + path_);
  return reinterpret_cast<NativeFunction>(symbol);
}

}  // namespace unidyn
