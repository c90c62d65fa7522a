// Exercise 5.6(a)–(f): a spring–rod pendulum with the non-integrable constraint (5.18).
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>

#include "support/model_run.hpp"
#include "unidyn/kinematics/integrability.hpp"

namespace unidyn {
namespace {

// (5.18) r1 θ̇1 + L2 θ̇2 = 0 is not integrable; scleronomic with e = 0, its force does no work —
// the constraint forces' power Σ R_i · v_i is 0 along the run — and so E is conserved (5.6(f)).
TEST(SpringRodPendulum, NonIntegrableConstraintDoesNoWork) {
  const test::ModelRun run = test::run_model("spring-rod-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_FALSE(constraint_integrability(run.system, 0).integrable);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "power"), 0.0, 1e-11) << run.at(i, "t");
  }
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  EXPECT_TRUE(run.summary.energy_not_conserved.empty()) << run.summary.energy_not_conserved;
  EXPECT_LT(run.summary.max_velocity_residual, 1e-11);
}

// Ex. 5.6 by hand, with q = (θ1, θ2, r1), r2 = L2 and z1 = z2 = 0 ((5.16), (b)), e_ri = cos θi E1 +
// sin θi E2, e_θi = −sin θi E1 + cos θi E2, φ = θ2 − θ1, M = m1 + m2, gravity −g E2:
//   r1 = r1 e_r1, r2 = r1 e_r1 + L2 e_r2 (the position vectors);
//   (c) T̃ = ½ M (ṙ1² + r1² θ̇1²) + ½ m2 L2² θ̇2² + m2 L2 θ̇2 (r1 θ̇1 cos φ − ṙ1 sin φ),
//       Ũ = ½ K1 (r1 − L0)² + M g r1 sin θ1 + m2 g L2 sin θ2;
//   (d), (e) with the force of (5.18), μ4 (e_θ1 − e_θ2) on m1 and μ4 e_θ2 on m2 (generalised
//   force μ4 (r1, L2, 0)):
//   θ1: M r1² θ̈1 + m2 L2 r1 cos φ θ̈2 + 2 M r1 ṙ1 θ̇1 − m2 L2 r1 sin φ θ̇2² = −M g r1 cos θ1 + μ4 r1
//   θ2: m2 L2 r1 cos φ θ̈1 + m2 L2² θ̈2 − m2 L2 sin φ r̈1 + m2 L2 (2 ṙ1 θ̇1 cos φ + r1 θ̇1² sin φ)
//       = −m2 g L2 cos θ2 + μ4 L2
//   r1: −m2 L2 sin φ θ̈2 + M r̈1 − m2 L2 cos φ θ̇2² − M r1 θ̇1² = −K1 (r1 − L0) − M g sin θ1
//   and (5.18) differentiated: r1 θ̈1 + ṙ1 θ̇1 + L2 θ̈2 = 0.
struct SpringRod {
  double m1, m2, K1, L0, L2, g;

  // q̈ and μ4 from the four equations above
  Eigen::Vector4d accelerations(const Eigen::Vector3d& q, const Eigen::Vector3d& v) const {
    const double M = m1 + m2, r = q[2], c = std::cos(q[1] - q[0]), s = std::sin(q[1] - q[0]);
    Eigen::Matrix4d A;
    A << M * r * r, m2 * L2 * r * c, 0, -r,                //
        m2 * L2 * r * c, m2 * L2 * L2, -m2 * L2 * s, -L2,  //
        0, -m2 * L2 * s, M, 0,                             //
        r, L2, 0, 0;
    const Eigen::Vector4d b(
        -M * g * r * std::cos(q[0]) - 2 * M * r * v[2] * v[0] + m2 * L2 * r * s * v[1] * v[1],
        -m2 * g * L2 * std::cos(q[1]) - m2 * L2 * (2 * v[2] * v[0] * c + r * v[0] * v[0] * s),
        -K1 * (r - L0) - M * g * std::sin(q[0]) + m2 * L2 * c * v[1] * v[1] + M * r * v[0] * v[0],
        -v[2] * v[0]);
    return A.fullPivLu().solve(b);
  }
  double energy(const Eigen::Vector3d& q, const Eigen::Vector3d& v) const {
    const double M = m1 + m2, r = q[2], c = std::cos(q[1] - q[0]), s = std::sin(q[1] - q[0]);
    const double T = 0.5 * M * (v[2] * v[2] + r * r * v[0] * v[0]) +
                     0.5 * m2 * L2 * L2 * v[1] * v[1] + m2 * L2 * v[1] * (r * v[0] * c - v[2] * s);
    const double U =
        0.5 * K1 * (r - L0) * (r - L0) + M * g * r * std::sin(q[0]) + m2 * g * L2 * std::sin(q[1]);
    return T + U;
  }
};

SpringRod spring_rod(const test::ModelRun& run) {
  return {run.parameter("m1"), run.parameter("m2"), run.parameter("K1"),
          run.parameter("L0"), run.parameter("L2"), run.parameter("g")};
}

// Ex. 5.6(a)–(e): at 50 random states (r1 ∈ (0.5, 1.5), any angles, θ̇2 = −r1 θ̇1/L2 from (5.18))
// unidyn's q̈ and λ(c518) against (i) q̈ and μ4 of the Lagrange equations typed above, and (ii) a
// Newton–Euler derivation of the book's constraint forces: with a1 = (r̈1 − r1 θ̇1²) e_r1 + (r1 θ̈1 +
// 2 ṙ1 θ̇1) e_θ1, a2 = a1 + L2 θ̈2 e_θ2 − L2 θ̇2² e_r2, the forces R_i = m_i a_i − F_i must be
// (5.17) + (e): R1 = μ1 e_r2 + μ4 (e_θ1 − e_θ2), R2 = −μ1 e_r2 + μ4 e_θ2 for some rod tension μ1,
// so R1 + R2 = μ4 e_θ1 and R2 · e_θ2 = μ4 (R1 has no part along E3 in the plane).
TEST(SpringRodPendulum, EquationsOfExercise56AgainstHandDerivedOnes) {
  const test::ModelRun run =
      test::run_model("spring-rod-pendulum", {}, [](SimulationOptions& o) { o.t_end = 0.01; });
  ASSERT_EQ(run.system.coordinates().size(), 3u);
  const SpringRod p = spring_rod(run);
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  const SimulationStart start = initial_state(run.system, {});
  CompiledSystemData data = compiled.make_data();
  std::mt19937 random(56);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double lagrange_error = 0, multiplier_error = 0, newton_error = 0;
  for (int k = 0; k < 50; ++k) {
    const Eigen::Vector3d q(3.14159 * u(random), 3.14159 * u(random), 1.0 + 0.5 * u(random));
    const double theta1_rate = 2 * u(random);
    const Eigen::Vector3d v(theta1_rate, -q[2] * theta1_rate / p.L2, 2 * u(random));
    Eigen::VectorXd qddot, lambda;
    compiled.solve(0.0, q, v, start.parameters, qddot, lambda, data);
    ASSERT_EQ(lambda.size(), 1);
    const Eigen::Vector4d hand = p.accelerations(q, v);
    lagrange_error = std::max(lagrange_error, (qddot - hand.head<3>()).cwiseAbs().maxCoeff());
    multiplier_error = std::max(multiplier_error, std::abs(lambda[0] - hand[3]));

    const auto e_r = [](double a) { return Eigen::Vector2d(std::cos(a), std::sin(a)); };
    const auto e_t = [](double a) { return Eigen::Vector2d(-std::sin(a), std::cos(a)); };
    const double r = q[2];
    const Eigen::Vector2d a1 =
        (qddot[2] - r * v[0] * v[0]) * e_r(q[0]) + (r * qddot[0] + 2 * v[2] * v[0]) * e_t(q[0]);
    const Eigen::Vector2d a2 = a1 + p.L2 * qddot[1] * e_t(q[1]) - p.L2 * v[1] * v[1] * e_r(q[1]);
    const Eigen::Vector2d F1 = Eigen::Vector2d(0, -p.m1 * p.g) - p.K1 * (r - p.L0) * e_r(q[0]);
    const Eigen::Vector2d F2(0, -p.m2 * p.g);
    const Eigen::Vector2d R1 = p.m1 * a1 - F1, R2 = p.m2 * a2 - F2;
    newton_error = std::max({newton_error, (R1 + R2 - lambda[0] * e_t(q[0])).cwiseAbs().maxCoeff(),
                             std::abs(R2.dot(e_t(q[1])) - lambda[0])});
  }
  // round-off of the two 3×3 + 1 solves (accelerations of order 10², μ4 of order 10)
  EXPECT_LT(lagrange_error, 1e-10);
  EXPECT_LT(multiplier_error, 1e-10);
  EXPECT_LT(newton_error, 1e-10);
  std::printf("Ex. 5.6 at 50 states: q'' %.3g, mu4 %.3g, Newton-Euler forces (5.17)+(e) %.3g\n",
              lagrange_error, multiplier_error, newton_error);
}

// Ex. 5.6(f): E = T̃ + Ũ, computed here from (c) typed above, keeps its initial value along the
// model's 10 s run and equals the run's energy column.
TEST(SpringRodPendulum, EnergyOfExercise56fConserved) {
  const test::ModelRun run = test::run_model("spring-rod-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const SpringRod p = spring_rod(run);
  const auto E = [&](std::size_t i) {
    return p.energy({run.at(i, "theta1"), run.at(i, "theta2"), run.at(i, "r1")},
                    {run.at(i, "der(theta1)"), run.at(i, "der(theta2)"), run.at(i, "der(r1)")});
  };
  const double E0 = E(0);
  double drift = 0, column = 0, theta1_range[2] = {1e300, -1e300};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    drift = std::max(drift, std::abs(E(i) - E0));
    column = std::max(column, std::abs(run.at(i, "energy") - E(i)));
    theta1_range[0] = std::min(theta1_range[0], run.at(i, "theta1"));
    theta1_range[1] = std::max(theta1_range[1], run.at(i, "theta1"));
  }
  EXPECT_GT(theta1_range[1] - theta1_range[0], 0.5);  // it swings
  // rtol 1e-12 per step over the run's steps; |E| of order 10 J
  EXPECT_LT(drift, 1e-9 * std::abs(E0));
  EXPECT_LT(column, 1e-12 * std::abs(E0));
  std::printf("Ex. 5.6(f): E0 = %.6g J, drift %.3g J, against the energy column %.3g J\n", E0,
              drift, column);
}

}  // namespace
}  // namespace unidyn
