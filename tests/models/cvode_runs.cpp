// Simulations through SUNDIALS CVODE (`method: cvode`): a stiff damped oscillator against its
// closed form, a constrained top (projection inside CVODE's step) converging to the Dormand–Prince
// run, and a stick–slip event against the book's closed form.
#include <cmath>
#include <fstream>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// Runs a model with method cvode at rtol, atol = rtol / 100.
test::ModelRun run_cvode(const std::string& name, double rtol) {
  return test::run_model(name, {}, [rtol](SimulationOptions& o) {
    o.method = "cvode";
    o.rtol = rtol;
    o.atol = rtol * 1e-2;
  });
}

// m ẍ + c ẋ + K (x − L) = 0 with c² ≫ 4 m K: x − L = A e^(s1 t) + B e^(s2 t), s1 ≈ −K/c = −0.1,
// s2 ≈ −c/m = −10⁵. An explicit method needs |h| < 3/|s2| (~7·10⁵ steps to t = 20); BDF's steps
// follow the slow mode only.
TEST(CvodeRuns, StiffDampedOscillator) {
  const std::string path = ::testing::TempDir() + "stiff-damper.yaml";
  std::ofstream(path) << R"yaml(unidyn: 1
name: Stiff damped oscillator
parameters: {m: 1.0, K: 1.0e4, c: 1.0e5, L: 1.0}
coordinates: [x]
particles:
  P: {mass: m, position: [x, 0, 0]}
forces:
  - spring: {from: [0, 0, 0], to: P, stiffness: K, rest_length: L}
  - damper: {from: [0, 0, 0], to: P, coefficient: c}
initial: {x: 1.5}
simulate: {t_end: 20, output_step: 0.1, method: cvode, rtol: 1e-9}
)yaml";
  const System system = load_model(path);
  const CompiledSystem compiled(system, lagrange_equations(system));
  std::vector<std::vector<double>> rows;
  const SimulationSummary summary =
      simulate(system, compiled, initial_state(system, {}), simulation_options(system.simulate),
               [&](const std::vector<double>& row) { rows.push_back(row); });
  ASSERT_TRUE(summary.ok) << summary.message;
  const double m = 1, K = 1e4, c = 1e5, root = std::sqrt(c * c - 4 * m * K);
  const double s1 = (-c + root) / (2 * m), s2 = (-c - root) / (2 * m);
  const double A = 0.5 * s2 / (s2 - s1), B = -0.5 * s1 / (s2 - s1);
  ASSERT_EQ(rows.size(), 201u);
  for (const auto& row : rows) {
    const double t = row[0];
    EXPECT_NEAR(row[1] - 1, A * std::exp(s1 * t) + B * std::exp(s2 * t), 1e-8) << t;
  }
  EXPECT_LT(summary.stats.accepted_steps, 2000u);
}

// The heavy top on a ball joint with Euler parameters: CVODE, with the projection inside its step,
// converges to the Dormand–Prince run at rtol 1e-12 as its tolerance falls, and so does its energy
// error (BDF's global error grows with the ~100 turns of the top: about 10³ rtol here); its rows —
// dense output between projected steps — stay on |e| = 1 and the joint to within its tolerance.
TEST(CvodeRuns, ConstrainedTopConvergesToDormandPrince) {
  const test::ModelRun reference = test::run_model("heavy-top-socket");
  ASSERT_TRUE(reference.summary.ok) << reference.summary.message;
  std::vector<double> errors, drifts;
  for (const double rtol : {1e-10, 1e-12}) {
    const test::ModelRun run = run_cvode("heavy-top-socket", rtol);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    ASSERT_EQ(run.rows.size(), reference.rows.size());
    // |Ψ| is dimensionless; |A q̇| scales with the rates, |ė| up to ~25 /s here
    EXPECT_LT(run.summary.max_position_residual, 10 * rtol);
    EXPECT_LT(run.summary.max_velocity_residual, 10 * rtol * 25);
    drifts.push_back(run.summary.energy_relative_drift);
    const std::size_t last = run.rows.size() - 1;
    double error = 0;
    for (std::size_t k = 1; k < run.columns.size(); ++k) {
      const double expected = reference.rows[last][k];
      error = std::max(error, std::abs(run.rows[last][k] - expected) / (1 + std::abs(expected)));
    }
    errors.push_back(error);
  }
  EXPECT_LT(errors[0], 1e-3);
  EXPECT_LT(errors[1], errors[0] / 10) << errors[0];
  EXPECT_LT(drifts[0], 1e-6);
  EXPECT_LT(drifts[1], drifts[0] / 10) << drifts[0];
}

// (9.27)–(9.29): the sphere thrown without spin rolls from T = 2 u0/(7 μ_d g), then at 5/7 u0 —
// the friction phases and their event located through CVODE's dense output.
TEST(CvodeRuns, SlideThenRollEvent) {
  const test::ModelRun run = run_cvode("sphere-slide-roll", 1e-10);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double T = 2 * 2.0 / (7 * 0.2 * 9.81);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what, "contact 'table' sticks");
  EXPECT_NEAR(run.summary.phases[1].t, T, 1e-8);
  EXPECT_NEAR(run.at(run.rows.size() - 1, "der(x1)"), 5.0 / 7.0 * 2.0, 1e-8);
}

}  // namespace
}  // namespace unidyn
