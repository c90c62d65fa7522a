// Exercises 5.1 and 5.2: the chain of §5.2 with viscous dampers and a driving force.
#include <random>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The compiled equations give, at random states and times, the accelerations of the equations
// written here: m1 ẍ1 = −K1 x1 − K2 (x1 − x2) − c1 ẋ1 − c2 (ẋ1 − ẋ2),
// m2 ẍ2 = −K2 (x2 − x1) − c2 (ẋ2 − ẋ1) + P0 cos ωt.
TEST(DampedForcedChain, EquationsOfExercises51And52) {
  const double m1 = 1.0, m2 = 2.0, K1 = 10.0, K2 = 5.0, c1 = 0.3, c2 = 0.2, P0 = 1.5, w = 2.0;
  const System system = load_model(test::model_path("damped-forced-chain"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  std::mt19937 random(3);
  std::uniform_real_distribution<double> u(-0.4, 0.4);
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q(2), qdot(2), qddot, lambda;
    q << u(random), u(random);
    qdot << 5 * u(random), 5 * u(random);
    const double t = 10 * (u(random) + 0.4);
    compiled.solve(t, q, qdot, start.parameters, qddot, lambda, data);
    const double a1 =
        (-K1 * q[0] - K2 * (q[0] - q[1]) - c1 * qdot[0] - c2 * (qdot[0] - qdot[1])) / m1;
    const double a2 = (-K2 * (q[1] - q[0]) - c2 * (qdot[1] - qdot[0]) + P0 * std::cos(w * t)) / m2;
    EXPECT_NEAR(qddot[0], a1, 1e-12) << k;
    EXPECT_NEAR(qddot[1], a2, 1e-12) << k;
  }
}

}  // namespace
}  // namespace unidyn
