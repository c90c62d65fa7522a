// Native code for compiled equations: a tape printed as a C++ function, compiled by the system
// compiler into a shared library, cached on disk (numeric/code_cache.hpp) under the SHA-256 of
// everything that determines it, and loaded. The function performs the tape's operations in the
// tape's order with IEEE semantics (no fast math, no contraction into fused multiply-adds), so it
// gives the tape's results.
//
// A library is called only after it has proved what it is: it carries its full key and its
// signature (each function's name and input/output sizes), which are compared with the ones
// expected before any function is looked up; a library freshly compiled also carries the SHA-256
// of its source, compared with the source just written. A cached library that fails a check is
// removed and compiled again.
#pragma once

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace unidyn {

// A compiled tape: outputs[k] = output k at inputs (sizes as the tape's).
using NativeFunction = void (*)(const double* inputs, double* outputs);

// The C++ source of `extern "C" void <name>(const double* in, double* out)` evaluating `tape`.
std::string tape_source(const Tape& tape, std::string_view name);

struct NativeOptions {
  // The compiler: empty takes $CXX, else c++.
  std::string compiler;
  // Where libraries are kept: empty takes $UNIDYN_CACHE_DIR, else $XDG_CACHE_HOME/unidyn, else
  // $HOME/.cache/unidyn; without one (or when it is not trusted) a private temporary directory
  // that is removed after loading (see CacheLocation).
  std::string cache_directory;
  // -O1: the straight-line code of a tape runs as fast as at -O2 (measured: pendulum-5, -10, -20,
  // heavy top, bicycle) and compiles in half the time for the large ones (pendulum-20 3.9 → 2.9 s).
  // On x86-64 the processor's micro-architecture level is added (-march=x86-64-v2, -v3 or -v4)
  // unless the flags name a target (native_code.cpp: the same numbers, more registers).
  std::string flags = "-std=c++17 -O1 -ffp-contract=off -fno-fast-math -fPIC -shared";
  // What the cache is keyed by, besides the unidyn version, the compiler's identity (its resolved
  // path, size and time of change), the flags and the functions' names and sizes: empty takes the
  // generated source. A model's text is the better key: the source of one model can differ from
  // run to run in the order GiNaC gives its (equal) expressions.
  std::string key;
  // Only a library already in the cache: NotCached rather than compiling one.
  bool only_cached = false;
  // Test hook: the file name of an entry from its key's text (default: its SHA-256). A weak one
  // makes different keys share a file, as a collision of the hash would.
  std::string (*entry_name)(std::string_view key_text) = nullptr;
};

// Native code cannot be had: no compiler, a failed compilation (with its diagnostics), a library
// that does not load.
class NativeCodeError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// NativeOptions::only_cached and the library is not in the cache.
class NotCached : public NativeCodeError {
 public:
  using NativeCodeError::NativeCodeError;
};

// Ends every compiler this process runs (each in a process group of its own, killed whole) and
// refuses to start another: for a signal that ends the process. Async-signal-safe. The compiling
// thread then reaps its compiler, removes its build directory and throws NativeCodeError.
void stop_native_compilers() noexcept;

// A loaded library of compiled tapes. Immutable; its functions stay valid while it lives.
class NativeLibrary {
 public:
  // Generate the functions' source, compile it unless a library of the same key is cached, and
  // load it after checking its key and signature. Throws NativeCodeError.
  static std::shared_ptr<const NativeLibrary> build(
      const std::vector<std::pair<std::string, const Tape*>>& functions,
      const NativeOptions& options = {});

  ~NativeLibrary();
  NativeLibrary(const NativeLibrary&) = delete;
  NativeLibrary& operator=(const NativeLibrary&) = delete;

  // The function of that name; throws NativeCodeError when the library has none.
  NativeFunction function(const std::string& name) const;
  const std::string& path() const { return path_; }
  // Whether the library stays in the cache after this process (false: it was compiled in a
  // private temporary directory, already removed).
  bool kept() const { return kept_; }
  // Whether the library came from the cache, and how long compiling it took (0 when cached).
  bool cached() const { return cached_; }
  double compile_seconds() const { return compile_seconds_; }
  // Size of the generated source, in bytes.
  std::size_t source_bytes() const { return source_bytes_; }
  // What happened besides a plain load or compile: why the cache was not used, a cached library
  // refused and compiled again, time spent waiting for another process compiling it ("" if none).
  const std::string& notes() const { return notes_; }

 private:
  NativeLibrary() = default;
  void* handle_ = nullptr;
  std::string path_;
  bool cached_ = false;
  bool kept_ = true;
  double compile_seconds_ = 0.0;
  std::size_t source_bytes_ = 0;
  std::string notes_;
};

}  // namespace unidyn
