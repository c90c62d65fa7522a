// Andrews' squeezer (models/andrews-squeezer.yaml), the seven-body planar closed loop of Hairer &
// Wanner, Solving ODEs II §VII.7, against the literature's numbers, none computed here:
//  - at t = 0 (at rest): β'' = 14222.44391995412, Θ'' = −10666.83293996559 and the multipliers of
//    the first two loop rows 98.56687039624 and −6.1226883442557 (the literature's M q'' = f − Gᵀλ:
//    unidyn's λ, of M q'' = f + Aᵀλ, is their negative);
//  - at t = 0.03: the seven angles of the Test Set for IVP Solvers' reference (PSIDE at 1e-14),
//    which is itself accurate to about 1.4e-9 (an RK4 with Richardson extrapolation written from
//    the published formulas agrees with DOP853 at 1e-14 to 8e-13 and differs from it by that).
// And by every method: DOP853 and dopri5; CVODE, which used to fall into millions of steps with
// t + h = t at rtol 1e-10 (its error estimate was not projected with the state).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

const char* const kAngles[] = {"beta", "Theta", "gamma", "Phi", "delta", "Omega", "epsilon"};
constexpr std::array<double, 7> kReference = {
    15.81077119629904,  -15.75637105984298, 0.04082224013073101, -0.5347301163226948,
    0.5244099658805304, 0.5347301163226948, 1.048080741042263};

TEST(AndrewsSqueezer, AccelerationsAndMultipliersAtRest) {
  const System system = load_model(test::model_path("andrews-squeezer"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  Eigen::VectorXd qddot, lambda;
  compiled.solve(0.0, start.q, start.qdot, start.parameters, qddot, lambda, data);
  EXPECT_NEAR(qddot[0], 14222.44391995412, 1e-8);
  EXPECT_NEAR(qddot[1], -10666.83293996559, 1e-8);
  EXPECT_NEAR(lambda[0], -98.56687039624, 1e-9);
  EXPECT_NEAR(lambda[1], 6.1226883442557, 1e-10);
  for (Eigen::Index k = 2; k < 6; ++k) EXPECT_NEAR(lambda[k], 0.0, 1e-9) << k;
}

// The angles at t = 0.03 to the reference's own accuracy (tolerance 3e-9 with the reference off
// by 1.4e-9), for each method at a tolerance that reaches it; the driving moment's U = −mom β,
// found by unidyn, is in the energy, which the run keeps.
TEST(AndrewsSqueezer, ReferenceSolutionByEveryMethod) {
  const struct {
    const char* method;
    double rtol, tolerance;
  } runs[] = {{"dop853", 1e-13, 3e-9},
              {"dopri5", 1e-12, 3e-9},
              {"cvode", 1e-12, 1e-8},
              {"cvode", 1e-10, 1e-7}};
  for (const auto& r : runs) {
    const test::ModelRun run = test::run_model("andrews-squeezer", {}, [&](SimulationOptions& o) {
      o.method = r.method;
      o.rtol = r.rtol;
      o.atol = r.rtol / 100;
      o.max_steps = 20000;  // a trapped CVODE fails here, not after minutes
    });
    ASSERT_TRUE(run.summary.ok) << r.method << ": " << run.summary.message;
    const std::size_t last = run.rows.size() - 1;
    ASSERT_DOUBLE_EQ(run.at(last, "t"), 0.03);
    for (std::size_t i = 0; i < 7; ++i) {
      EXPECT_NEAR(run.at(last, kAngles[i]), kReference[i], r.tolerance)
          << r.method << " " << r.rtol << ": " << kAngles[i];
    }
    EXPECT_TRUE(run.summary.has_energy);
    EXPECT_LT(run.summary.energy_relative_drift, 1e-6) << r.method;
  }
}

}  // namespace
}  // namespace unidyn
