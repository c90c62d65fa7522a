// Every bundled model (each *.yaml in models/, found by listing the directory, so a new model is
// covered without touching this file): it loads, Newton's and Lagrange's equations agree (the
// projection of F + R = m a onto the partial velocities is Lagrange's equations, §4.4–4.6), and a
// short simulation runs and stays on the constraint manifolds.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "support/oracles.hpp"
#include "unidyn/equations/equivalence.hpp"
#include "unidyn/equations/newton.hpp"

namespace unidyn {
namespace {

// Keeps a measured value in the test report (--gtest_output=xml).
void record(const std::string& name, double value) {
  std::ostringstream text;
  text << std::scientific << std::setprecision(3) << value;
  ::testing::Test::RecordProperty(name, text.str());
}

// The names (file stems) of the bundled models, sorted.
std::vector<std::string> bundled_models() {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(UNIDYN_MODELS_DIR)) {
    if (entry.is_regular_file() && entry.path().extension() == ".yaml") {
      names.push_back(entry.path().stem().string());
    }
  }
  std::sort(names.begin(), names.end());
  return names;
}

// A test name may hold letters, digits and underscores only.
std::string test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& c : name) {
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  }
  return name;
}

// The listing finds the models the validation tests are written for (so the parametrised tests
// below cannot pass by finding nothing).
TEST(BundledModels, DirectoryIsListed) {
  const std::vector<std::string> names = bundled_models();
  for (const char* expected : {"kepler", "two-body", "pendulum-cart", "double-pendulum",
                               "spring-chain", "dumbbell-satellite"}) {
    EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
  }
}

class AllModels : public ::testing::TestWithParam<std::string> {};

// §4.4–4.6: Newton's F + R = m a projected onto ∂r/∂q^i equals Lagrange's equation i, identically
// (after simplification) and at random states (to round-off: 1e-12 of the largest term).
TEST_P(AllModels, NewtonAndLagrangeAgree) {
#if defined(__SANITIZE_ADDRESS__)
  // (the same code paths as every other model's, 100 s of GiNaC under the sanitizers: a fifth
  // of their whole run; checked in the plain build)
  if (GetParam() == "satellite-relative-equilibria") {
    GTEST_SKIP() << "checked in the plain build";
  }
#endif
  const System system = load_model(test::model_path(GetParam()));
  ASSERT_FALSE(system.coordinates().empty());
  const EquationsOfMotion lagrange = lagrange_equations(system);
  const NewtonEquations newton = newton_equations(system);
  const EquivalenceReport report = check_equivalence(system, lagrange, newton);
  EXPECT_TRUE(report.symbolic_zero);
  for (std::size_t i = 0; i < report.symbolic_residual.size(); ++i) {
    EXPECT_TRUE(report.symbolic_residual[i].is_zero())
        << "coordinate " << system.coordinates()[i].name << ": " << report.symbolic_residual[i];
  }
  EXPECT_GT(report.states, 0);
  EXPECT_LT(report.numeric_relative_residual, 1e-12);
  record("numeric_relative_residual", report.numeric_relative_residual);
}

// A 0.5 s run from the model's own initial state — the values it leaves out computed from the
// constraints, as `unidyn simulate` does — succeeds and keeps |Ψ| and |A q̇ + e| below 1e-9 (the
// projection after every step holds them at ~1e-14; dopri5 at rtol 1e-12 would drift far less
// than 1e-9 in 0.5 s even without it).
TEST_P(AllModels, ShortSimulationStaysOnTheConstraints) {
  const auto run = test::run_model(
      GetParam(), {},
      [](SimulationOptions& options) {
        options.t_end = 0.5;
        options.output_step = 0.05;
      },
      true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message << " at t = " << run.summary.failure_time;
  // 0, 0.05, …, 0.5, and a row at each event between
  ASSERT_EQ(run.on_grid(0.05).rows.size(), 11u);
  for (std::size_t i = 1; i < run.rows.size(); ++i) ASSERT_GT(run.rows[i][0], run.rows[i - 1][0]);
  EXPECT_EQ(run.rows.back().front(), 0.5);
  EXPECT_EQ(run.columns.size(), run.rows.front().size());
  for (const auto& row : run.rows) {
    for (double value : row) ASSERT_TRUE(std::isfinite(value));
  }
  EXPECT_LT(run.summary.max_position_residual, 1e-9);
  EXPECT_LT(run.summary.max_velocity_residual, 1e-9);
  record("max_position_residual", run.summary.max_position_residual);
  record("max_velocity_residual", run.summary.max_velocity_residual);
  record("energy_relative_drift", run.summary.energy_relative_drift);
}

INSTANTIATE_TEST_SUITE_P(Bundled, AllModels, ::testing::ValuesIn(bundled_models()), test_name);

}  // namespace
}  // namespace unidyn
