// Torsion springs and dampers in joints (model/angle_joint.hpp): a joint's angle q, with
// ω_B − ω_P = q̇ w and ‖w‖ = 1, gets the moments τ w on B and −τ w on P, whose generalised force
// is τ on q alone. Oracles: the damped oscillator's closed form for a rod hinged to the ground, and
// for two bodies hinged in space (§11.3) Newton–Euler against Lagrange, the momentum G and the
// angular momentum H_O (the joint's moments are equal and opposite), and the energy the damper
// takes.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/equations/equivalence.hpp"
#include "unidyn/equations/newton.hpp"
#include "unidyn/model/angle_joint.hpp"

namespace unidyn {
namespace {

// A rod (mass m, length L, along e1) hinged at one end to the ground about E3, with a torsion
// spring K and damper c in the hinge: (m L²/3) q̈ = −K q − c q̇.
const char* kHingedRod = R"(unidyn: 1
parameters: {m: 3, L: 2, K: 9, c: 1.2}
coordinates: [q]
bodies:
  R: {mass: m, inertia: [0, m*L^2/12, m*L^2/12], rotation: {axis: [0, 0, 1], angle: q}, center: L/2*R.e1}
forces:
  - torsion_spring: {angle: q, stiffness: K}
  - torsion_damper: {angle: q, coefficient: c}
initial: {q: 0.4}
simulate: {t_end: 6, output_step: 0.01, rtol: 1e-12}
)";

TEST(TorsionJoints, HingedRodIsADampedOscillator) {
  const test::ModelRun run = test::run_system(parse_model(kHingedRod, "rod.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  // I_O = m L²/3 = 4, ω0 = √(K/I_O) = 1.5, ζ = c/(2 √(K I_O)) = 0.1
  const double w0 = 1.5, zeta = 0.1, wd = w0 * std::sqrt(1 - zeta * zeta), q0 = 0.4;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const double q =
        std::exp(-zeta * w0 * t) * q0 * (std::cos(wd * t) + zeta * w0 / wd * std::sin(wd * t));
    EXPECT_NEAR(run.at(i, "q"), q, 1e-9) << t;
  }
  // the hinge to the ground: the rod alone carries the moment, along E3
  const auto joint = joint_of_angle(run.system, 0);
  ASSERT_TRUE(joint.has_value());
  EXPECT_EQ(joint->body, 0u);
  EXPECT_FALSE(joint->parent.has_value());
  EXPECT_TRUE(joint->axis[0].is_zero() && joint->axis[1].is_zero() && joint->axis[2] == 1);
}

// §11.3's two bodies (models/hinged-bodies.yaml): B turns by theta about A's e3, in space, with a
// torsion spring and a damper in the hinge. T and U are given as outputs for the energy balance.
std::string hinged_bodies(const std::string& damping) {
  return R"(unidyn: 1
parameters: {mA: 1.0, mB: 0.8, L1: 0.3, L2: 0.25, A1: 0.01, A2: 0.05, A3: 0.055, B1: 0.008, B2: 0.03, B3: 0.035, K: 0.4, c: )" +
         damping + R"(}
coordinates: [x, y, z, psi, th, phi, theta]
bodies:
  A:
    mass: mA
    inertia: [A1, A2, A3]
    rotation: {euler: 3-2-1, angles: [psi, th, phi]}
    center: [x, y, z]
  B:
    mass: mB
    inertia: [B1, B2, B3]
    rotation: [{euler: 3-2-1, angles: [psi, th, phi]}, {axis: [0, 0, 1], angle: theta}]
    center: A.center + L1*A.e1 + L2*B.e1
forces:
  - torsion_spring: {angle: theta, stiffness: K, rest_angle: 0.2}
  - torsion_damper: {angle: theta, coefficient: c}
initial: {theta: 0.5, der(y): 0.1, der(phi): 0.2, der(th): 0.1, der(psi): 1, der(theta): 2}
simulate: {t_end: 4, output_step: 0.01, rtol: 1e-12}
outputs:
  E: "A.mass*dot(A.velocity, A.velocity)/2 + dot(A.omega, A.H)/2 + B.mass*dot(B.velocity, B.velocity)/2 + dot(B.omega, B.H)/2 + K*(theta - 0.2)^2/2"
conserved:
  G1: dot(A.mass*A.velocity + B.mass*B.velocity, E1)
  G2: dot(A.mass*A.velocity + B.mass*B.velocity, E2)
  G3: dot(A.mass*A.velocity + B.mass*B.velocity, E3)
  H1: dot(A.angular_momentum + B.angular_momentum, E1)
  H2: dot(A.angular_momentum + B.angular_momentum, E2)
  H3: dot(A.angular_momentum + B.angular_momentum, E3)
)";
}

TEST(TorsionJoints, HingeInSpaceKeepsMomentaAndLosesTheDampersWork) {
  const System system = parse_model(hinged_bodies("0.05"), "hinged.yaml");
  // the joint: B turning relative to A about A's e3
  const auto joint = joint_of_angle(system, 6);
  ASSERT_TRUE(joint.has_value());
  EXPECT_EQ(joint->body, 1u);
  ASSERT_TRUE(joint->parent.has_value());
  EXPECT_EQ(*joint->parent, 0u);
  // Euler's laws with the two moments give Lagrange's equations, identically
  const EquivalenceReport report =
      check_equivalence(system, lagrange_equations(system), newton_equations(system));
  EXPECT_TRUE(report.symbolic_zero);

  const test::ModelRun run = test::run_system(system);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (const auto& kept : run.summary.conserved_drift) {
    EXPECT_LT(kept.max_change, 1e-10) << kept.name;
  }
  // E(0) − E(t) = ∫ c θ̇² dt (Simpson's rule over the rows)
  const double c = 0.05;
  double dissipated = 0;
  for (std::size_t i = 0; i + 2 < run.rows.size(); i += 2) {
    const auto power = [&](std::size_t k) { return c * std::pow(run.at(k, "der(theta)"), 2); };
    dissipated += 0.01 / 3 * (power(i) + 4 * power(i + 1) + power(i + 2));
  }
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const double lost = run.at(0, "E") - run.rows.back()[run.index("E")];
  EXPECT_GT(lost, 0.01);
  EXPECT_NEAR(lost, dissipated, 1e-7 * lost);
}

// Without the damper the energy column is kept to the integrator's accuracy.
TEST(TorsionJoints, HingeSpringAloneKeepsTheEnergy) {
  std::string text = hinged_bodies("0");
  text.erase(text.find("  - torsion_damper"),
             text.find("initial:") - text.find("  - torsion_damper"));
  const test::ModelRun run = test::run_system(parse_model(text, "hinged.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_TRUE(run.summary.has_energy);
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "energy") - run.at(i, "E"), run.at(0, "energy") - run.at(0, "E"), 1e-9);
  }
}

// A coordinate that is neither a joint's angle nor a body's Euler angle (x, a position) is refused
// with the reason; a body's own Euler angle is accepted.
TEST(TorsionJoints, NotAJointAngleIsRefused) {
  std::string text = hinged_bodies("0");
  const std::string spring = "{angle: theta, stiffness: K, rest_angle: 0.2}";
  text.replace(text.find(spring), spring.size(), "{angle: x, stiffness: K}");
  try {
    parse_model(text, "hinged.yaml");
    ADD_FAILURE() << "a spring on x was accepted";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("the angle of a joint"), std::string::npos) << e.what();
  }
  std::string euler = hinged_bodies("0");
  euler.replace(euler.find(spring), spring.size(), "{angle: psi, stiffness: K}");
  const System system = parse_model(euler, "hinged.yaml");
  EXPECT_EQ(system.forces[0].moments.size(), 1u);  // along A's dual Euler basis vector g^1
}

}  // namespace
}  // namespace unidyn
