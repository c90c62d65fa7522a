// Validation of models/two-body.yaml against Exercise 4.6 (the two-body problem): the centre of
// mass moves uniformly, E and H_O are conserved, and the relative vector r2 − r1 moves on a Kepler
// orbit (§2.8) with GM replaced by G(m1 + m2) and the reduced mass m1 m2/(m1 + m2).
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

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

}  // namespace
}  // namespace unidyn
