// The initial state: the values given stay as given, the others come from the constraints
// (Newton on Ψ = 0, then A q̇ + e = 0, least norm) — the Atwood machine's second mass, a rolling
// sphere's spin from its forward speed — and given values that violate a constraint, or leave
// nothing free to satisfy it, are refused with the constraint, its residual and its coordinates.
#include "unidyn/integrate/initial_state.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/rotation/euler_angles.hpp"

namespace unidyn {
namespace {

struct Completed {
  SimulationStart start;
  std::vector<std::string> computed;
};

// Reads `text`, starts it with `sets`, and completes the start.
Completed complete(const std::string& text,
                   const std::vector<std::pair<std::string, double>>& sets = {}) {
  const System system = parse_model(text, "initial.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  Completed c{initial_state(system, sets), {}};
  c.computed = complete_initial_state(system, compiled, c.start);
  return c;
}

std::string error_of(const std::string& text,
                     const std::vector<std::pair<std::string, double>>& sets = {}) {
  try {
    (void)complete(text, sets);
  } catch (const InitialStateError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// Two masses on a string over a pulley: y1 + y2 = −L.
std::string atwood(const std::string& initial) {
  return "unidyn: 1\nparameters: {m1: 1, m2: 2, g: 9.81, L: 3}\ncoordinates: [y1, y2]\n"
         "particles:\n  P1: {mass: m1, position: [0, y1, 0]}\n  P2: {mass: m2, position: [1, y2, "
         "0]}\nforces:\n  - gravity: -g*E2\nconstraints:\n  - {name: string, position: -y1 - y2 - "
         "L}\ninitial: " +
         initial + "\n";
}

TEST(InitialState, TheValuesGivenStayTheOthersAreComputed) {
  const Completed c = complete(atwood("{y1: -1, der(y1): 0.5}"), {{"y1", -0.9}});
  EXPECT_EQ(c.start.q[0], -0.9);  // as given with --set, not moved
  EXPECT_DOUBLE_EQ(c.start.q[1], -2.1);
  EXPECT_EQ(c.start.qdot[0], 0.5);
  EXPECT_DOUBLE_EQ(c.start.qdot[1], -0.5);
  ASSERT_EQ(c.computed.size(), 2u);
  EXPECT_EQ(c.computed[0], "y2 = -2.1");
  EXPECT_EQ(c.computed[1], "der(y2) = -0.5");
  // nothing to compute when everything given is consistent
  EXPECT_TRUE(complete(atwood("{y1: -1, y2: -2}")).computed.empty());
}

TEST(InitialState, GivenValuesThatViolateAConstraintAreRefused) {
  const std::string message = error_of(atwood("{y1: -1, y2: -2}"), {{"y1", -0.9}});
  EXPECT_TRUE(contains(message, "constraint 'string'")) << message;
  EXPECT_TRUE(contains(message, "Psi = -0.1")) << message;
  EXPECT_TRUE(contains(message, "y1 (given), y2 (given)")) << message;
  const std::string rates = error_of(atwood("{y1: -1, der(y1): 1, der(y2): 1}"));
  EXPECT_TRUE(contains(rates, "A q' + e = -2")) << rates;
  EXPECT_TRUE(contains(rates, "der(y1) (given), der(y2) (given)")) << rates;
}

// x = 100 on a unit circle: no y can satisfy it (no "success" with |Ψ| = 10⁴ in the first row).
// x = 0.6 with y from 0: ∂Ψ/∂y = 2y is 0 there, so y must be given.
TEST(InitialState, NoFreeValueCanSatisfyIt) {
  const std::string circle =
      "unidyn: 1\ncoordinates: [x, y]\nparticles:\n  P: {mass: 1, position: [x, y, 0]}\n"
      "constraints:\n  - {name: rod, position: x^2 + y^2 - 1}\ninitial: ";
  EXPECT_TRUE(contains(error_of(circle + "{x: 100, y: -1}"), "'rod'"));
  const std::string far = error_of(circle + "{x: 100}");
  EXPECT_TRUE(contains(far, "constraint 'rod'")) << far;
  const std::string flat = error_of(circle + "{x: 0.6}");
  EXPECT_TRUE(contains(flat, "give them values")) << flat;
  // y alone: x = ±0.6, but from x = 0 the gradient 2x is 0 as well: x must be given
  EXPECT_TRUE(contains(error_of(circle + "{y: -0.8}"), "give them values"));
}

// Two ropes over pulleys: y1 + y2 = −L1 and y2 + y3 = −L2. Given y1 and y3 against them (y2
// cannot be both −L1 − y1 = −2 and −L2 − y3 = −1.5), the values given contradict the constraints:
// said so, with both ropes and their residuals at the best fit (y2 = −1.75: ±0.25), not as a
// Newton iteration that does not converge.
TEST(InitialState, GivenValuesThatContradictTheConstraintsAreNamedSo) {
  const std::string ropes =
      "unidyn: 1\nparameters: {L1: 3, L2: 2}\ncoordinates: [y1, y2, y3]\nparticles:\n"
      "  P1: {mass: 1, position: [0, y1, 0]}\n  P2: {mass: 1, position: [1, y2, 0]}\n"
      "  P3: {mass: 1, position: [2, y3, 0]}\nconstraints:\n"
      "  - {name: rope1, position: y1 + y2 + L1}\n  - {name: rope2, position: y2 + y3 + L2}\n"
      "initial: {y1: -1, y3: -0.5}\n";
  const std::string message = error_of(ropes);
  EXPECT_TRUE(contains(message, "the values given contradict the constraints")) << message;
  EXPECT_TRUE(contains(message, "'rope1' (Psi = 0.25), 'rope2' (Psi = -0.25)")) << message;
  // consistent values are completed as before
  EXPECT_DOUBLE_EQ(complete(ropes, {{"y3", 0.0}}).start.q[1], -2.0);
}

// An angle computed from a start where the constraint's gradient is tiny: Newton's first step is
// 5e5 rad, and it converges some 80 000 turns away. The configuration is right; the angle is taken
// back by whole turns to the solution nearest where it started (cos θ = 1/2: θ = ±π/3), since the
// equations repeat after 2π in it. A length is never moved so.
TEST(InitialState, AnglesComputedComeOutNearestWhereTheyStarted) {
  const std::string text =
      "unidyn: 1\ncoordinates: [theta, z]\nparticles:\n"
      "  P: {mass: 1, position: [cos(theta), sin(theta), z]}\nconstraints:\n"
      "  - {name: pin, position: cos(theta) - 1/2}\n";
  const System system = parse_model(text, "initial.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  SimulationStart start = initial_state(system, {});
  start.q[0] = 1e-6;  // not given: where Newton starts
  const std::vector<std::string> computed = complete_initial_state(system, compiled, start);
  EXPECT_NEAR(std::abs(start.q[0]), std::acos(0.5), 1e-12) << start.q[0];
  ASSERT_EQ(computed.size(), 1u);
  EXPECT_TRUE(contains(computed[0], "theta = ")) << computed[0];
  // from 40 rad, the nearest solution to 40
  start.q[0] = 40.0;
  complete_initial_state(system, compiled, start);
  EXPECT_LT(std::abs(start.q[0] - 40.0), std::numbers::pi) << start.q[0];
  EXPECT_NEAR(std::cos(start.q[0]), 0.5, 1e-12);
}

// One tolerance, relative to the model's size and measured as a distance (|Ψ| over |∂Ψ/∂q|): a
// pendulum of 1 mm given 1e-12 m off its circle (1e-9 of its size) is refused, one of 1 km given
// 1e-8 m off it (1e-11 of its size; Ψ = x² + y² − L² is 2e-5 m² there) is accepted — in metres
// both were judged against 1e-10 absolute before, the wrong way round.
TEST(InitialState, OneToleranceRelativeToTheModelsSize) {
  const auto pendulum = [](double L, double off) {
    return "unidyn: 1\nparameters: {L: " + std::to_string(L) +
           "}\ncoordinates: [x, y]\nparticles:\n  P: {mass: 1, position: [x, y, 0]}\n"
           "constraints:\n  - {name: rod, position: x^2 + y^2 - L^2}\ninitial: {x: 0, y: " +
           detail::to_short_text(-(L + off), 17) + "}\n";
  };
  EXPECT_TRUE(contains(error_of(pendulum(1e-3, 1e-12)), "constraint 'rod'"));
  EXPECT_NO_THROW(complete(pendulum(1e3, 1e-8)));
  // and within it at either size
  EXPECT_NO_THROW(complete(pendulum(1e-3, 1e-15)));
  EXPECT_TRUE(contains(error_of(pendulum(1e3, 1e-5)), "constraint 'rod'"));
  // the fraction itself: Ψ = 2e-5 m² with |∇Ψ| = 2e3 m is 1e-8 m, 1e-11 of 1000 m
  EXPECT_NEAR(relative_residual(2e-5, Eigen::RowVector2d(0, -2e3), Eigen::Vector2d(0, -1e3)), 1e-11,
              1e-24);
}

// A sphere rolling on a plane (Euler parameters): given its forward speed, its spin follows from
// the rolling constraints: ω2 = v/R, e2' = ω2/2 at the identity; nothing else moves.
TEST(InitialState, ARollingSpheresSpinFromItsSpeed) {
  const std::string sphere =
      "unidyn: 1\nparameters: {m: 1, g: 9.81, R: 0.1}\ncoordinates: [x1, x2, x3, e0, e1, e2, e3]\n"
      "bodies:\n  ball:\n    mass: m\n    inertia: {sphere: {radius: R}}\n    rotation: "
      "{quaternion: [e0, e1, e2, e3]}\n    center: [x1, x2, x3]\nforces:\n  - gravity: -g*E3\n"
      "constraints:\n  - {name: plane, position: x3 - R}\n"
      "  - {name: roll1, velocity: \"dot(ball.velocity + cross(ball.omega, -R*E3), E1)\"}\n"
      "  - {name: roll2, velocity: \"dot(ball.velocity + cross(ball.omega, -R*E3), E2)\"}\n"
      "initial: {e0: 1, der(x1): 2}\n";
  const Completed c = complete(sphere);
  EXPECT_DOUBLE_EQ(c.start.q[2], 0.1);  // x3 = R, from the plane
  EXPECT_EQ(c.start.qdot[0], 2.0);
  EXPECT_NEAR(c.start.qdot[5], 2.0 / 0.1 / 2, 1e-14);  // e2' = ω2 / 2
  for (const int i : {1, 2, 3, 4, 6}) EXPECT_NEAR(c.start.qdot[i], 0.0, 1e-15) << i;
}

// initial: {B.omega: [..]} gives the rates of B's rotation: for 3-1-3 angles the angle rates of
// that ω (checked with the rotation layer's own ω of the angles and rates); for Euler parameters,
// with B.omega_body, rates with e·ė = 0 whose body angular velocity 2 (e0 ė − ė0 e − e × ė) is it.
TEST(InitialState, AngularVelocityOfABody) {
  const std::string top =
      "unidyn: 1\nparameters: {m: 1, w3: 5}\ncoordinates: [psi, theta, phi]\nbodies:\n  top:\n"
      "    mass: m\n    inertia: [2, 2, 1]\n    rotation: {euler: 3-1-3, angles: [psi, theta, "
      "phi]}\n    center: [0, 0, 0]\ninitial: {psi: 0.2, theta: 0.3, phi: -0.4, top.omega: [0.1, "
      "-0.2, w3]}\n";
  const Completed c = complete(top);
  const Vec3 w = angular_velocity(EulerSet{3, 1, 3}, Vec3(0.2, 0.3, -0.4),
                                  Vec3(c.start.qdot[0], c.start.qdot[1], c.start.qdot[2]));
  EXPECT_NEAR(w.x(), 0.1, 1e-14);
  EXPECT_NEAR(w.y(), -0.2, 1e-14);
  EXPECT_NEAR(w.z(), 5.0, 1e-14);
  // and der(psi) cannot be given besides
  EXPECT_THROW((void)parse_model(top + "  der(psi): 1\n", "omega.yaml"), ModelError);

  const std::string ball =
      "unidyn: 1\ncoordinates: [e0, e1, e2, e3]\nbodies:\n  B:\n    mass: 1\n    inertia: [1, "
      "2, 3]\n    rotation: {quaternion: [e0, e1, e2, e3]}\n    center: [0, 0, 0]\n"
      "initial: {e0: 0.5, e1: 0.5, e2: 0.5, e3: 0.5, B.omega_body: [1, 2, 3]}\n";
  const Completed b = complete(ball);
  const double e0 = 0.5;
  const Eigen::Vector3d e(0.5, 0.5, 0.5);
  const double de0 = b.start.qdot[0];
  const Eigen::Vector3d de(b.start.qdot[1], b.start.qdot[2], b.start.qdot[3]);
  EXPECT_NEAR(e0 * de0 + e.dot(de), 0.0, 1e-14);
  const Eigen::Vector3d body = 2 * (e0 * de - de0 * e - e.cross(de));
  EXPECT_NEAR(body.x(), 1.0, 1e-13);
  EXPECT_NEAR(body.y(), 2.0, 1e-13);
  EXPECT_NEAR(body.z(), 3.0, 1e-13);
}

// Two rows that say the same thing (x = 0 twice) are accepted, the later one named as depending on
// the one before; two that contradict each other (x = 0, x = 1) cannot hold and are refused.
TEST(InitialState, DependentConstraintsAreNamedAndContradictoryOnesRefused) {
  const std::string twice =
      "unidyn: 1\ncoordinates: [x, y]\nparticles:\n  P: {mass: 1, position: [x, y, 0]}\n"
      "constraints:\n  - {name: a, position: x}\n  - {name: b, position: 2*x}\n";
  EXPECT_EQ(complete(twice).start.dependent_constraints, std::vector<std::string>{"b"});
  const std::string apart =
      "unidyn: 1\ncoordinates: [x, y]\nparticles:\n  P: {mass: 1, position: [x, y, 0]}\n"
      "constraints:\n  - {name: a, position: x}\n  - {name: b, position: x - 1}\n";
  const std::string message = error_of(apart);
  EXPECT_TRUE(contains(message, "contradict the constraints") && contains(message, "'a'"))
      << message;
  EXPECT_TRUE(
      complete(apart.substr(0, apart.rfind("  - {name: b"))).start.dependent_constraints.empty());
}

TEST(InitialState, AUnilateralContactMustNotStartInside) {
  const std::string ball =
      "unidyn: 1\ncoordinates: [z]\nparticles:\n  P: {mass: 1, position: [0, 0, z]}\n"
      "constraints:\n  - {name: floor, position: z, unilateral: true}\ninitial: {z: -0.5}\n";
  EXPECT_TRUE(contains(error_of(ball), "inside the unilateral contact 'floor'"));
}

}  // namespace
}  // namespace unidyn
