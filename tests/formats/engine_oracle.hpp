// Another engine as an oracle for the imported formats (mujoco_oracle.hpp, kdl_oracle.hpp): a file
// read by unidyn and by an engine written independently of unidyn, at random states (q, q̇): the
// mass matrix M, the forcing f of Lagrange's equations M q̈ = f (book (3.7); no constraints) and
// the accelerations q̈ agree to kTolerance relative. The engine gives its own M, f and q̈ (and the
// random states, inside its joints' ranges); this header gives unidyn's and compares.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/tree_evaluation.hpp"

namespace unidyn::engine_oracle {
namespace {

// Both engines are exact on these models up to rounding: a relative error this large is a
// difference in the physics.
constexpr double kTolerance = 1e-10;

// A test model of tests/formats/models by name, or a file by its absolute path.
std::string formats_model(const std::string& file) {
  if (file.starts_with("/")) return file;
  std::string path = UNIDYN_FORMATS_DIR;
  path.append("/").append(file);
  return path;
}

// M, f of M q̈ = f, and q̈ at one state.
struct Dynamics {
  Eigen::MatrixXd M;
  Eigen::VectorXd f, qddot;
};

// The engine under comparison: its name and version, a random state inside its joints' ranges,
// and its M, f and q̈ there.
struct Engine {
  std::string name;
  std::function<void(test::Random&, Eigen::VectorXd& q, Eigen::VectorXd& qdot)> random_state;
  std::function<Dynamics(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot)> dynamics;
};

// unidyn's recursive dynamics of the tree (numeric/tree_evaluation.hpp): M and f by the
// composite-rigid-body and Newton–Euler algorithms, q̈ by the articulated-body algorithm.
Dynamics unidyn_dynamics(const CompiledSystem& compiled, const std::vector<double>& parameters,
                         CompiledSystemData& data, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& qdot) {
  EXPECT_TRUE(compiled.recursive()) << compiled.why_not_recursive();
  Eigen::VectorXd qddot, lambda;
  compiled.solve(0, q, qdot, parameters, qddot, lambda, data);
  compiled.mass_and_forcing(0, q, qdot, parameters, data);
  return {data.mass_matrix, data.forcing, qddot};
}

// unidyn's symbolic path: the compiled Lagrange's equations M q̈ = f (the dynamics tape, which
// the analyses use), solved here.
Dynamics symbolic_dynamics(const CompiledSystem& compiled, const std::vector<double>& parameters,
                           const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  std::vector<double> inputs{0.0};
  inputs.insert(inputs.end(), q.begin(), q.end());
  inputs.insert(inputs.end(), qdot.begin(), qdot.end());
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  const std::vector<double> out = compiled.dynamics().evaluate(inputs);
  const auto n = q.size();
  const Eigen::MatrixXd M =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          out.data(), n, n);
  const Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(out.data() + n * n, n);
  return {M, f, M.ldlt().solve(f)};
}

// q̈ by the articulated-body algorithm recorded at the parameters (numeric/recorded_tree.hpp), its
// tape evaluated: the program the native code runs. Its pivots are positive.
Eigen::VectorXd recorded_accelerations(const Tape& recorded, const std::vector<double>& parameters,
                                       const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  std::vector<double> inputs{0.0};
  inputs.insert(inputs.end(), q.begin(), q.end());
  inputs.insert(inputs.end(), qdot.begin(), qdot.end());
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  const std::vector<double> out = recorded.evaluate(inputs);
  EXPECT_GT(out.size(), static_cast<std::size_t>(q.size())) << "no pivot watched";
  for (std::size_t k = static_cast<std::size_t>(q.size()); k < out.size(); ++k) {
    EXPECT_GT(out[k], 0.0) << "pivot " << k - static_cast<std::size_t>(q.size());
  }
  return Eigen::Map<const Eigen::VectorXd>(out.data(), q.size());
}

// The tape of the recorded algorithm for the system at its parameters' values.
Tape recorded_tape(const System& system, const std::vector<double>& parameters) {
  const TreePlan plan = plan_tree(system);
  EXPECT_TRUE(plan.tree) << plan.why_not;
  return plan.tree ? plan.tree->recorded_accelerations(parameters) : Tape();
}

// The largest relative errors of M, f and q̈ of one evaluation against the engine's.
struct Errors {
  double M = 0, f = 0, qddot = 0;
  void add(const Dynamics& ours, const Dynamics& reference);
};

double relative(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).norm() / reference.norm();
}

void Errors::add(const Dynamics& ours, const Dynamics& reference) {
  M = std::max(M, relative(ours.M, reference.M));
  f = std::max(f, relative(ours.f, reference.f));
  qddot = std::max(qddot, relative(ours.qddot, reference.qddot));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Which of unidyn's evaluations a test compares with the engine's.
enum class Paths { recursive, both };

// The file loaded by unidyn, and compiled for the paths compared.
struct LoadedFile {
  commands::LoadedModel loaded;
  std::unique_ptr<CompiledSystem> compiled;
  double load_time = 0, derive_time = 0, compile_time = 0;
};

LoadedFile load_and_compile(const std::string& file, Paths paths) {
  LoadedFile result;
  auto start = std::chrono::steady_clock::now();
  result.loaded = commands::load_named_model(formats_model(file));
  result.load_time = seconds_since(start);
  CompileOptions options;
  options.recursive_from_coordinates = 0;  // the recursive algorithms at every size
  options.recursive_loops_from_coordinates = 0;
  // the compiled equations only when they are compared: the recursive ones need no derivation
  const System& system = result.loaded.system;
  start = std::chrono::steady_clock::now();
  const EquationsOfMotion equations =
      paths == Paths::both ? lagrange_equations(system) : EquationsOfMotion();
  result.derive_time = seconds_since(start);
  start = std::chrono::steady_clock::now();
  result.compiled = paths == Paths::both
                        ? std::make_unique<CompiledSystem>(system, equations, options)
                        : std::make_unique<CompiledSystem>(system, options);
  if (paths == Paths::both) result.compiled->dynamics();
  result.compile_time = seconds_since(start);
  return result;
}

// The loaded file against the engine at 20 random states: the largest relative (Frobenius)
// errors of M, f and q̈ — of the recursive algorithms and, with Paths::both, of the compiled
// Lagrange's equations — stay within kTolerance. Prints them, and unidyn's times to load, derive
// and compile.
void expect_agreement(const std::string& file, const LoadedFile& unidyn, Paths paths,
                      const Engine& engine) {
  const CompiledSystem& compiled = *unidyn.compiled;
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(unidyn.loaded.system, {}).parameters;
  const Tape recorded = recorded_tape(unidyn.loaded.system, parameters);
  test::Random random;
  Errors recursive, symbolic;
  double recorded_error = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q, qdot;
    engine.random_state(random, q, qdot);
    const Dynamics reference = engine.dynamics(q, qdot);
    recursive.add(unidyn_dynamics(compiled, parameters, data, q, qdot), reference);
    recorded_error =
        std::max(recorded_error,
                 relative(recorded_accelerations(recorded, parameters, q, qdot), reference.qddot));
    if (paths == Paths::both) {
      symbolic.add(symbolic_dynamics(compiled, parameters, q, qdot), reference);
    }
  }
  for (const Errors* e : {&recursive, &symbolic}) {
    EXPECT_LT(e->M, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
    EXPECT_LT(e->f, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
    EXPECT_LT(e->qddot, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
  }
  EXPECT_LT(recorded_error, kTolerance) << "recorded";
  test::record("M_error", std::max(recursive.M, symbolic.M));
  test::record("f_error", std::max(recursive.f, symbolic.f));
  test::record("qddot_error", std::max(recursive.qddot, symbolic.qddot));
  std::printf(
      "%s against %s: relative errors of the recursive algorithms M %.3g, f %.3g, q'' %.3g; of "
      "the compiled equations M %.3g, f %.3g, q'' %.3g (0: not compared); q'' of the recorded "
      "algorithm (%zu instructions) %.3g; unidyn's load %.3f s, derive %.3f s, compile %.3f s\n",
      file.c_str(), engine.name.c_str(), recursive.M, recursive.f, recursive.qddot, symbolic.M,
      symbolic.f, symbolic.qddot, recorded.instruction_count(), recorded_error, unidyn.load_time,
      unidyn.derive_time, unidyn.compile_time);
}

}  // namespace
}  // namespace unidyn::engine_oracle
