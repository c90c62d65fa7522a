// Friction laws beyond a constant coefficient: μ_d as an expression of the slip speed (the tippe
// top's μ_k + μ_v |v_P|, Ex. 9.13) and viscous friction −c v_t at a contact, on a puck sliding
// on a horizontal plane, where m v̇ = −μ_d(v) m g − c v has closed-form solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

constexpr double m = 0.5, g = 9.81, v0 = 3.0;

// The puck with the friction keys `friction` (inside {on: P, ...}).
test::ModelRun slide(const std::string& friction, double t_end) {
  const std::string text =
      "unidyn: 1\n"
      "parameters: {m: 0.5, g: 9.81, mu_k: 0.1, mu_v: 0.4, c: 0.6}\n"
      "coordinates: [x, y, z]\n"
      "particles:\n"
      "  P: {mass: m, position: [x, y, z]}\n"
      "forces:\n"
      "  - gravity: -g*E3\n"
      "constraints:\n"
      "  - {name: plane, position: z, friction: {on: P, " +
      friction +
      "}}\n"
      "initial: {der(x): 3}\n"
      "simulate: {t_end: " +
      std::to_string(t_end) +
      ", output_step: 0.01, rtol: 1e-11}\n"
      "outputs:\n"
      "  friction: dot(P.constraint_force, E1)\n";
  return test::run_system(parse_model(text, "puck.yaml"));
}

// μ_d = μ_k + μ_v v: v̇ = −g μ_k − g μ_v v, so v = (v0 + μ_k/μ_v) e^{−g μ_v t} − μ_k/μ_v until
// it stops at t* = ln(1 + μ_v v0/μ_k)/(g μ_v); μ_s defaults to μ_d at no slip, μ_k, which holds it.
TEST(FrictionLaws, CoefficientGrowingWithTheSlipSpeed) {
  const double mu_k = 0.1, mu_v = 0.4;
  const test::ModelRun run = slide("dynamic: mu_k + mu_v*slip_speed", 1.5);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double stop = std::log(1 + mu_v * v0 / mu_k) / (g * mu_v);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what, "contact 'plane' sticks");
  EXPECT_NEAR(run.summary.phases[1].t, stop, 1e-9);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (t > stop - 1e-9) {
      EXPECT_NEAR(run.at(i, "der(x)"), 0, 1e-12) << t;
      continue;
    }
    const double v = (v0 + mu_k / mu_v) * std::exp(-g * mu_v * t) - mu_k / mu_v;
    EXPECT_NEAR(run.at(i, "der(x)"), v, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "friction"), -(mu_k + mu_v * v) * m * g, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "der(y)"), 0, 1e-14) << t;
  }
}

// Viscous friction c at the contact with Coulomb μ_k: m v̇ = −μ_k m g − c v, so
// v = (v0 + V) e^{−c t/m} − V with V = μ_k m g/c, stopping at t* = (m/c) ln(1 + v0/V); with
// μ_k = 0 the puck slows as v0 e^{−c t/m} and never stops.
TEST(FrictionLaws, ViscousFrictionAtTheContact) {
  const double mu_k = 0.1, c = 0.6;
  const test::ModelRun run = slide("dynamic: mu_k, viscous: c", 1.5);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double V = mu_k * m * g / c, stop = m / c * std::log(1 + v0 / V);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_NEAR(run.summary.phases[1].t, stop, 1e-9);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (t < stop - 1e-9) {
      const double v = (v0 + V) * std::exp(-c * t / m) - V;
      EXPECT_NEAR(run.at(i, "der(x)"), v, 1e-9) << t;
      EXPECT_NEAR(run.at(i, "friction"), -(mu_k * m * g + c * v), 1e-8) << t;
    }
  }
  const test::ModelRun viscous = slide("dynamic: 0, viscous: c", 3);
  ASSERT_TRUE(viscous.summary.ok) << viscous.summary.message;
  EXPECT_EQ(viscous.summary.phases.size(), 1u) << "it never stops";
  for (std::size_t i = 0; i < viscous.rows.size(); ++i) {
    const double t = viscous.at(i, "t");
    EXPECT_NEAR(viscous.at(i, "der(x)"), v0 * std::exp(-c * t / m), 1e-9) << t;
  }
}

}  // namespace
}  // namespace unidyn
