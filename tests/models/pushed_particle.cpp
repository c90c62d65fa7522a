// Problem 2.4: a particle on a table pushed by a moving plane; the constraints' power (Ex. 4.2).
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The plane x1 = f(t) = t²/2 + 0.1 sin 2t pushes with λ2 = m f̈ = m (1 − 0.4 sin 2t) along E1, the
// table holds the weight, λ1 = m g; x2 moves uniformly; F_c = λ1 E3 + λ2 E1.
TEST(PushedParticle, TheMovingPlanesForceIsMassTimesItsAcceleration) {
  const double m = 2.0, g = 9.81;
  const test::ModelRun run = test::run_model("pushed-particle");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), f2 = 1 - 0.4 * std::sin(2 * t);
    EXPECT_NEAR(run.at(i, "lambda(table)"), m * g, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "lambda(plane)"), m * f2, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "Fc.x"), m * f2, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "Fc.z"), m * g, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "x1"), t * t / 2 + 0.1 * std::sin(2 * t), 1e-10) << t;
    EXPECT_NEAR(run.at(i, "x2"), 0.7 * t, 1e-10) << t;
  }
}

// Exercise 4.2 (§4.4): the constraint forces' power is P = −μ e for a constraint f · v + e = 0
// with F_c = μ f, so it vanishes only when e = 0. Here the table x3 = 0 (f = E3, e = 0) does no
// work, and the plane x1 = f(t) (f = E1, e = −ḟ) works at P = −μ e = m f̈ ḟ with μ = m f̈ by
// Newton's law along E1, f = t²/2 + 0.1 sin 2t:
//   P_plane = m (1 − 0.4 sin 2t)(t + 0.2 cos 2t).
// The run's F_c · v (the particle's m a − F, and each constraint's force, dotted with its velocity:
// outputs of the model given with them) against that closed form and 0 (f̈ = 1 − 0.4 sin 2t and
// ḟ = t + 0.2 cos 2t stay positive, so the plane feeds power throughout), and the kinetic energy
// against m (ḟ² + 0.7²)/2 (x2 moves uniformly at 0.7).
TEST(PushedParticle, ConstraintPowerOfExercise42IsMinusMuE) {
  std::ifstream file(test::model_path("pushed-particle"));
  std::stringstream text;
  text << file.rdbuf()
       << "  power: dot(P.constraint_force, P.velocity)\n"
          "  plane_power: dot(plane.force.P, P.velocity)\n"
          "  table_power: dot(table.force.P, P.velocity)\n"
          "  T: m/2*dot(P.velocity, P.velocity)\n";
  const test::ModelRun run =
      test::run_system(parse_model(text.str(), "pushed-particle-power.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 2.0;
  ASSERT_EQ(run.parameter("m"), m);
  double power_error = 0, table_power = 0, energy_error = 0, largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), fdot = t + 0.2 * std::cos(2 * t),
                 fddot = 1 - 0.4 * std::sin(2 * t), P = m * fddot * fdot;
    power_error = std::max(
        {power_error, std::abs(run.at(i, "power") - P), std::abs(run.at(i, "plane_power") - P)});
    table_power = std::max(table_power, std::abs(run.at(i, "table_power")));
    energy_error =
        std::max(energy_error, std::abs(run.at(i, "T") - m / 2 * (fdot * fdot + 0.7 * 0.7)));
    largest = std::max(largest, P);
  }
  EXPECT_GT(largest, 10.0);  // m f̈ ḟ reaches ~12 W near t = 5
  // a run at rtol 1e-12 over 5 s: the rates to ~1e-10 of ḟ ~ 5 m/s
  EXPECT_LT(power_error, 1e-9);
  EXPECT_LT(table_power, 1e-9);
  EXPECT_LT(energy_error, 1e-9);
  std::printf("Ex. 4.2: plane's power %.3g W, table's %.3g W, T %.3g J off m f'' f', 0, m f'^2/2\n",
              power_error, table_power, energy_error);
}

}  // namespace
}  // namespace unidyn
