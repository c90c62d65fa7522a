// Validation of models/two-body.yaml against Exercise 4.6 (the two-body problem): the centre of
// mass moves uniformly, E and H_O are conserved, and the relative vector r2 − r1 moves on a Kepler
// orbit (§2.8) with GM replaced by G(m1 + m2) and the reduced mass m1 m2/(m1 + m2).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::record;

// The default parameters of two-body.yaml.
constexpr double G = 1.0, m1 = 1.0, m2 = 0.5, m = m1 + m2, reduced_mass = m1 * m2 / m;

// Positions and velocities of the two particles in a row.
struct Bodies {
  Vec3 r1, r2, v1, v2;
};

Bodies bodies(const test::ModelRun& run, std::size_t i) {
  return {Vec3(run.at(i, "x1"), run.at(i, "y1"), run.at(i, "z1")),
          Vec3(run.at(i, "x2"), run.at(i, "y2"), run.at(i, "z2")),
          Vec3(run.at(i, "der(x1)"), run.at(i, "der(y1)"), run.at(i, "der(z1)")),
          Vec3(run.at(i, "der(x2)"), run.at(i, "der(y2)"), run.at(i, "der(z2)"))};
}

Vec3 angular_momentum(const Bodies& b) {
  return b.r1.cross(m1 * b.v1) + b.r2.cross(m2 * b.v2);
}

double energy(const Bodies& b) {
  return 0.5 * m1 * b.v1.squaredNorm() + 0.5 * m2 * b.v2.squaredNorm() -
         G * m1 * m2 / (b.r2 - b.r1).norm();
}

// Energy of the relative motion: ½ (m1m2/(m1+m2)) ‖ẋ‖² − G m1 m2/‖x‖, x = r2 − r1.
double relative_energy(const Bodies& b) {
  return 0.5 * reduced_mass * (b.v2 - b.v1).squaredNorm() - G * m1 * m2 / (b.r2 - b.r1).norm();
}

const test::ModelRun& default_run() {
  static const test::ModelRun run = test::run_model("two-body");
  return run;
}

// The tests below assume the model file's parameter values.
TEST(TwoBody, ModelFileParameters) {
  const System system = load_model(test::model_path("two-body"));
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  EXPECT_EQ(value("G"), G);
  EXPECT_EQ(value("m1"), m1);
  EXPECT_EQ(value("m2"), m2);
}

// Exercise 4.6(a): the momentum is conserved, so C moves uniformly on a straight line,
// r̄(t) = r̄(0) + v̄(0) t.
TEST(TwoBody, CentreOfMassMovesUniformly) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Bodies start = bodies(run, 0);
  const Vec3 c0 = (m1 * start.r1 + m2 * start.r2) / m;
  const Vec3 v0 = (m1 * start.v1 + m2 * start.v2) / m;
  double position_error = 0.0, velocity_error = 0.0, momentum_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Bodies b = bodies(run, i);
    const Vec3 c = (m1 * b.r1 + m2 * b.r2) / m;
    const Vec3 v = (m1 * b.v1 + m2 * b.v2) / m;
    position_error = std::max(position_error, (c - c0 - v0 * run.at(i, "t")).cwiseAbs().maxCoeff());
    velocity_error = std::max(velocity_error, (v - v0).cwiseAbs().maxCoeff());
    momentum_error = std::max(momentum_error, std::abs(run.at(i, "Gx") - m * v0.x()));
  }
  // Runge–Kutta methods keep linear invariants exactly: only round-off accumulates
  EXPECT_LT(position_error, 1e-12);
  EXPECT_LT(velocity_error, 1e-13);
  EXPECT_LT(momentum_error, 1e-13);
  record("centre_of_mass_position_error", position_error);
  record("centre_of_mass_velocity_error", velocity_error);
}

// Exercise 4.6(b), (c): H_O and E = T − G m1 m2/‖r2 − r1‖ keep their initial values (computed here
// from the rows), and the columns are those quantities.
TEST(TwoBody, EnergyAndAngularMomentumConserved) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Bodies start = bodies(run, 0);
  const double E0 = energy(start);
  const Vec3 H0 = angular_momentum(start);
  double energy_error = 0.0, momentum_error = 0.0, column_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Bodies b = bodies(run, i);
    const Vec3 H(run.at(i, "Hx"), run.at(i, "Hy"), run.at(i, "Hz"));
    column_error = std::max({column_error, std::abs(run.at(i, "energy") - energy(b)) / std::abs(E0),
                             (H - angular_momentum(b)).norm() / H0.norm()});
    energy_error = std::max(energy_error, std::abs(run.at(i, "energy") - E0));
    momentum_error = std::max(momentum_error, (H - H0).norm());
  }
  EXPECT_LT(column_error, 1e-14);
  // relative drift of a few rtol = 1e-12 over the ~10³ steps of the run
  EXPECT_LT(energy_error / std::abs(E0), 1e-10);
  EXPECT_LT(momentum_error / H0.norm(), 1e-10);
  record("energy_relative_drift", energy_error / std::abs(E0));
  record("H_relative_drift", momentum_error / H0.norm());
}

// Exercise 4.6(d), (e) with §2.8: x = r2 − r1 obeys ẍ = −G(m1 + m2) x/‖x‖³, a Kepler orbit with
// a = −G m1 m2/(2 E_rel) and period T = 2π a^{3/2}/√(G(m1 + m2)): after T, x and ẋ are back.
TEST(TwoBody, RelativeMotionIsAKeplerOrbit) {
  const Bodies start = bodies(default_run(), 0);
  const double E_rel = relative_energy(start);
  ASSERT_LT(E_rel, 0.0);  // a bound (elliptic) orbit
  const double a = -G * m1 * m2 / (2.0 * E_rel);
  const double period = 2.0 * kPi * std::pow(a, 1.5) / std::sqrt(G * m);
  const auto run =
      test::run_model("two-body", {}, [&](SimulationOptions& options) { options.t_end = period; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_EQ(run.at(last, "t"), period);
  const Bodies end = bodies(run, last);
  const Vec3 x0 = start.r2 - start.r1, u0 = start.v2 - start.v1;
  const double position_error = (end.r2 - end.r1 - x0).norm() / x0.norm();
  const double velocity_error = (end.v2 - end.v1 - u0).norm() / u0.norm();
  // the global error of one revolution at rtol 1e-12
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(velocity_error, 1e-9);
  record("relative_position_error", position_error);
  record("relative_velocity_error", velocity_error);

  // Halfway round, the relative vector has not come back (the check above is not trivially met).
  const std::size_t half = last / 2;
  const Bodies middle = bodies(run, half);
  EXPECT_GT((middle.r2 - middle.r1 - x0).norm(), 0.1);

  // Along the way: E = E_rel + ½ m ‖v̄‖² (Koenig), E_rel constant, and x stays in the plane
  // normal to x(0) × ẋ(0).
  const Vec3 normal = x0.cross(u0).normalized();
  const Vec3 v0 = (m1 * start.v1 + m2 * start.v2) / m;
  double koenig_error = 0.0, relative_energy_error = 0.0, plane_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Bodies b = bodies(run, i);
    const double E_r = relative_energy(b);
    koenig_error =
        std::max(koenig_error, std::abs(run.at(i, "energy") - E_r - 0.5 * m * v0.squaredNorm()));
    relative_energy_error = std::max(relative_energy_error, std::abs(E_r - E_rel));
    plane_error = std::max(plane_error, std::abs((b.r2 - b.r1).dot(normal)));
  }
  EXPECT_LT(koenig_error / std::abs(E_rel), 1e-10);
  EXPECT_LT(relative_energy_error / std::abs(E_rel), 1e-10);
  EXPECT_LT(plane_error, 1e-10);
  record("relative_energy_drift", relative_energy_error / std::abs(E_rel));
  record("orbital_plane_error", plane_error);
}

// Exercise 4.5(d), the gravitational pair force by force: models/two-body.yaml with the
// particles' accelerations as outputs; m1 a1 = G m1 m2 x/|x|³ = −m2 a2 (x = r2 − r1, from
// U = −G m1 m2/|x|, F_con,i = −∂U/∂r_i), computed here from the row's positions.
TEST(TwoBody, GravitationalForcesAreEqualOppositeAlongTheLine) {
  std::ifstream file(test::model_path("two-body"));
  std::stringstream text;
  text << file.rdbuf() << "outputs:\n  a1: A.acceleration\n  a2: B.acceleration\n";
  const test::ModelRun run = test::run_system(parse_model(text.str(), "two-body.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double error = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Bodies b = bodies(run, i);
    const Vec3 x = b.r2 - b.r1;
    const Vec3 F12 = G * m1 * m2 * x / std::pow(x.norm(), 3);
    const Vec3 a1(run.at(i, "a1.x"), run.at(i, "a1.y"), run.at(i, "a1.z"));
    const Vec3 a2(run.at(i, "a2.x"), run.at(i, "a2.y"), run.at(i, "a2.z"));
    error =
        std::max({error, (m1 * a1 - F12).norm() / F12.norm(), (m2 * a2 + F12).norm() / F12.norm()});
  }
  std::printf("Two bodies: m1 a1 and m2 a2 against ±G m1 m2 x/|x|³: %.3g (relative)\n", error);
  EXPECT_LT(error, 1e-13);  // both sides at the same state: round-off
  record("gravitational_pair_error", error);
}

// Exercise 4.5(c), (4.43): two free particles (gravity −g E3 on both) joined by a rod whose length
// is prescribed, Ψ = |r2 − r1| − L(t), L(t) = L + a sin ωt.
constexpr const char* kRheonomicRod = R"yaml(unidyn: 1
name: Two particles on a rod of prescribed length
parameters: {m1: 1.0, m2: 0.5, L: 1.0, a: 0.3, w: 2.0, u: 1.5, g: 9.81}
coordinates: [x1, y1, z1, x2, y2, z2]
particles:
  A: {mass: m1, position: [x1, y1, z1]}
  B: {mass: m2, position: [x2, y2, z2]}
forces:
  - gravity: -g*E3
constraints:
  - {name: rod, position: sqrt((x2 - x1)^2 + (y2 - y1)^2 + (z2 - z1)^2) - L - a*sin(w*t)}
initial: {x2: L, der(x1): 0.1, der(y1): -0.2, der(z1): 0.3,
          der(x2): 0.1 + a*w, der(y2): -0.2 + u, der(z2): 0.3}
simulate: {t_end: 6, output_step: 0.001, rtol: 1e-12}
outputs:
  # m a − F on each particle: the constraint forces the motion needs
  R1: A.constraint_force
  R2: B.constraint_force
)yaml";

// Exercise 4.5(c) solved by hand. F_c1 = λ ∂Ψ/∂r1 = −λ e, F_c2 = λ ∂Ψ/∂r2 = +λ e with e = x/|x|,
// x = r2 − r1: equal and opposite because Ψ depends on |r2 − r1| only. Then
//   - the centre of mass moves as if free: r̄ = r̄0 + v̄0 t − ½ g t² E3 (F_c1 + F_c2 = 0);
//   - ẍ = F_c2/m2 − F_c1/m1 = (λ/μ_r) e with μ_r = m1m2/(m1 + m2), so x × ẋ is constant: x stays
//     in the plane E1–E2 of x(0) = L E1, ẋ(0) = a ω E1 + u E2; with x = L(t)(cos θ, sin θ, 0),
//     L² θ̇ = h = L u (θ(t) = ∫ h/L² dt, Simpson's rule here) and the radial part of ẍ gives
//       λ = μ_r (L̈ − L θ̇²) = μ_r (L̈ − h²/L³),   F_c2 = −F_c1 = μ_r (L̈ − h²/L³) e.
// Compared with: the run's r1, r2 (through r̄ and x), its multiplier lambda(rod), and its
// constraint-force columns R1 = m1 a1 − F1 and R2 = m2 a2 − F2.
TEST(TwoBody, RheonomicRodForcesOfExercise45c) {
  const test::ModelRun run = test::run_system(parse_model(kRheonomicRod, "rheonomic-rod.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double M1 = run.parameter("m1"), M2 = run.parameter("m2"), L = run.parameter("L"),
               a = run.parameter("a"), w = run.parameter("w"), u = run.parameter("u"),
               g = run.parameter("g");
  const double mu_r = M1 * M2 / (M1 + M2), h = L * u;
  const auto length = [&](double t) { return L + a * std::sin(w * t); };
  const auto length_acceleration = [&](double t) { return -a * w * w * std::sin(w * t); };
  const Bodies start = bodies(run, 0);
  const Vec3 c0 = (M1 * start.r1 + M2 * start.r2) / (M1 + M2);
  const Vec3 u0 = (M1 * start.v1 + M2 * start.v2) / (M1 + M2);
  const double dt = run.at(1, "t") - run.at(0, "t");
  double theta = 0, centre_error = 0, relative_error = 0, lambda_error = 0, force_error = 0,
         largest = 0, smallest = INFINITY;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (i > 0) {  // θ from the previous row by Simpson's rule on [t − dt, t]
      const auto rate = [&](double s) { return h / (length(s) * length(s)); };
      theta += dt / 6 * (rate(t - dt) + 4 * rate(t - dt / 2) + rate(t));
    }
    const Bodies b = bodies(run, i);
    const Vec3 c = (M1 * b.r1 + M2 * b.r2) / (M1 + M2);
    centre_error = std::max(centre_error, (c - c0 - u0 * t + Vec3(0, 0, 0.5 * g * t * t)).norm());
    const Vec3 e(std::cos(theta), std::sin(theta), 0.0);
    relative_error = std::max(relative_error, (b.r2 - b.r1 - length(t) * e).norm());
    const double Lt = length(t);
    const double lambda = mu_r * (length_acceleration(t) - h * h / (Lt * Lt * Lt));
    lambda_error = std::max(lambda_error, std::abs(run.at(i, "lambda(rod)") - lambda));
    const Vec3 R1(run.at(i, "R1.x"), run.at(i, "R1.y"), run.at(i, "R1.z"));
    const Vec3 R2(run.at(i, "R2.x"), run.at(i, "R2.y"), run.at(i, "R2.z"));
    force_error = std::max({force_error, (R1 + lambda * e).norm(), (R2 - lambda * e).norm()});
    largest = std::max(largest, std::abs(lambda));
    smallest = std::min(smallest, std::abs(lambda));
  }
  std::printf(
      "Rheonomic rod (Ex. 4.5(c)): |λ| from %.3g to %.3g N; centre of mass %.3g m, x = L(t) e(θ) "
      "%.3g m, λ = μ_r(L̈ − h²/L³) %.3g N, R1 = −R2 = −λe %.3g N over %g s\n",
      smallest, largest, centre_error, relative_error, lambda_error, force_error,
      run.rows.back()[0]);
  // the run's global error at rtol 1e-12 over 6 s (~2 turns), Simpson's error dt⁴ ~ 1e-12 per row
  // in θ; λ and the forces at the run's state (its θ̇ off by the same global error)
  EXPECT_LT(centre_error, 1e-10);
  EXPECT_LT(relative_error, 1e-9);
  EXPECT_LT(lambda_error, 1e-9 * largest);
  EXPECT_LT(force_error, 1e-9 * largest);
  EXPECT_GT(largest - smallest, 0.5);  // L̈ and h²/L³ do change λ
}

}  // namespace
}  // namespace unidyn
