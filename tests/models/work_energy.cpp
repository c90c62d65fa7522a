// Exercise 9.11: Koenig's decomposition T = ½ m v̄·v̄ + ½ H·ω and the work–energy theorem
// Ṫ = F·v̄ + M·ω for a rigid body with a force and a moment acting (not the torque-free case).
#include <array>
#include <cmath>

#include "support/model_run.hpp"
#include "support/rigid_kinematics.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// A free body (Euler parameters) pushed by F = F0 e3 + F0 sin t E1 at its centre of mass and
// turned by M = M0 e1 + M0 cos t E3: both do work, neither has a potential.
constexpr const char* kPushedBody = R"yaml(unidyn: 1
name: Pushed and turned body
parameters: {m: 2.0, l1: 2.0, l2: 4.0, l3: 5.0, F0: 3.0, M0: 1.5}
coordinates: [x, y, z, e0, e1, e2, e3]
bodies:
  body:
    mass: m
    inertia: [l1, l2, l3]
    rotation: {quaternion: [e0, e1, e2, e3]}
    center: [x, y, z]
forces:
  - force: {on: body, value: F0*body.e3 + F0*sin(t)*E1}
  - moment: {on: body, value: M0*body.e1 + M0*cos(t)*E3}
initial: {e0: 1, der(x): 1.0, der(e2): 0.25, der(e3): 2.5}
simulate: {t_end: 4, output_step: 0.001, rtol: 1e-12}
)yaml";

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// What the test computes from one row: the body's basis e_i and ω from the Euler parameters and
// their rates alone (support/rigid_kinematics.hpp), and v̄.
struct RowKinematics {
  std::array<Vec, 3> basis;
  Vec omega, velocity;
};

RowKinematics kinematics(const test::ModelRun& run, std::size_t k) {
  const test::EulerParameterKinematics q = test::euler_parameter_kinematics(run, k);
  return {q.basis, q.omega, {run.at(k, "der(x)"), run.at(k, "der(y)"), run.at(k, "der(z)")}};
}

// T = ½ m v̄·v̄ + ½ H·ω with H = Σ λ_i (ω·e_i) e_i, so H·ω = Σ λ_i (ω·e_i)², and Ṫ = F·v̄ + M·ω
// integrated by Simpson's rule: T(t) − T(0) = ∫ (F·v̄ + M·ω) dt, everything from the rows' state.
TEST(WorkEnergy, KoenigsDecompositionAndTheWorkOfAForceAndAMomentOfExercise911) {
  const test::ModelRun run = test::run_system(parse_model(kPushedBody, "pushed-body.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = run.parameter("m"), F0 = run.parameter("F0"), M0 = run.parameter("M0");
  const std::array<double, 3> lambda{run.parameter("l1"), run.parameter("l2"), run.parameter("l3")};
  std::vector<double> T, power;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const RowKinematics r = kinematics(run, k);
    const double t = run.at(k, "t");
    double rotational = 0;
    for (int i = 0; i < 3; ++i) rotational += lambda[i] * std::pow(dot(r.omega, r.basis[i]), 2);
    T.push_back(0.5 * m * dot(r.velocity, r.velocity) + 0.5 * rotational);
    Vec F = r.basis[2], M = r.basis[0];
    for (int j = 0; j < 3; ++j) {
      F[j] *= F0;
      M[j] *= M0;
    }
    F[0] += F0 * std::sin(t);
    M[2] += M0 * std::cos(t);
    power.push_back(dot(F, r.velocity) + dot(M, r.omega));
  }
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const double h = run.at(1, "t") - run.at(0, "t");
  double work_error = 0, work = 0;
  for (std::size_t k = 2; k < run.rows.size(); k += 2) {
    work += h / 3 * (power[k - 2] + 4 * power[k - 1] + power[k]);
    work_error = std::max(work_error, std::abs(T[k] - T[0] - work));
  }
  // the kinetic energy changes by several joules: the theorem is not met by T staying constant
  EXPECT_GT(std::abs(T.back() - T.front()), 1.0);
  // Simpson's error at h = 1 ms (~1e-12) and the run's (rtol 1e-12)
  EXPECT_LT(work_error, 1e-9);
  std::printf("T: %.6g -> %.6g; |T - T0 - work| %.3g\n", T.front(), T.back(), work_error);
}

}  // namespace
}  // namespace unidyn
