// States where the equations are not finite, met on the way (integrate/simulation.cpp): a trial
// stage of a Runge–Kutta step or a Newton iterate inside CVODE that leaves the model's domain is a
// step to shrink, not the end of the run (issue 34: a stiff closed loop under CVODE stopped at
// t = 0.0103 with "the mass matrix is not finite"). A particle on x²/2 whose path carries
// k (1 − x²)^{3/4}: M = 1 + (9/4) k² x² (1 − x²)^{−1/2} is not finite beyond |x| = 1, and the
// motion from x = 0.9999 at rest turns back at 0.9999 (its energy x²/2 conserved), so every state
// it reaches is inside; a loose tolerance's big steps try states outside.
#include <gtest/gtest.h>

#include <cmath>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

const char* const kEdge = R"(unidyn: 1
name: Edge of the domain
parameters: {k: 1.0e-3}
coordinates: [x]
particles:
  P: {mass: 1, position: "[x, k*(1 - x^2)^(3/4), 0]"}
forces:
  - potential: x^2/2
initial: {x: 0.9999}
simulate: {t_end: 100, output_step: 0.1, rtol: 1e-3}
)";

// A run of the model: its summary and the largest |x| of its rows.
struct Outcome {
  SimulationSummary summary;
  std::size_t rows = 0;
  double largest_x = 0.0;
};

Outcome run_with(const std::string& method, double rtol) {
  const System system = parse_model(kEdge, "edge.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  SimulationOptions options = simulation_options(system.simulate);
  options.method = method;
  options.rtol = rtol;
  Outcome run;
  run.summary = simulate(system, compiled, initial_state(system, {}), options,
                         [&](const std::vector<double>& row) {
                           ++run.rows;
                           run.largest_x = std::max(run.largest_x, std::abs(row[1]));
                         });
  return run;
}

TEST(NotFiniteStates, TrialStatesOutsideTheDomainShrinkTheStep) {
  // dopri5's stages leave the domain near each turn: rejected, the run goes on (it stopped at
  // t ≈ 2.9 before)
  const Outcome loose = run_with("dopri5", 1e-3);
  EXPECT_TRUE(loose.summary.ok) << loose.summary.message;
  EXPECT_EQ(loose.rows, 1001u);
  EXPECT_LT(loose.largest_x, 1.0);
  // CVODE: its Newton iterates outside are recoverable errors; at this tolerance its interpolated
  // row at t = 6.2 is itself outside: the run stops there, saying so and when (not at a trial
  // state's t ≈ 3, nor "at t = 0")
  const Outcome cvode = run_with("cvode", 1e-3);
  EXPECT_FALSE(cvode.summary.ok);
  EXPECT_NE(cvode.summary.message.find("the state the integrator gives for this row is outside"),
            std::string::npos)
      << cvode.summary.message;
  EXPECT_GT(cvode.summary.failure_time, 6.0) << cvode.summary.message;
  // at a usual tolerance every method runs through, inside the domain, with its energy kept
  for (const std::string method : {"dopri5", "dop853", "cvode"}) {
    const Outcome run = run_with(method, 1e-8);
    EXPECT_TRUE(run.summary.ok) << method << ": " << run.summary.message;
    EXPECT_LT(run.largest_x, 1.0) << method;
    EXPECT_NEAR(run.largest_x, 0.9999, 1e-4) << method;
  }
}

}  // namespace
}  // namespace unidyn
