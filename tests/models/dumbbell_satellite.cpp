// Validation of models/dumbbell-satellite.yaml against §5.3 (the dumbbell satellite, (5.7)): the
// energy E = T + U and the angular momentum H_O = r1 × m1v1 + r2 × m2v2 are conserved, and H_O
// equals the notes' closed form r̄ × m v̄ + (m1m2/(m1+m2)) R² (φ̇ e_θ − θ̇ sinφ e_φ), m = m1 + m2.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::record;

// The model's defaults.
constexpr double G = 1.0, M = 1.0, m1 = 0.001, m2 = 0.002, K = 0.5, L0 = 0.01;
constexpr double m = m1 + m2, reduced_mass = m1 * m2 / m;

// The state of a row in the coordinates (5.7).
struct Dumbbell {
  Vec3 center, center_velocity;  // r̄, v̄
  double R, phi, theta, dR, dphi, dtheta;
  // e_R = sinφ (cosθ E1 + sinθ E2) + cosφ E3, e_φ = ∂e_R/∂φ, e_θ = −sinθ E1 + cosθ E2
  Vec3 e_R() const {
    return {std::sin(phi) * std::cos(theta), std::sin(phi) * std::sin(theta), std::cos(phi)};
  }
  Vec3 e_phi() const {
    return {std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta), -std::sin(phi)};
  }
  Vec3 e_theta() const { return {-std::sin(theta), std::cos(theta), 0.0}; }
};

Dumbbell dumbbell(const test::ModelRun& run, std::size_t i) {
  return {Vec3(run.at(i, "x"), run.at(i, "y"), run.at(i, "z")),
          Vec3(run.at(i, "der(x)"), run.at(i, "der(y)"), run.at(i, "der(z)")),
          run.at(i, "R"),
          run.at(i, "phi"),
          run.at(i, "theta"),
          run.at(i, "der(R)"),
          run.at(i, "der(phi)"),
          run.at(i, "der(theta)")};
}

// §5.3 H_O = r̄ × m v̄ + (m1m2/(m1+m2)) R² (φ̇ e_θ − θ̇ sinφ e_φ).
Vec3 closed_form_H(const Dumbbell& d) {
  return d.center.cross(m * d.center_velocity) +
         reduced_mass * d.R * d.R * (d.dphi * d.e_theta() - d.dtheta * std::sin(d.phi) * d.e_phi());
}

// §5.3 T = (m/2) v̄·v̄ + (m1m2/(2m)) (Ṙ² + R²φ̇² + R² sin²φ θ̇²),
// U = −GMm1/‖r̄ − (m2/m) R e_R‖ − GMm2/‖r̄ + (m1/m) R e_R‖ + K/2 (R − L0)².
// `scale` is T + |U|; `internal` the energy of the relative motion, (m1m2/(2m)) ‖Ṙ‖² + K/2 (R −
// L0)².
double energy(const Dumbbell& d, double* scale, double* internal) {
  const double s = std::sin(d.phi);
  const double T_relative =
      0.5 * reduced_mass *
      (d.dR * d.dR + d.R * d.R * d.dphi * d.dphi + d.R * d.R * s * s * d.dtheta * d.dtheta);
  const double T = 0.5 * m * d.center_velocity.squaredNorm() + T_relative;
  const Vec3 r1 = d.center - m2 / m * d.R * d.e_R(), r2 = d.center + m1 / m * d.R * d.e_R();
  const double U_spring = 0.5 * K * (d.R - L0) * (d.R - L0);
  const double U = -G * M * m1 / r1.norm() - G * M * m2 / r2.norm() + U_spring;
  *scale = T + std::abs(U);
  *internal = T_relative + U_spring;
  return T + U;
}

const test::ModelRun& default_run() {
  // ~9 periods of the spring (2π√(m1m2/(mK)) ≈ 0.23 s) and a quarter of an orbit (≈ 7.4 s): the
  // spring's fast oscillation sets the step, so a longer run only costs time
  static const test::ModelRun run =
      test::run_model("dumbbell-satellite", {}, [](SimulationOptions& o) { o.t_end = 2.0; });
  return run;
}

// The tests below assume the model file's parameter values.
TEST(DumbbellSatellite, ModelFileParameters) {
  const System system = load_model(test::model_path("dumbbell-satellite"));
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  EXPECT_EQ(value("G"), G);
  EXPECT_EQ(value("M"), M);
  EXPECT_EQ(value("m1"), m1);
  EXPECT_EQ(value("m2"), m2);
  EXPECT_EQ(value("K"), K);
  EXPECT_EQ(value("L0"), L0);
}

// §5.3 E = T + U and H_O are conserved (gravity is central about O, the spring internal); the
// energy column is the notes' T + U.
TEST(DumbbellSatellite, EnergyAndAngularMomentumConserved) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double scale = 0.0, internal = INFINITY, row_internal = 0.0;
  const double E0 = energy(dumbbell(run, 0), &scale, &row_internal);
  const Vec3 H0(run.at(0, "Hx"), run.at(0, "Hy"), run.at(0, "Hz"));
  double energy_drift = 0.0, energy_column = 0.0;
  Vec3 H_drift = Vec3::Zero();
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    double row_scale = 0.0;
    const double E = energy(dumbbell(run, i), &row_scale, &row_internal);
    scale = std::max(scale, row_scale);
    internal = std::min(internal, row_internal);
    energy_drift = std::max(energy_drift, std::abs(E - E0));
    energy_column = std::max(energy_column, std::abs(run.at(i, "energy") - E));
    const Vec3 H(run.at(i, "Hx"), run.at(i, "Hy"), run.at(i, "Hz"));
    H_drift = H_drift.cwiseMax((H - H0).cwiseAbs());
  }
  // rtol 1e-12 per step over the run's ~3·10³ steps; the components of H relative to ‖H‖ (Hx is
  // only the spin part)
  EXPECT_LT(energy_drift / scale, 1e-9);
  EXPECT_LT(energy_column / scale, 1e-13);
  EXPECT_LT(H_drift.maxCoeff() / H0.norm(), 1e-9);
  // The orbit dominates both E and H: the dumbbell's own vibration and spin carry only ~1e-5 of
  // them. The drifts are small on that scale too (a spring or spin force inconsistent with the
  // potential would change E by a fraction of the internal energy).
  const Dumbbell start = dumbbell(run, 0);
  const double spin = (closed_form_H(start) - start.center.cross(m * start.center_velocity)).norm();
  EXPECT_LT(energy_drift / internal, 1e-8);
  EXPECT_LT(H_drift.maxCoeff() / spin, 1e-8);
  record("energy_relative_drift", energy_drift / scale);
  record("energy_drift_relative_to_internal", energy_drift / internal);
  record("H_drift_relative_to_spin", H_drift.maxCoeff() / spin);
  record("Hx_drift", H_drift.x() / H0.norm());
  record("Hy_drift", H_drift.y() / H0.norm());
  record("Hz_drift", H_drift.z() / H0.norm());
  record("accepted_steps", double(run.summary.stats.accepted_steps));
}

// §5.3 the closed form of H_O, computed here from (r̄, R, φ, θ) and their rates, is the Hx, Hy, Hz
// columns (r1 × m1v1 + r2 × m2v2 of the model); its spin part (m1m2/m) R² (φ̇ e_θ − θ̇ sinφ e_φ)
// matters.
TEST(DumbbellSatellite, AngularMomentumClosedForm) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double error = 0.0, spin_error = 0.0, spin_size = INFINITY;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Dumbbell d = dumbbell(run, i);
    const Vec3 H(run.at(i, "Hx"), run.at(i, "Hy"), run.at(i, "Hz"));
    const Vec3 expected = closed_form_H(d);
    const Vec3 orbital = d.center.cross(m * d.center_velocity);
    error = std::max(error, (H - expected).norm() / H.norm());
    // the spin part alone, relative to itself
    spin_error = std::max(
        spin_error, (H - orbital - (expected - orbital)).norm() / (expected - orbital).norm());
    spin_size = std::min(spin_size, (expected - orbital).norm());
  }
  // round-off of the two expressions
  EXPECT_LT(error, 1e-13);
  // the spin part is ~1e-5 ‖H‖, so H − r̄ × m v̄ loses about five digits to cancellation
  EXPECT_LT(spin_error, 1e-8);
  EXPECT_GT(spin_size, 0.0);
  record("closed_form_relative_error", error);
  record("spin_part_relative_error", spin_error);
}

}  // namespace
}  // namespace unidyn
