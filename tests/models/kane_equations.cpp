// Kane's form (partial velocities, (10.16)) against Lagrange's equations on every bundled model:
// the same M and f at random states — two derivations that share no differentiation of T.
#include "unidyn/equations/kane.hpp"

#include <filesystem>
#include <random>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// M (row-major) and f as one tape of [t, q, q̇, p].
Tape mass_and_forcing(const System& system, const EquationsOfMotion& eq) {
  std::vector<GiNaC::ex> outputs(eq.mass_matrix.data.begin(), eq.mass_matrix.data.end());
  outputs.insert(outputs.end(), eq.forcing.begin(), eq.forcing.end());
  std::vector<GiNaC::ex> inputs{system.time()};
  for (const auto& q : system.coordinates()) inputs.push_back(q.value);
  for (const auto& q : system.coordinates()) inputs.push_back(q.rate);
  for (const auto& p : system.parameters) inputs.push_back(p.symbol);
  return Tape::compile(outputs, inputs);
}

TEST(KaneEquations, SameAsLagrangeOnEveryModel) {
  std::size_t models = 0;
  for (const auto& entry : std::filesystem::directory_iterator(UNIDYN_MODELS_DIR)) {
    // (the benchmark problems in models/iftomm have tests of their own: cli/singular_positions)
    if (!entry.is_regular_file()) continue;
    const System system = load_model(entry.path().string());
    const Tape lagrange = mass_and_forcing(system, lagrange_equations(system));
    const Tape kane = mass_and_forcing(system, kane_equations(system));
    // Euler parameters: the two agree on |e| = 1 (where ω is an angular velocity), so only at
    // the model's own start; elsewhere at random states around it
    bool parametrised = false;
    for (const auto& c : system.constraints) parametrised = parametrised || c.parametrisation;
    const SimulationStart start = initial_state(system, {});
    std::mt19937 random(5);
    std::uniform_real_distribution<double> value(-0.3, 0.3);
    double worst = 0;
    for (int trial = 0; trial < (parametrised ? 1 : 10); ++trial) {
      std::vector<double> in{0.7};
      for (double x : start.q) in.push_back(x + (trial > 0 ? value(random) : 0.0));
      for (double x : start.qdot) in.push_back(x + (trial > 0 ? value(random) : 0.0));
      in.insert(in.end(), start.parameters.begin(), start.parameters.end());
      const std::vector<double> a = lagrange.evaluate(in), b = kane.evaluate(in);
      double scale = 1, difference = 0;
      for (const double x : a) scale = std::max(scale, std::abs(x));
      for (std::size_t k = 0; k < a.size(); ++k) {
        difference = std::max(difference, std::abs(a[k] - b[k]));
      }
      worst = std::max(worst, difference / scale);
    }
    EXPECT_LT(worst, 1e-12) << entry.path().filename();
    ++models;
  }
  EXPECT_GE(models, 40u);
}

}  // namespace
}  // namespace unidyn
