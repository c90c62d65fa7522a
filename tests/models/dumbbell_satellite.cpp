// Validation of models/dumbbell-satellite.yaml against §5.3 (the dumbbell satellite, (5.7)): the
// energy E = T + U and the angular momentum H_O = r1 × m1v1 + r2 × m2v2 are conserved, and H_O
// equals the notes' closed form r̄ × m v̄ + (m1m2/(m1+m2)) R² (φ̇ e_θ − θ̇ sinφ e_φ), m = m1 + m2.
#include <gtest/gtest.h>

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

// The model file with the particles' accelerations as outputs (columns a1.x … a2.z).
const test::ModelRun& run_with_accelerations() {
  static const test::ModelRun run = [] {
    std::ifstream file(test::model_path("dumbbell-satellite"));
    std::stringstream text;
    text << file.rdbuf();
    text << "outputs:\n  a1: P1.acceleration\n  a2: P2.acceleration\n";
    return test::run_system(parse_model(text.str(), "dumbbell-satellite.yaml"), {},
                            [](SimulationOptions& o) { o.t_end = 2.0; });
  }();
  return run;
}

// §4.5 (Fig. 4.3), the spring pair force by force: with x = r2 − r1 computed here from the row's
// (r̄, R, φ, θ) by (5.7), the spring's forces (from U_s = K/2 (|x| − L0)², F_con,i = −∂U_s/∂r_i)
//   F_12 = K (|x| − L0) x/|x| on P1,   F_21 = −F_12 on P2
// are equal and opposite along r2 − r1; the run's accelerations (a1, a2 from q̈ at each row) less
// the planet's pulls −GM m_i r_i/|r_i|³ must be them: m1 a1 + GM m1 r1/|r1|³ = F_12 and
// m2 a2 + GM m2 r2/|r2|³ = −F_12; the sum of the two is the third law.
TEST(DumbbellSatellite, SpringForcesAreEqualOppositeAlongTheSpring) {
  const auto& run = run_with_accelerations();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double error1 = 0, error2 = 0, third_law = 0, smallest = INFINITY, largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Dumbbell d = dumbbell(run, i);
    const Vec3 r1 = d.center - m2 / m * d.R * d.e_R(), r2 = d.center + m1 / m * d.R * d.e_R();
    const Vec3 x = r2 - r1;
    const Vec3 F12 = K * (x.norm() - L0) * x.normalized();
    const Vec3 a1(run.at(i, "a1.x"), run.at(i, "a1.y"), run.at(i, "a1.z"));
    const Vec3 a2(run.at(i, "a2.x"), run.at(i, "a2.y"), run.at(i, "a2.z"));
    const Vec3 spring1 = m1 * a1 + G * M * m1 * r1 / std::pow(r1.norm(), 3);
    const Vec3 spring2 = m2 * a2 + G * M * m2 * r2 / std::pow(r2.norm(), 3);
    error1 = std::max(error1, (spring1 - F12).norm());
    error2 = std::max(error2, (spring2 + F12).norm());
    third_law = std::max(third_law, (spring1 + spring2).norm());
    smallest = std::min(smallest, F12.norm());
    largest = std::max(largest, F12.norm());
  }
  std::printf(
      "Dumbbell spring pair: |F_12| = K(|x| − L0) from %.3g to %.3g N; m1 a1 − gravity − F_12 "
      "%.3g, "
      "m2 a2 − gravity + F_12 %.3g, sum %.3g (relative to the largest |F_12|)\n",
      smallest, largest, error1 / largest, error2 / largest, third_law / largest);
  // both sides at the same state: round-off of forces of ~1e-3 N (the planet's pull on each is of
  // the size of the largest F_12)
  EXPECT_LT(error1 / largest, 1e-12);
  EXPECT_LT(error2 / largest, 1e-12);
  EXPECT_LT(third_law / largest, 1e-12);
  EXPECT_GT(largest, 100 * smallest);  // the spring's force varies: it vibrates
  record("spring_force_error_P1", error1 / largest);
  record("spring_force_error_P2", error2 / largest);
}

}  // namespace
}  // namespace unidyn
