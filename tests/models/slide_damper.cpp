// Dampers in prismatic joints (slide_damper, model/forces.hpp): a body sliding by d along its
// joint's unit axis u gets −c ḋ u at its frame's origin, its parent c ḋ u at the joint's origin on
// the same line, so the generalised force is −c ḋ on d alone. Oracles: the closed form of a damped
// cart, m ẍ = −c ẋ: x(t) = x0 + v0 (m/c)(1 − e^{−c t/m}); and for a carriage on an arm spinning
// freely about E3, the rail off the axis, Newton–Euler against Lagrange, the angular momentum about
// E3 (the two forces are equal and opposite on one line; without the parent's, their moment about
// E3 would change it) and the energy the damper takes, ∫ c ḋ² dt.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/equations/equivalence.hpp"
#include "unidyn/equations/newton.hpp"

namespace unidyn {
namespace {

// A cart on a rail turned 0.3 rad about E3 from E1, pushed off at v0 = 2, damped by c: gravity is
// across the rail.
const char* kDampedCart = R"(unidyn: 1
parameters: {m: 2.5, c: 1.5, g: 9.81}
coordinates: [x]
bodies:
  cart:
    joint: {rotation: {axis: [0, 0, 1], angle: 0.3}, prismatic: x, axis: [1, 0, 0]}
    mass: m
    inertia: [0.1, 0.2, 0.3]
forces:
  - gravity: -g*E3
  - slide_damper: {displacement: x, coefficient: c}
initial: {x: 0.5, der(x): 2}
simulate: {t_end: 4, output_step: 0.01, rtol: 1e-12}
)";

TEST(SlideDamper, DampedCartFollowsTheClosedForm) {
  const test::ModelRun run = test::run_system(parse_model(kDampedCart, "cart.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 2.5, c = 1.5, x0 = 0.5, v0 = 2;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x"), x0 + v0 * m / c * (1 - std::exp(-c * t / m)), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "der(x)"), v0 * std::exp(-c * t / m), 1e-9) << t;
  }
}

// An arm turning freely about E3 (no gravity), a rail on it off the axis (0.2 along the arm's e2),
// a carriage on the rail held by a spring and damped.
std::string spinning_rail(const std::string& damping) {
  return R"(unidyn: 1
parameters: {k: 3, c: )" +
         damping + R"(}
coordinates: [phi, s]
bodies:
  arm:
    joint: {revolute: phi, axis: [0, 0, 1]}
    mass: 2
    inertia: [0.02, 0.3, 0.3]
    center: arm.frame_point([0.3, 0, 0])
  carriage:
    joint: {parent: arm, origin: [0.1, 0.2, 0], rotation: {axis: [0, 0, 1], angle: 0.4}, prismatic: s, axis: [1, 0, 0]}
    mass: 0.7
    inertia: [0.001, 0.002, 0.002]
    center: carriage.frame_point([0.05, 0, 0])
forces:
  - potential: k*s^2/2
  - slide_damper: {displacement: s, coefficient: c}
initial: {s: 0.3, der(phi): 1.5, der(s): -0.4}
simulate: {t_end: 5, output_step: 0.01, rtol: 1e-12}
outputs:
  E: "arm.mass*dot(arm.velocity, arm.velocity)/2 + dot(arm.omega, arm.H)/2 + carriage.mass*dot(carriage.velocity, carriage.velocity)/2 + dot(carriage.omega, carriage.H)/2 + k*s^2/2"
conserved:
  H3: dot(arm.angular_momentum + carriage.angular_momentum, E3)
)";
}

TEST(SlideDamper, SpinningRailKeepsTheAngularMomentumAndLosesTheDampersWork) {
  const System system = parse_model(spinning_rail("0.6"), "rail.yaml");
  // the forces on the carriage and the arm give Lagrange's equations, identically
  const EquivalenceReport report =
      check_equivalence(system, lagrange_equations(system), newton_equations(system));
  EXPECT_TRUE(report.symbolic_zero) << report.numeric_relative_residual;
  const test::ModelRun run = test::run_system(system);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-10);
  // E(0) − E(t) = ∫ c ṡ² dt (Simpson's rule over the rows)
  const double c = 0.6;
  double dissipated = 0;
  ASSERT_EQ(run.rows.size() % 2, 1u);
  for (std::size_t i = 0; i + 2 < run.rows.size(); i += 2) {
    const auto power = [&](std::size_t k) { return c * std::pow(run.at(k, "der(s)"), 2); };
    dissipated += 0.01 / 3 * (power(i) + 4 * power(i + 1) + power(i + 2));
  }
  const double lost = run.at(0, "E") - run.rows.back()[run.index("E")];
  EXPECT_GT(lost, 0.01);
  EXPECT_NEAR(lost, dissipated, 1e-7 * lost);
}

// A coordinate that is not a prismatic joint's is refused with the reason.
TEST(SlideDamper, NotAPrismaticJointIsRefused) {
  std::string text = spinning_rail("0.6");
  text.replace(text.find("{displacement: s"), 16, "{displacement: phi");
  try {
    parse_model(text, "rail.yaml");
    ADD_FAILURE() << "not refused";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("a slide_damper needs the coordinate of a prismatic "
                                         "joint ('phi' is not one)"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace unidyn
