// unidyn's side of the side-by-side benchmarks (bench/run.sh): derivation time and accelerations,
// right-hand-side evaluation time, and time to accuracy, on the models of bench/MODELS.md.
//
//   unidyn_bench derive MODEL [--method lagrange|kane] [--repeat K] [--states FILE]
//   unidyn_bench rhs MODEL [--evaluation tape|native] [--state stdin|initial]  (states on stdin,
//                                           peer convention; or the model's initial state)
//   unidyn_bench simulate MODEL --t-end T --method M [--rtol R] [--step H] [--evaluation E]
//   unidyn_bench longrun MODEL --steps N --step H [--method rattle|dopri5] [--rtol R]
//
// derive and simulate print one JSON line; rhs prints one line of accelerations per state, then
// ns_per_eval.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench_models.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/rattle.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace {

using namespace unidyn;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// --name value options after the subcommand and model.
std::map<std::string, std::string> options_of(int argc, char** argv) {
  std::map<std::string, std::string> options;
  for (int i = 3; i + 1 < argc; i += 2) options[argv[i]] = argv[i + 1];
  return options;
}

std::string option(const std::map<std::string, std::string>& o, const std::string& name,
                   const std::string& fallback) {
  const auto it = o.find(name);
  return it == o.end() ? fallback : it->second;
}

// Whitespace-separated numbers, one state per line.
std::vector<Eigen::VectorXd> read_states(std::istream& in) {
  std::vector<Eigen::VectorXd> states;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::vector<double> values;
    for (double v; fields >> v;) values.push_back(v);
    if (!values.empty())
      states.push_back(
          Eigen::Map<Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size())));
  }
  return states;
}

std::string json_vector(const Eigen::VectorXd& v) {
  std::string text = "[";
  char buffer[32];
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    std::snprintf(buffer, sizeof buffer, "%.17g", v[i]);
    text += (i > 0 ? ", " : "") + std::string(buffer);
  }
  return text + "]";
}

CompileOptions compile_options(const std::string& evaluation) {
  CompileOptions options;
  options.native = evaluation == "native";
  return options;
}

// Derivation (parse + Lagrange's equations), compilation to the tape and to native code, and q̈
// at the given states (unidyn's coordinates).
int derive(const std::string& name, const std::map<std::string, std::string>& o) {
  const int repeat = std::stoi(option(o, "--repeat", "1"));
  const bool kane = option(o, "--method", "lagrange") == "kane";
  double best = INFINITY;
  bench::BenchModel model;
  EquationsOfMotion equations;
  for (int k = 0; k < repeat; ++k) {
    const auto start = Clock::now();
    model = bench::bench_model(name, UNIDYN_MODELS_DIR);
    equations = kane ? kane_equations(model.system) : lagrange_equations(model.system);
    best = std::min(best, seconds_since(start));
  }
  auto start = Clock::now();
  const CompiledSystem tape(model.system, equations);
  const double tape_seconds = seconds_since(start);
  CompileOptions native_options = compile_options("native");
  // an empty cache of its own, so that the compilation is timed
  native_options.native_options.cache_directory =
      "/tmp/unidyn-bench-cache-" + std::filesystem::path(name).filename().string();
  std::filesystem::remove_all(native_options.native_options.cache_directory);
  start = Clock::now();
  const CompiledSystem native(model.system, equations, native_options);
  const double native_seconds = seconds_since(start);
  std::vector<Eigen::VectorXd> states;
  if (o.count("--states")) {
    std::ifstream in(o.at("--states"));
    states = read_states(in);
  }
  const auto n = static_cast<Eigen::Index>(tape.coordinate_count());
  const SimulationStart initial = initial_state(model.system, {});
  CompiledSystemData data = tape.make_data();
  std::string qddots;
  for (const Eigen::VectorXd& state : states) {
    Eigen::VectorXd qddot, lambda;
    tape.solve(0, state.head(n), state.tail(n), initial.parameters, qddot, lambda, data);
    qddots += (qddots.empty() ? "" : ", ") + json_vector(qddot);
  }
  std::printf(
      "{\"model\": \"%s\", \"n\": %ld, \"derive_seconds\": %.6g, \"tape_seconds\": %.6g, "
      "\"native_seconds\": %.6g, \"native\": %s, \"instructions\": %zu, \"source_bytes\": %zu, "
      "\"qddot\": [%s]}\n",
      name.c_str(), static_cast<long>(n), best, tape_seconds, native_seconds,
      native.native() ? "true" : "false", tape.instruction_count(), native.native_source_bytes(),
      qddots.c_str());
  return 0;
}

// Accelerations at the peer-convention states of stdin, then the time of one right-hand side
// (solve for q̈ from q, q̇) at the first state.
int rhs(const std::string& name, const std::map<std::string, std::string>& o) {
  const bench::BenchModel model = bench::bench_model(name, UNIDYN_MODELS_DIR);
  // --sizes: the peer state's shape, {"nq", "nv", "quaternions": first index of each}
  if (o.count("--sizes")) {
    const std::vector<std::size_t> blocks = bench::euler_parameter_blocks(model);
    std::string list;
    for (const std::size_t b : blocks) list += (list.empty() ? "" : ", ") + std::to_string(b);
    const std::size_t nq = model.system.coordinates().size();
    std::printf("{\"nq\": %zu, \"nv\": %zu, \"quaternions\": [%s]}\n", nq, nq - blocks.size(),
                list.c_str());
    return 0;
  }
  // as `unidyn simulate` compiles it: Kane's equations, or a large tree's recursive dynamics
  // (--recursive-from N: from N coordinates, instead of simulate's threshold)
  CompileOptions options = compile_options(option(o, "--evaluation", "native"));
  if (o.count("--recursive-from")) {
    options.recursive_from_coordinates = std::stoul(o.at("--recursive-from"));
  }
  // --native-flags: the compiler's flags for the native code instead of the default
  if (o.count("--native-flags")) options.native_options.flags = o.at("--native-flags");
  const CompiledSystem compiled(model.system, options);
  const SimulationStart initial = initial_state(model.system, {});
  CompiledSystemData data = compiled.make_data();
  // --state initial: the model's initial state instead (a model no peer has, the bicycle)
  const std::vector<Eigen::VectorXd> states =
      option(o, "--state", "stdin") == "initial"
          ? std::vector<Eigen::VectorXd>{(Eigen::VectorXd(2 * initial.q.size()) << initial.q,
                                          initial.qdot)
                                             .finished()}
          : read_states(std::cin);
  Eigen::VectorXd q, qdot, qddot, lambda;
  for (const Eigen::VectorXd& state : states) {
    bench::from_peer_state(model, state, q, qdot);
    compiled.solve(0, q, qdot, initial.parameters, qddot, lambda, data);
    const Eigen::VectorXd a = bench::to_peer_acceleration(model, q, qdot, qddot);
    for (Eigen::Index i = 0; i < a.size(); ++i) std::printf(i ? " %.17g" : "%.17g", a[i]);
    std::printf("\n");
  }
  if (states.empty()) return 0;
  bench::from_peer_state(model, states.front(), q, qdot);
  long evaluations = 0;
  const auto start = Clock::now();
  double elapsed = 0;
  while (elapsed < 0.3) {
    for (int k = 0; k < 1000; ++k) {
      q[0] += 1e-12;  // a new state each time
      compiled.solve(0, q, qdot, initial.parameters, qddot, lambda, data);
    }
    evaluations += 1000;
    elapsed = seconds_since(start);
  }
  std::printf("ns_per_eval %.6g\nevaluation %s\n", 1e9 * elapsed / double(evaluations),
              compiled.evaluation().c_str());
  return 0;
}

// Wall time of a run to t_end (rows only at the ends), and, in a separate untimed pass with a row
// every output_step, the largest relative energy error and the final state (peer convention).
int simulate_run(const std::string& name, const std::map<std::string, std::string>& o) {
  const bench::BenchModel model = bench::bench_model(name, UNIDYN_MODELS_DIR);
  // as `unidyn simulate` compiles it: Kane's equations, or a large tree's recursive dynamics
  const CompiledSystem compiled(model.system, compile_options(option(o, "--evaluation", "native")));
  SimulationOptions options = simulation_options(model.system.simulate);
  options.t_end = std::stod(option(o, "--t-end", "100"));
  options.method = option(o, "--method", "dopri5");
  options.rtol = std::stod(option(o, "--rtol", "1e-10"));
  options.atol = options.rtol * 1e-2;
  options.step = std::stod(option(o, "--step", "0"));
  options.output_step = options.t_end;
  const SimulationStart start = initial_state(model.system, {});
  std::vector<double> last;
  const auto timed = Clock::now();
  const SimulationSummary summary =
      simulate(model.system, compiled, start, options,
               [&last](const std::vector<double>& row) { last = row; });
  const double wall = seconds_since(timed);
  // the energy at every step's end: rows at the step size (or 1e-3)
  options.output_step = options.step > 0 ? options.step : 1e-3;
  const auto n = static_cast<Eigen::Index>(compiled.coordinate_count());
  const std::size_t energy_column = 1 + 2 * static_cast<std::size_t>(n);
  double e0 = NAN, worst = 0;
  simulate(model.system, compiled, start, options, [&](const std::vector<double>& row) {
    if (std::isnan(e0)) e0 = row[energy_column];
    worst = std::max(worst, std::abs(row[energy_column] - e0) / std::abs(e0));
  });
  Eigen::VectorXd q(n), qdot(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    q[i] = last[static_cast<std::size_t>(1 + i)];
    qdot[i] = last[static_cast<std::size_t>(1 + n + i)];
  }
  std::printf(
      "{\"ok\": %s, \"wall_seconds\": %.6g, \"steps\": %zu, \"rhs\": %zu, "
      "\"max_relative_energy_error\": %.6g, \"final_state\": %s, \"evaluation\": \"%s\"}\n",
      summary.ok ? "true" : "false", wall, summary.stats.accepted_steps,
      summary.stats.rhs_evaluations, worst,
      json_vector(bench::to_peer_state(model, q, qdot)).c_str(),
      compiled.native() ? "native" : "tape");
  return summary.ok ? 0 : 1;
}

// RATTLE over many steps: the relative energy error, largest over the first tenth of the run and
// over all of it (bounded: the two stay alike), sampled every `stride` steps; with --method dopri5
// the same span by Dormand–Prince at --rtol for contrast.
int long_run(const std::string& name, const std::map<std::string, std::string>& o) {
  const bench::BenchModel model = bench::bench_model(name, UNIDYN_MODELS_DIR);
  const EquationsOfMotion equations = kane_equations(model.system);
  const CompiledSystem compiled(model.system, equations);
  const auto steps = static_cast<long>(std::stod(option(o, "--steps", "1e7")));
  const double h = std::stod(option(o, "--step", "1e-3"));
  const std::string method = option(o, "--method", "rattle");
  const SimulationStart start = initial_state(model.system, {});
  CompiledSystemData data = compiled.make_data();
  std::vector<double> observed(compiled.observation_count());
  const auto energy = [&](const Eigen::VectorXd& y) {
    const auto n = y.size() / 2;
    Eigen::VectorXd qddot, lambda;
    compiled.solve(0, y.head(n), y.tail(n), start.parameters, qddot, lambda, data);
    compiled.observe(0, y.head(n), y.tail(n), qddot, lambda, start.parameters, observed, data);
    return observed[0] + observed[1];
  };
  Eigen::VectorXd y0(2 * start.q.size());
  y0 << start.q, start.qdot;
  const double e0 = energy(y0), t_end = double(steps) * h;
  double first_tenth = 0, whole = 0;
  const long samples = 1000;
  const auto started = Clock::now();
  double sampling = 0;  // time spent on the energy samples, left out of the wall time
  const auto sample = [&](const Eigen::VectorXd& y, double t) {
    const auto before = Clock::now();
    const double error = std::abs(energy(y) - e0) / std::abs(e0);
    whole = std::max(whole, error);
    if (t <= 0.1 * t_end * (1 + 1e-12)) first_tenth = whole;
    sampling += seconds_since(before);
  };
  std::size_t evaluations = 0;
  if (method == "rattle") {
    const CompiledNaturalSystem natural(model.system, equations);
    RattleOptions options;
    options.step = h;
    Rattle stepper(natural, start.parameters, options);
    stepper.initialize(0, y0);
    for (long k = 1; k <= steps; ++k) {
      stepper.step(2 * t_end);
      if (k % (steps / samples) == 0) sample(stepper.y(), stepper.t());
    }
    evaluations = stepper.stats().rhs_evaluations;
  } else {
    Eigen::VectorXd qddot, lambda;
    const auto n = start.q.size();
    DormandPrinceOptions options;
    options.rtol = std::stod(option(o, "--rtol", "1e-8"));
    options.atol = options.rtol * 1e-2;
    options.max_steps = 1000000000;
    DormandPrince54 stepper(
        [&](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
          compiled.solve(t, y.head(n), y.tail(n), start.parameters, qddot, lambda, data);
          dydt << y.tail(n), qddot;
        },
        options);
    stepper.initialize(0, y0);
    for (long k = 1; k <= samples; ++k) {
      const double t = t_end * double(k) / double(samples);
      while (stepper.t() < t) stepper.step(t);
      sample(stepper.y(), t);
    }
    evaluations = stepper.stats().rhs_evaluations;
  }
  std::printf(
      "{\"model\": \"%s\", \"method\": \"%s\", \"steps\": %ld, \"step\": %.6g, \"t_end\": %.6g, "
      "\"wall_seconds\": %.6g, \"evaluations\": %zu, \"energy_error_first_tenth\": %.6g, "
      "\"energy_error_whole\": %.6g}\n",
      name.c_str(), method.c_str(), steps, h, t_end, seconds_since(started) - sampling, evaluations,
      first_tenth, whole);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: unidyn_bench derive|rhs|simulate MODEL [options]\n");
    return 2;
  }
  try {
    const std::string command = argv[1], name = argv[2];
    const auto o = options_of(argc, argv);
    if (command == "derive") return derive(name, o);
    if (command == "rhs") return rhs(name, o);
    if (command == "simulate") return simulate_run(name, o);
    if (command == "longrun") return long_run(name, o);
    std::fprintf(stderr, "unknown command %s\n", command.c_str());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "unidyn_bench: %s\n", e.what());
    return 1;
  }
}
