// Two free particles, the second located relative to the first (book Ex. 5.3(d)–(f)):
// models/two-particles-relative.yaml. The six Lagrange equations in {r1, θ1, z1, R2, φ2, θ2} must
// give each particle the free fall r_i(t) = r_i(0) + v_i(0) t − ½ g t² E3, and T's cross terms
// must be the corrected group m2 cos φ2 R2 φ̇2 (ṙ1 cos θ21 + r1 θ̇1 sin θ21), not the printed one.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/kinematics/kinetic_energy.hpp"

namespace unidyn {
namespace {

TEST(TwoParticlesRelative, EachParticleFallsFreely) {
  const test::ModelRun run = test::run_model("two-particles-relative");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double g = 9.81;
  const double r1 = 1.0, t1 = 0.3, R2 = 0.8, p2 = 1.1, t2 = -0.4;
  const double dr1 = 0.5, dt1 = 0.7, dz1 = 1.5, dR2 = -0.2, dp2 = 0.3, dt2 = 0.6;
  // v_A(0) by hand from the cylindrical coordinates, v_B(0) = v_A + d/dt (R2 u(φ2, θ2))
  const std::array<double, 3> vA{dr1 * std::cos(t1) - r1 * dt1 * std::sin(t1),
                                 dr1 * std::sin(t1) + r1 * dt1 * std::cos(t1), dz1};
  const std::array<double, 3> u{std::sin(p2) * std::cos(t2), std::sin(p2) * std::sin(t2),
                                std::cos(p2)};
  const std::array<double, 3> u_phi{std::cos(p2) * std::cos(t2), std::cos(p2) * std::sin(t2),
                                    -std::sin(p2)};
  const std::array<double, 3> u_theta{-std::sin(p2) * std::sin(t2), std::sin(p2) * std::cos(t2), 0};
  std::array<double, 3> vB{};
  for (int k = 0; k < 3; ++k) vB[k] = vA[k] + dR2 * u[k] + R2 * (dp2 * u_phi[k] + dt2 * u_theta[k]);
  const char* A[3] = {"xA", "yA", "zA"};
  const char* B[3] = {"xB", "yB", "zB"};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    for (int k = 0; k < 3; ++k) {
      const double fall = k == 2 ? -0.5 * g * t * t : 0.0;
      EXPECT_NEAR(run.at(i, A[k]), run.at(0, A[k]) + vA[k] * t + fall, 1e-9) << t;
      EXPECT_NEAR(run.at(i, B[k]), run.at(0, B[k]) + vB[k] * t + fall, 1e-9) << t;
    }
  }
}

// (d) ⚠: the coefficients of φ̇2 ṙ1 and φ̇2 θ̇1 in T are m2 R2 cos φ2 cos θ21 and
// m2 R2 r1 cos φ2 sin θ21 (θ21 = θ2 − θ1); the book prints cos θ2 and sin θ2.
TEST(TwoParticlesRelative, KineticEnergysCrossTermsAreTheCorrectedOnes) {
  const System system = load_model(test::model_path("two-particles-relative"));
  const KineticEnergyForm form = kinetic_energy_form(system);
  GiNaC::exmap at;
  for (const auto& p : system.parameters) at[p.symbol] = p.value;
  const double values[6] = {1.3, 0.4, 0.2, 0.9, 0.8, 1.7};
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) at[q[i].value] = values[i];
  const auto entry = [&](std::size_t i, std::size_t k) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(form.mass_matrix(i, k).subs(at))).to_double();
  };
  const double m2 = 0.5, r1 = 1.3, t1 = 0.4, R2 = 0.9, p2 = 0.8, t2 = 1.7;
  // T = ½ q̇ᵀ M q̇: the cross term c q̇_i q̇_k is M_ik
  EXPECT_NEAR(entry(0, 4), m2 * R2 * std::cos(p2) * std::cos(t2 - t1), 1e-14);
  EXPECT_NEAR(entry(1, 4), m2 * R2 * r1 * std::cos(p2) * std::sin(t2 - t1), 1e-14);
  EXPECT_GT(std::abs(entry(0, 4) - m2 * R2 * std::cos(p2) * std::cos(t2)), 1e-2);
  EXPECT_GT(std::abs(entry(1, 4) - m2 * R2 * r1 * std::cos(p2) * std::sin(t2)), 1e-2);
  // and φ̇2 ż1 has −m2 R2 sin φ2
  EXPECT_NEAR(entry(2, 4), -m2 * R2 * std::sin(p2), 1e-14);
}

}  // namespace
}  // namespace unidyn
