// Shared by the MuJoCo and Simbody peers: the benchmark models of bench/MODELS.md, the peer state
// convention, the command line and the JSON/timing helpers.
//
// This header must stay valid C++17: Simbody 3.7's headers do not compile as C++20 (see
// CMakeLists.txt), so peer_simbody is built as C++17.
#pragma once

#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace unidyn::peers {

// ---------------------------------------------------------------------------------------------
// Model constants (bench/MODELS.md, SI units).

inline constexpr double kGravity = 9.81;

// pendulum-N: unit point masses on massless links of unit length.
inline constexpr double kPendulumMass = 1.0;
inline constexpr double kPendulumLength = 1.0;
// MuJoCo needs a positive rotational inertia for a point mass.
inline constexpr double kPointMassInertia = 1e-12;

// heavy-top: centre of mass at l e3 from the fixed point; (A, A, C) about the centre of mass.
inline constexpr double kTopMass = 1.0;
inline constexpr double kTopL = 0.05;
inline constexpr double kTopA = 0.004;
inline constexpr double kTopC = 0.002;

// torque-free: principal inertias about the centre of mass, no gravity.
inline constexpr double kFreeMass = 1.0;
inline constexpr std::array<double, 3> kFreeInertia{2.0, 4.0, 5.0};

// kRobotFile: a URDF or MJCF file, its state (qpos, qvel) in the file's joint order — a free or
// ball joint's quaternion (w, x, y, z) and angular velocity on the body frame — and its output
// qacc (the backend learns the sizes from the file).
enum class ModelKind { kPendulum, kHeavyTop, kTorqueFree, kRobotFile };

struct Model {
  ModelKind kind = ModelKind::kPendulum;
  int links = 0;  // N for pendulum-N, 0 otherwise
  std::string name;

  // Peer state: pendulum (q, q̇); bodies (w, x, y, z, ω_b).
  std::size_t stateSize() const {
    if (kind == ModelKind::kRobotFile) return 0;  // any (q, q̇): checked by the backend
    return kind == ModelKind::kPendulum ? 2 * links : 7;
  }
  // Peer output: pendulum q̈; bodies ω̇_b.
  std::size_t accelerationSize() const {
    return kind == ModelKind::kPendulum || kind == ModelKind::kRobotFile ? links : 3;
  }
  bool isBody() const { return kind == ModelKind::kHeavyTop || kind == ModelKind::kTorqueFree; }
};

// Thrown for command-line mistakes (exit status 2, usage printed).
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Parses a finite floating-point number, the whole string.
inline double parseNumber(const std::string& text, const std::string& what) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value)) {
    throw UsageError("invalid number for " + what + ": '" + text + "'");
  }
  return value;
}

inline Model parseModel(const std::string& name) {
  Model model;
  model.name = name;
  const std::string prefix = "pendulum-";
  const auto ends_with = [&](const std::string& end) {
    return name.size() > end.size() && name.compare(name.size() - end.size(), end.size(), end) == 0;
  };
  if (ends_with(".urdf") || ends_with(".xml")) {
    model.kind = ModelKind::kRobotFile;
  } else if (name == "heavy-top") {
    model.kind = ModelKind::kHeavyTop;
  } else if (name == "torque-free") {
    model.kind = ModelKind::kTorqueFree;
  } else if (name.compare(0, prefix.size(), prefix) == 0) {
    const std::string digits = name.substr(prefix.size());
    char* end = nullptr;
    const long n = std::strtol(digits.c_str(), &end, 10);
    if (digits.empty() || end != digits.c_str() + digits.size() || n < 1 || n > 1000) {
      throw UsageError("invalid pendulum size in '" + name + "'");
    }
    model.kind = ModelKind::kPendulum;
    model.links = static_cast<int>(n);
  } else {
    throw UsageError("unknown model '" + name +
                     "' (pendulum-N, heavy-top, torque-free, a .urdf or .xml file)");
  }
  return model;
}

// Initial state of the time-to-accuracy runs (pendulum-2 and heavy-top only).
inline std::vector<double> timeToAccuracyState(const Model& model) {
  if (model.kind == ModelKind::kPendulum && model.links == 2) return {0.5, 0.0, 0.0, 0.0};
  if (model.kind == ModelKind::kHeavyTop) {
    return {std::cos(0.15), std::sin(0.15), 0.0, 0.0, 0.0, 0.0, 60.0};
  }
  throw UsageError("simulate: MODELS.md defines a time-to-accuracy run only for pendulum-2 and " +
                   std::string("heavy-top, not ") + model.name);
}

// Normalises the attitude quaternion of a body state in place (both peers see the same unit
// quaternion whatever rounding the caller's input has).
inline void normalizeAttitude(const Model& model, std::vector<double>& state) {
  if (!model.isBody()) return;
  const double norm = std::sqrt(state[0] * state[0] + state[1] * state[1] + state[2] * state[2] +
                                state[3] * state[3]);
  if (!(norm > 0.0)) throw std::runtime_error("zero attitude quaternion");
  for (int i = 0; i < 4; ++i) state[i] /= norm;
}

// Reads whitespace-separated states from `in`, one a line; blank lines are skipped.
inline std::vector<std::vector<double>> readStates(std::istream& in, const Model& model) {
  std::vector<std::vector<double>> states;
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    std::istringstream fields(line);
    std::vector<double> state;
    std::string field;
    while (fields >> field) state.push_back(parseNumber(field, "state value"));
    if (state.empty()) continue;
    if (model.stateSize() != 0 && state.size() != model.stateSize()) {
      throw UsageError("line " + std::to_string(lineNumber) + ": expected " +
                       std::to_string(model.stateSize()) + " numbers for " + model.name + ", got " +
                       std::to_string(state.size()));
    }
    normalizeAttitude(model, state);
    states.push_back(std::move(state));
  }
  return states;
}

// ---------------------------------------------------------------------------------------------
// Output helpers.

inline std::string formatNumber(double value) {
  if (!std::isfinite(value)) return "null";  // keeps the JSON valid; never expected
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", value);
  return buffer;
}

inline void printRow(const std::vector<double>& values) {
  std::string line;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) line += ' ';
    line += formatNumber(values[i]);
  }
  std::printf("%s\n", line.c_str());
}

// Calls `eval` in doubling batches until at least `minSeconds` have passed; returns the mean
// wall time of one call in nanoseconds.
template <class F>
double timeEvaluations(F&& eval, double minSeconds) {
  using Clock = std::chrono::steady_clock;
  for (int i = 0; i < 100; ++i) eval();  // warm caches and lazy initialisation
  long long count = 0;
  long long batch = 16;
  double elapsed = 0.0;
  const auto start = Clock::now();
  while (elapsed < minSeconds) {
    for (long long i = 0; i < batch; ++i) eval();
    count += batch;
    elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (batch < (1LL << 20)) batch *= 2;
  }
  return elapsed * 1e9 / static_cast<double>(count);
}

// Wall-clock stopwatch for the simulate runs.
class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// Largest |E − E0| / |E0| over the observed energies.
class EnergyMonitor {
 public:
  explicit EnergyMonitor(double initial) : initial_(initial) {}
  void observe(double energy) {
    const double scale = initial_ != 0.0 ? std::abs(initial_) : 1.0;
    const double error = std::abs(energy - initial_) / scale;
    if (!(error <= maxError_)) maxError_ = error;  // also propagates NaN
  }
  double initial() const { return initial_; }
  double maxRelativeError() const { return maxError_; }

 private:
  double initial_;
  double maxError_ = 0.0;
};

// ---------------------------------------------------------------------------------------------
// The peer interface and the common main().

struct SimulateOptions {
  double tEnd = 0.0;
  std::string integrator;
  std::optional<double> dt;
  std::optional<double> accuracy;
};

struct SimulateResult {
  double wallSeconds = 0.0;
  long long steps = 0;
  double maxRelativeEnergyError = 0.0;
  double initialEnergy = 0.0;
  std::vector<double> finalState;  // peer state convention
};

class Backend {
 public:
  virtual ~Backend() = default;
  // Accelerations (q̈, or ω̇_b in body components) at one state in the peer convention.
  virtual std::vector<double> rhs(const std::vector<double>& state) = 0;
  // Mean wall time of one right-hand-side evaluation at `state`, repeated for `minSeconds`.
  virtual double nsPerEval(const std::vector<double>& state, double minSeconds) = 0;
  // Integrates from `initial` to options.tEnd (see each peer for the integrators).
  virtual SimulateResult simulate(const std::vector<double>& initial,
                                  const SimulateOptions& options) = 0;
};

using BackendFactory = std::unique_ptr<Backend> (*)(const Model&);

inline void printUsage(const char* program, const char* integrators) {
  std::fprintf(stderr,
               "usage: %s rhs MODEL < states\n"
               "       %s simulate MODEL --t-end T --integrator NAME [--dt H] [--accuracy A]\n"
               "MODEL: pendulum-N | heavy-top | torque-free; integrators: %s\n",
               program, program, integrators);
}

inline void printSimulateJson(const SimulateResult& result) {
  std::string json =
      "{\"wall_seconds\":" + formatNumber(result.wallSeconds) +
      ",\"steps\":" + std::to_string(result.steps) +
      ",\"max_relative_energy_error\":" + formatNumber(result.maxRelativeEnergyError) +
      ",\"initial_energy\":" + formatNumber(result.initialEnergy) + ",\"final_state\":[";
  for (std::size_t i = 0; i < result.finalState.size(); ++i) {
    if (i > 0) json += ',';
    json += formatNumber(result.finalState[i]);
  }
  json += "]}";
  std::printf("%s\n", json.c_str());
}

inline SimulateOptions parseSimulateOptions(int argc, char** argv, int first) {
  SimulateOptions options;
  bool haveEnd = false;
  for (int i = first; i < argc; ++i) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw UsageError("missing value after " + flag);
    const std::string value = argv[++i];
    if (flag == "--t-end") {
      options.tEnd = parseNumber(value, flag);
      haveEnd = true;
    } else if (flag == "--integrator") {
      options.integrator = value;
    } else if (flag == "--dt") {
      options.dt = parseNumber(value, flag);
    } else if (flag == "--accuracy") {
      options.accuracy = parseNumber(value, flag);
    } else {
      throw UsageError("unknown option " + flag);
    }
  }
  if (!haveEnd || !(options.tEnd > 0.0)) throw UsageError("simulate needs --t-end T > 0");
  if (options.integrator.empty()) throw UsageError("simulate needs --integrator NAME");
  if (options.dt && !(*options.dt > 0.0)) throw UsageError("--dt must be positive");
  if (options.accuracy && !(*options.accuracy > 0.0)) throw UsageError("--accuracy must be > 0");
  return options;
}

// Dispatches the `rhs` and `simulate` subcommands to the backend made by `make`.
inline int peerMain(int argc, char** argv, const char* integrators, BackendFactory make) {
  constexpr double kMinTimingSeconds = 0.3;
  try {
    if (argc < 3) throw UsageError("missing subcommand or model");
    const std::string command = argv[1];
    const Model model = parseModel(argv[2]);
    if (command == "rhs") {
      if (argc != 3) throw UsageError("rhs takes no options");
      const auto states = readStates(std::cin, model);
      if (states.empty()) throw UsageError("rhs: no state on standard input");
      auto backend = make(model);
      for (const auto& state : states) printRow(backend->rhs(state));
      std::fflush(stdout);
      const double ns = backend->nsPerEval(states.front(), kMinTimingSeconds);
      std::printf("ns_per_eval %s\n", formatNumber(ns).c_str());
      return 0;
    }
    if (command == "simulate") {
      const SimulateOptions options = parseSimulateOptions(argc, argv, 3);
      const std::vector<double> initial = timeToAccuracyState(model);
      auto backend = make(model);
      printSimulateJson(backend->simulate(initial, options));
      return 0;
    }
    throw UsageError("unknown subcommand '" + command + "'");
  } catch (const UsageError& error) {
    std::fprintf(stderr, "%s: %s\n", argv[0], error.what());
    printUsage(argv[0], integrators);
    return 2;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "%s: error: %s\n", argv[0], error.what());
    return 1;
  }
}

}  // namespace unidyn::peers
