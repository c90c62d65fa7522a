// A free particle under gravity in spherical coordinates (book §3.3, (3.3); covariant form (4.33)):
// models/free-particle-spherical.yaml against the projectile r(t) = r0 + v0 t − ½ g t² E3.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::ModelRun;
using test::run_model;

using Vec = std::array<double, 3>;

// r = R e_R with e_R = sin φ (cos θ E1 + sin θ E2) + cos φ E3 (φ the polar angle from E3).
Vec position(double R, double phi, double theta) {
  return {R * std::sin(phi) * std::cos(theta), R * std::sin(phi) * std::sin(theta),
          R * std::cos(phi)};
}

// v = Ṙ e_R + R φ̇ e_φ + R sin φ θ̇ e_θ (§3.3: a_1 = e_R, a_2 = R e_φ, a_3 = R sin φ e_θ).
Vec velocity(double R, double phi, double theta, double Rdot, double phidot, double thetadot) {
  const Vec eR{std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)};
  const Vec ephi{std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), -std::sin(phi)};
  const Vec etheta{-std::sin(theta), std::cos(theta), 0.0};
  Vec v{};
  for (int i = 0; i < 3; ++i) {
    v[i] = Rdot * eR[i] + R * phidot * ephi[i] + R * std::sin(phi) * thetadot * etheta[i];
  }
  return v;
}

// §3.3: Lagrange's equations (3.3) in {R, φ, θ} with F = −mg E3 are m a = −mg E3 written in
// curvilinear coordinates, so the motion is the projectile r0 + v0 t − ½ g t² E3.
TEST(FreeParticleSpherical, FollowsProjectileClosedForm) {
  const ModelRun run = run_model("free-particle-spherical");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size(), 121u);
  const double g = run.system.parameters.at(run.system.find_parameter("g").value()).value;

  const Vec r0 = position(run.at(0, "R"), run.at(0, "phi"), run.at(0, "theta"));
  const Vec v0 = velocity(run.at(0, "R"), run.at(0, "phi"), run.at(0, "theta"), run.at(0, "der(R)"),
                          run.at(0, "der(phi)"), run.at(0, "der(theta)"));
  // the model's own initial state, as its file gives it
  EXPECT_EQ(run.at(0, "R"), 3.0);
  EXPECT_EQ(run.at(0, "der(theta)"), 0.8);

  const char* names[] = {"x", "y", "z"};
  double output_error = 0.0, coordinate_error = 0.0, velocity_error = 0.0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double t = run.at(k, "t");
    const double R = run.at(k, "R"), phi = run.at(k, "phi"), theta = run.at(k, "theta");
    const Vec r = position(R, phi, theta);
    const Vec v = velocity(R, phi, theta, run.at(k, "der(R)"), run.at(k, "der(phi)"),
                           run.at(k, "der(theta)"));
    for (int i = 0; i < 3; ++i) {
      const double expected = r0[i] + v0[i] * t - (i == 2 ? 0.5 * g * t * t : 0.0);
      const double expected_rate = v0[i] - (i == 2 ? g * t : 0.0);
      output_error = std::max(output_error, std::abs(run.at(k, names[i]) - expected));
      coordinate_error = std::max(coordinate_error, std::abs(r[i] - expected));
      velocity_error = std::max(velocity_error, std::abs(v[i] - expected_rate));
    }
  }
  // rtol 1e-12 on |r| ~ 3 m over 1.2 s: ~1e-11; 1e-9 leaves room for the error's growth.
  EXPECT_LT(output_error, 1e-9);
  EXPECT_LT(coordinate_error, 1e-9);
  EXPECT_LT(velocity_error, 1e-9);
  std::printf("max error: outputs %.3g, position from q %.3g, velocity %.3g\n", output_error,
              coordinate_error, velocity_error);
}

// §2.5: the energy T + mgz of the free particle is conserved.
TEST(FreeParticleSpherical, EnergyConserved) {
  const ModelRun run = run_model("free-particle-spherical");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_TRUE(run.summary.has_energy);
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
}

}  // namespace
}  // namespace unidyn
