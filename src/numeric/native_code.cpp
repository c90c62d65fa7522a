// Tapes printed as C++, compiled by the system compiler, cached by the hash of source and
// command, and loaded with dlopen.
#include "unidyn/numeric/native_code.hpp"

#include <dlfcn.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace unidyn {
namespace {

namespace fs = std::filesystem;

// A double as an exact C++ literal (hexadecimal floating point), infinities and NaN included.
std::string literal(double value) {
  if (std::isnan(value)) return "__builtin_nan(\"\")";
  if (std::isinf(value)) return value > 0 ? "__builtin_inf()" : "(-__builtin_inf())";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

// The C++ expression of a single-result operation on x = r[a] (and r[b]); as the tape's execute().
std::string operation(TapeOp op, const std::string& x, const std::string& y) {
  switch (op) {
    case TapeOp::add:
      return x + " + " + y;
    case TapeOp::sub:
      return x + " - " + y;
    case TapeOp::mul:
      return x + " * " + y;
    case TapeOp::div:
      return x + " / " + y;
    case TapeOp::neg:
      return "-" + x;
    case TapeOp::recip:
      return "1.0 / " + x;
    case TapeOp::sqrt:
      return "std::sqrt(" + x + ")";
    case TapeOp::pow:
      return "std::pow(" + x + ", " + y + ")";
    case TapeOp::sin:
      return "std::sin(" + x + ")";
    case TapeOp::cos:
      return "std::cos(" + x + ")";
    case TapeOp::sincos:
      break;  // two results: written by the caller
    case TapeOp::tan:
      return "std::tan(" + x + ")";
    case TapeOp::asin:
      return "std::asin(" + x + ")";
    case TapeOp::acos:
      return "std::acos(" + x + ")";
    case TapeOp::atan:
      return "std::atan(" + x + ")";
    case TapeOp::atan2:
      return "std::atan2(" + x + ", " + y + ")";
    case TapeOp::sinh:
      return "std::sinh(" + x + ")";
    case TapeOp::cosh:
      return "std::cosh(" + x + ")";
    case TapeOp::tanh:
      return "std::tanh(" + x + ")";
    case TapeOp::exp:
      return "std::exp(" + x + ")";
    case TapeOp::log:
      return "std::log(" + x + ")";
    case TapeOp::abs:
      return "std::fabs(" + x + ")";
    case TapeOp::sign:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? -1.0 : 0.0))";
    case TapeOp::step:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? 0.0 : 0.5))";
  }
  return {};
}

// FNV-1a of text: the same in every run.
std::uint64_t hash_text(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

fs::path cache_directory(const NativeOptions& options) {
  if (!options.cache_directory.empty()) return options.cache_directory;
  if (const std::string d = environment("UNIDYN_CACHE_DIR"); !d.empty()) return d;
  if (const std::string d = environment("XDG_CACHE_HOME"); !d.empty())
    return fs::path(d) / "unidyn";
  if (const std::string d = environment("HOME"); !d.empty()) return fs::path(d) / ".cache/unidyn";
  return "/tmp/unidyn-cache";
}

// Text in single quotes for the shell.
std::string shell_quoted(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

}  // namespace

std::string tape_source(const Tape& tape, std::string_view name) {
  std::ostringstream os;
  const std::size_t inputs = tape.input_count(), constants = tape.constant_count();
  os << "extern \"C\" void " << name << "(const double* in, double* out) {\n";
  // registers: inputs, constants, then temporaries (reused as in the tape)
  for (std::size_t r = 0; r < tape.register_count(); ++r) {
    os << "  double r" << r;
    if (r < inputs) os << " = in[" << r << "]";
    if (r >= inputs && r < inputs + constants) os << " = " << literal(tape.constants()[r - inputs]);
    os << ";\n";
  }
  os << "  (void)in;\n";
  for (const TapeInstruction& i : tape.instructions()) {
    const std::string x = "r" + std::to_string(i.a), y = "r" + std::to_string(i.b);
    if (i.op == TapeOp::sincos) {
      os << "  { const double x = " << x << "; r" << i.dst << " = std::sin(x); " << y
         << " = std::cos(x); }\n";
    } else {
      os << "  r" << i.dst << " = " << operation(i.op, x, y) << ";\n";
    }
  }
  for (std::size_t k = 0; k < tape.output_count(); ++k) {
    os << "  out[" << k << "] = r" << tape.output_registers()[k] << ";\n";
  }
  os << "}\n";
  return os.str();
}

std::shared_ptr<const NativeLibrary> NativeLibrary::build(
    const std::vector<std::pair<std::string, const Tape*>>& functions,
    const NativeOptions& options) {
  // The source of every function, and the command that compiles it.
  std::string source = "// generated by unidyn: compiled equations\n#include <cmath>\n";
  for (const auto& [name, tape] : functions) source += "\n" + tape_source(*tape, name);
  std::string compiler = options.compiler;
  if (compiler.empty()) compiler = environment("CXX");
  if (compiler.empty()) compiler = "c++";
  const std::string command_text = compiler + " " + options.flags;
  // the key: the functions' signatures, the command, and the source or the caller's key
  std::string identity = "unidyn native code v1\n" + command_text + "\n";
  for (const auto& [name, tape] : functions) {
    identity += name + " " + std::to_string(tape->input_count()) + " " +
                std::to_string(tape->output_count()) + "\n";
  }
  identity += options.key.empty() ? source : options.key;
  char key[32];
  std::snprintf(key, sizeof key, "%016llx", static_cast<unsigned long long>(hash_text(identity)));

  std::shared_ptr<NativeLibrary> library(new NativeLibrary);
  library->source_bytes_ = source.size();
  const fs::path directory = cache_directory(options);
  const fs::path so = directory / (std::string(key) + ".so");
  library->path_ = so.string();
  std::error_code error;
  if (fs::exists(so, error)) {
    library->cached_ = true;
  } else {
    fs::create_directories(directory, error);
    if (error) {
      throw NativeCodeError("native code: cannot create the cache directory " + directory.string() +
                            ": " + error.message());
    }
    // compile under a name of this process, then rename: another process may be at it too
    const std::string unique = std::string(key) + "." + std::to_string(::getpid());
    const fs::path cpp = directory / (unique + ".cpp"), partial = directory / (unique + ".so");
    const fs::path log = directory / (unique + ".log");
    std::ofstream(cpp) << source;
    const std::string command = shell_quoted(compiler) + " " + options.flags + " -o " +
                                shell_quoted(partial.string()) + " " + shell_quoted(cpp.string()) +
                                " > " + shell_quoted(log.string()) + " 2>&1";
    const auto start = std::chrono::steady_clock::now();
    const int status = std::system(command.c_str());
    library->compile_seconds_ =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const std::string diagnostics = read_text(log);
    fs::remove(cpp, error);
    fs::remove(log, error);
    if (status != 0 || !fs::exists(partial, error)) {
      fs::remove(partial, error);
      throw NativeCodeError("native code: '" + command_text + "' failed (status " +
                            std::to_string(status) + ")" +
                            (diagnostics.empty() ? "" : ": " + diagnostics.substr(0, 2000)));
    }
    fs::rename(partial, so, error);
    if (error) throw NativeCodeError("native code: cannot store " + so.string());
  }
  library->handle_ = ::dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (library->handle_ == nullptr) {
    const char* why = ::dlerror();
    fs::remove(so, error);  // a damaged cached library: the next build compiles it again
    throw NativeCodeError("native code: cannot load " + so.string() + ": " +
                          (why != nullptr ? why : "unknown error"));
  }
  return library;
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
