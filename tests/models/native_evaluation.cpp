// Native code against the tape on the bundled models: the same compiled equations evaluated both
// ways give the same q̈, λ and observations, bit for bit, and the same simulation rows.
#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

CompileOptions native_in(const std::string& name) {
  CompileOptions options;
  options.native = true;
  options.native_options.cache_directory = ::testing::TempDir() + "unidyn-native-models-" + name;
  std::filesystem::remove_all(options.native_options.cache_directory);
  return options;
}

class NativeEvaluation : public ::testing::TestWithParam<std::string> {};

// q̈ and λ from solve(), and observe(), at random states.
TEST_P(NativeEvaluation, SolveAndObserveAsTheTape) {
  const System system = load_model(test::model_path(GetParam()));
  const EquationsOfMotion equations = lagrange_equations(system);
  const CompiledSystem tape(system, equations);
  const CompiledSystem native(system, equations, native_in(GetParam()));
  ASSERT_TRUE(native.native()) << native.evaluation();
  EXPECT_FALSE(tape.native());
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data_tape = tape.make_data(), data_native = native.make_data();
  const auto n = static_cast<Eigen::Index>(tape.coordinate_count());
  std::mt19937 random(11);
  std::uniform_real_distribution<double> value(-0.5, 0.5);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd q = start.q, qdot = start.qdot;
    for (Eigen::Index i = 0; i < n; ++i) {
      q[i] += trial == 0 ? 0.0 : value(random);
      qdot[i] += trial == 0 ? 0.0 : value(random);
    }
    Eigen::VectorXd qddot_tape, lambda_tape, qddot_native, lambda_native;
    bool solved = true;
    try {
      tape.solve(0.3, q, qdot, start.parameters, qddot_tape, lambda_tape, data_tape);
    } catch (const std::runtime_error&) {
      solved = false;  // a random state off the constraints may be singular: both must say so
    }
    if (!solved) {
      EXPECT_THROW(
          native.solve(0.3, q, qdot, start.parameters, qddot_native, lambda_native, data_native),
          std::runtime_error);
      continue;
    }
    native.solve(0.3, q, qdot, start.parameters, qddot_native, lambda_native, data_native);
    EXPECT_EQ(qddot_native, qddot_tape) << GetParam() << " trial " << trial;
    EXPECT_EQ(lambda_native, lambda_tape) << GetParam() << " trial " << trial;
    std::vector<double> seen_tape(tape.observation_count()), seen_native(seen_tape.size());
    tape.observe(0.3, q, qdot, qddot_tape, lambda_tape, start.parameters, seen_tape, data_tape);
    native.observe(0.3, q, qdot, qddot_native, lambda_native, start.parameters, seen_native,
                   data_native);
    for (std::size_t k = 0; k < seen_tape.size(); ++k) {
      if (std::isnan(seen_tape[k])) continue;
      EXPECT_EQ(seen_native[k], seen_tape[k]) << tape.observation_names()[k];
    }
  }
}

// A whole run, events and phases included, row for row.
TEST_P(NativeEvaluation, SameSimulationRows) {
  const System system = load_model(test::model_path(GetParam()));
  const EquationsOfMotion equations = lagrange_equations(system);
  SimulationOptions options = simulation_options(system.simulate);
  options.t_end = std::min(options.t_end, 2.0);
  std::vector<std::vector<double>> rows_tape, rows_native;
  const auto run = [&](const CompiledSystem& compiled, std::vector<std::vector<double>>& rows) {
    return simulate(system, compiled, initial_state(system, {}), options,
                    [&rows](const std::vector<double>& row) { rows.push_back(row); });
  };
  const SimulationSummary s_tape = run(CompiledSystem(system, equations), rows_tape);
  const SimulationSummary s_native =
      run(CompiledSystem(system, equations, native_in(GetParam() + "-run")), rows_native);
  ASSERT_TRUE(s_tape.ok && s_native.ok) << s_tape.message << s_native.message;
  ASSERT_EQ(rows_native.size(), rows_tape.size());
  for (std::size_t i = 0; i < rows_tape.size(); ++i) {
    for (std::size_t k = 0; k < rows_tape[i].size(); ++k) {
      if (std::isnan(rows_tape[i][k])) continue;
      ASSERT_EQ(rows_native[i][k], rows_tape[i][k]) << GetParam() << " row " << i << " col " << k;
    }
  }
  EXPECT_EQ(s_native.phases.size(), s_tape.phases.size());
}

INSTANTIATE_TEST_SUITE_P(Models, NativeEvaluation,
                         ::testing::Values("double-pendulum", "heavy-top", "heavy-top-socket",
                                           "rolling-disk", "braking-cart",
                                           "particle-leaving-sphere", "hinged-bodies-pinned"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

// Without a compiler the tape evaluates, and evaluation() says why.
TEST(NativeEvaluationFallback, NoCompilerKeepsTheTape) {
  const System system = load_model(test::model_path("double-pendulum"));
  CompileOptions options = native_in("fallback");
  options.native_options.compiler = "/nonexistent/c++";
  const CompiledSystem compiled(system, lagrange_equations(system), options);
  EXPECT_FALSE(compiled.native());
  EXPECT_EQ(compiled.evaluation().rfind("tape (native code: ", 0), 0u) << compiled.evaluation();
  Eigen::VectorXd qddot, lambda;
  CompiledSystemData data = compiled.make_data();
  const SimulationStart start = initial_state(system, {});
  compiled.solve(0, start.q, start.qdot, start.parameters, qddot, lambda, data);
  EXPECT_TRUE(qddot.allFinite());
}

// Compiled in the background: a run starts on the tape and goes on in native code once it is
// ready — here it waits for that halfway, so the switch falls inside the run — and its rows are
// the tape's, bit for bit; the compilation leaves the library in the cache, where the next one
// finds it at once.
TEST(NativeEvaluationBackground, SwitchesWithoutChangingARow) {
  const System system = load_model(test::model_path("double-pendulum"));
  const EquationsOfMotion equations = lagrange_equations(system);
  SimulationOptions options = simulation_options(system.simulate);
  options.t_end = 20.0;
  CompileOptions background = native_in("background");
  background.background = true;
  std::vector<std::vector<double>> rows_tape, rows_background;
  ASSERT_TRUE(simulate(system, CompiledSystem(system, equations), initial_state(system, {}),
                       options, [&](const std::vector<double>& row) { rows_tape.push_back(row); })
                  .ok);
  std::string evaluation;
  {
    const CompiledSystem compiled(system, equations, background);
    EXPECT_FALSE(compiled.native());  // nothing in the cache: the tape at the start
    const auto compiling = [&] {
      return compiled.evaluation().find("still compiling") != std::string::npos;
    };
    EXPECT_TRUE(compiling());
    const auto emit = [&](const std::vector<double>& row) {
      // halfway: wait (at most 5 min) for the native code, which evaluates the rest
      for (int wait = 0;
           rows_background.size() == rows_tape.size() / 2 && compiling() && wait < 30000; ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      rows_background.push_back(row);
    };
    ASSERT_TRUE(simulate(system, compiled, initial_state(system, {}), options, emit).ok);
    evaluation = compiled.evaluation();
  }
  EXPECT_NE(evaluation.find("compiled in"), std::string::npos) << evaluation;
  EXPECT_NE(evaluation.find("in the background, the tape until then"), std::string::npos)
      << evaluation;
  EXPECT_EQ(rows_background, rows_tape);
  // the library is now cached: the next one has native code from the start
  const CompiledSystem next(system, equations, background);
  EXPECT_TRUE(next.native()) << next.evaluation();
  EXPECT_EQ(next.evaluation().rfind("native code (cached: ", 0), 0u) << next.evaluation();
}

}  // namespace
}  // namespace unidyn
