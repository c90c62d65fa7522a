// Tree joints (`joint:` on a body, docs/model-format.md): a body placed on its parent by a joint
// has the rotation Q_B = Q_P R0 R(q) and the frame origin o_B = o_P + Q_P (p + R0 d(q)) of
// include/unidyn/model/tree_joint.hpp. The oracles are written here, not by the code under test:
// URDF's rpy as the matrices Rz(y) Ry(p) Rx(r) typed out, each joint's motion by hand, and the
// same mechanism written with the bodies' explicit rotation: and center: (whose kinetic and
// potential energies must agree at random states).
#include <cmath>
#include <map>
#include <random>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "unidyn/io/model_file.hpp"
#include "unidyn/model/scope.hpp"

namespace unidyn {
namespace {

using Matrix3 = Eigen::Matrix3d;
using Vector3 = Eigen::Vector3d;

// Elementary rotations, typed out: counter-clockwise by a about x, y, z.
Matrix3 Rx(double a) {
  Matrix3 R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return R;
}
Matrix3 Ry(double a) {
  Matrix3 R;
  R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return R;
}
Matrix3 Rz(double a) {
  Matrix3 R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}

// The coordinates' values (by name) and the parameters' as a substitution.
GiNaC::exmap state(const System& system, const std::map<std::string, double>& q,
                   const std::map<std::string, double>& rates = {}) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& c : system.coordinates()) {
    values[c.value] = q.count(c.name) ? q.at(c.name) : 0.0;
    values[c.rate] = rates.count(c.name) ? rates.at(c.name) : 0.0;
  }
  return values;
}

double number(const Expr& e, const GiNaC::exmap& values) {
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
}

// A body's rotation and frame origin (B.origin) at a state.
Matrix3 rotation_at(const System& system, const std::string& body, const GiNaC::exmap& values) {
  Matrix3 Q;
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k)
      Q(i, k) = number(system.bodies[*system.find_body(body)].rotation(i, k), values);
  }
  return Q;
}
Vector3 origin_at(const System& system, const std::string& body, const GiNaC::exmap& values) {
  const VectorExpr o = system.bodies[*system.find_body(body)].origin;
  return {number(o[0], values), number(o[1], values), number(o[2], values)};
}

// A spatial arm: a link turned by q1 about y from a fixed frame, a second by q2 about y after a
// joint frame turned by roll 0.4, pitch −0.7, yaw 1.1; a prismatic third along x turned by
// pitch 0.5; a massless tool fixed on it.
const std::string kArm = R"(unidyn: 1
parameters: {m1: 1.2, m2: 0.8, m3: 0.5, L1: 0.9, L2: 0.6, g: 9.81}
coordinates: [q1, q2, s]
bodies:
  base: {joint: {}, mass: 0}
  link1:
    joint: {parent: base, origin: [0, 0, 0.1], revolute: q1, axis: [0, 2, 0]}
    mass: m1
    inertia: [0.02, 0.03, 0.04]
    center: link1.frame_point([0.05, 0, -L1/2])
  link2:
    joint: {parent: link1, origin: [0, 0, -L1], rpy: [0.4, -0.7, 1.1], revolute: q2, axis: [0, 1, 0]}
    mass: m2
    inertia: {tensor: [[0.02, 0.001, 0], [0.001, 0.03, 0.002], [0, 0.002, 0.025]]}
    center: link2.frame_point([0, 0.01, -L2/2])
  slider:
    joint: {parent: link2, origin: [0, 0, -L2], rpy: [0, 0.5, 0], prismatic: s}
    mass: m3
    inertia: [0.001, 0.002, 0.002]
  tool:
    joint: {parent: slider, origin: [0.1, 0, 0]}
    mass: 0
forces:
  - gravity: -g*E3
)";

// The same arm with the bodies' rotations and centres written out by hand.
const std::string kArmByHand = R"(unidyn: 1
parameters: {m1: 1.2, m2: 0.8, m3: 0.5, L1: 0.9, L2: 0.6, g: 9.81}
coordinates: [q1, q2, s]
bodies:
  link1:
    mass: m1
    inertia: [0.02, 0.03, 0.04]
    rotation: {axis: [0, 1, 0], angle: q1}
    center: "[0, 0, 0.1] + 0.05*link1.e1 - L1/2*link1.e3"
  link2:
    mass: m2
    inertia: {tensor: [[0.02, 0.001, 0], [0.001, 0.03, 0.002], [0, 0.002, 0.025]]}
    rotation:
      - {axis: [0, 1, 0], angle: q1}
      - {axis: [0, 0, 1], angle: 1.1}
      - {axis: [0, 1, 0], angle: -0.7}
      - {axis: [1, 0, 0], angle: 0.4}
      - {axis: [0, 1, 0], angle: q2}
    center: "[0, 0, 0.1] - L1*link1.e3 + 0.01*link2.e2 - L2/2*link2.e3"
  slider:
    mass: m3
    inertia: [0.001, 0.002, 0.002]
    rotation:
      - {axis: [0, 1, 0], angle: q1}
      - {axis: [0, 0, 1], angle: 1.1}
      - {axis: [0, 1, 0], angle: -0.7}
      - {axis: [1, 0, 0], angle: 0.4}
      - {axis: [0, 1, 0], angle: q2}
      - {axis: [0, 1, 0], angle: 0.5}
    center: "[0, 0, 0.1] - L1*link1.e3 - L2*link2.e3 + s*slider.e1"
forces:
  - gravity: -g*E3
)";

// Q_B = Q_P R0 R(q) with R0 = Rz(y) Ry(p) Rx(r), o_B = o_P + Q_P (p + R0 d(q)): each frame against
// the matrices typed out above.
TEST(TreeJoints, FramesComposeAsUrdfDefinesThem) {
  const System system = parse_model(kArm, "arm.yaml");
  const double q1 = 0.7, q2 = -1.3, s = 0.25, L1 = 0.9, L2 = 0.6;
  const GiNaC::exmap at = state(system, {{"q1", q1}, {"q2", q2}, {"s", s}});
  const Matrix3 Q1 = Ry(q1);
  const Matrix3 Q2 = Q1 * Rz(1.1) * Ry(-0.7) * Rx(0.4) * Ry(q2);
  const Matrix3 Q3 = Q2 * Ry(0.5);
  const Vector3 o1(0, 0, 0.1);
  const Vector3 o2 = o1 + Q1 * Vector3(0, 0, -L1);
  const Vector3 o3 = o2 + Q2 * (Vector3(0, 0, -L2) + Ry(0.5) * Vector3(s, 0, 0));
  const Vector3 tool = o3 + Q3 * Vector3(0.1, 0, 0);
  EXPECT_LT((rotation_at(system, "link1", at) - Q1).norm(), 1e-14);
  EXPECT_LT((rotation_at(system, "link2", at) - Q2).norm(), 1e-14);
  EXPECT_LT((rotation_at(system, "slider", at) - Q3).norm(), 1e-14);
  EXPECT_LT((rotation_at(system, "tool", at) - Q3).norm(), 1e-14);
  EXPECT_LT((origin_at(system, "link2", at) - o2).norm(), 1e-14);
  EXPECT_LT((origin_at(system, "slider", at) - o3).norm(), 1e-14);
  EXPECT_LT((origin_at(system, "tool", at) - tool).norm(), 1e-14);
  // a body's centre defaults to its frame origin; frame_point is o + Q X
  const VectorExpr center = system.bodies[*system.find_body("link1")].center;
  const Vector3 expected = o1 + Q1 * Vector3(0.05, 0, -L1 / 2);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(number(center[i], at), expected[i], 1e-14);
  const VectorExpr slider = system.bodies[*system.find_body("slider")].center;
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(number(slider[i], at), o3[i], 1e-14);
}

// The tree and the same arm written out by hand have the same T and U at random states, so the
// same equations of motion; the massless frames add nothing.
TEST(TreeJoints, EnergiesAgreeWithTheArmWrittenByHand) {
  const System tree = parse_model(kArm, "arm.yaml");
  const System hand = parse_model(kArmByHand, "hand.yaml");
  std::mt19937 random(38);
  std::uniform_real_distribution<double> any(-2, 2);
  for (int trial = 0; trial < 10; ++trial) {
    const std::map<std::string, double> q{
        {"q1", any(random)}, {"q2", any(random)}, {"s", any(random)}};
    const std::map<std::string, double> rates{
        {"q1", any(random)}, {"q2", any(random)}, {"s", any(random)}};
    const double T = number(hand.kinetic_energy(), state(hand, q, rates));
    const double U = number(hand.potential_energy(), state(hand, q, rates));
    EXPECT_NEAR(number(tree.kinetic_energy(), state(tree, q, rates)), T, 1e-13 * (1 + std::abs(T)));
    EXPECT_NEAR(number(tree.potential_energy(), state(tree, q, rates)), U,
                1e-13 * (1 + std::abs(U)));
  }
}

// A floating joint: seven coordinates, the origin on the joint frame and Euler parameters (6.36),
// with the constraint NAME_unit; a planar joint slides along the next two axes and turns about its
// own; a ball joint turns by four Euler parameters about the joint frame's origin.
TEST(TreeJoints, FloatingAndPlanarJoints) {
  const System system = parse_model(R"(unidyn: 1
coordinates: [x, y, z, e0, e1, e2, e3, u, v, th, f0, f1, f2, f3]
bodies:
  hull:
    joint: {origin: [1, 0, 0], rpy: [0, 0, 0.3], floating: [x, y, z, e0, e1, e2, e3]}
    mass: 2
    inertia: [1, 2, 3]
  cart:
    joint: {parent: hull, planar: [u, v, th], axis: [0, -1, 0]}
    mass: 1
    inertia: [1, 1, 1]
  bob:
    joint: {origin: [0, 0, 1], rpy: [0, 0.2, 0], ball: [f0, f1, f2, f3]}
    mass: 1
    inertia: [1, 1, 1]
)",
                                    "floating.yaml");
  const double h = std::sqrt(0.3 * 0.3 + 0.5 * 0.5 + 0.1 * 0.1 + 0.8 * 0.8);
  const double e0 = 0.3 / h, e1 = 0.5 / h, e2 = -0.1 / h, e3 = 0.8 / h;
  const GiNaC::exmap at = state(system, {{"x", 0.2},
                                         {"y", -0.4},
                                         {"z", 0.6},
                                         {"e0", e0},
                                         {"e1", e1},
                                         {"e2", e2},
                                         {"e3", e3},
                                         {"u", 0.7},
                                         {"v", -0.2},
                                         {"th", 0.9},
                                         {"f0", e3},
                                         {"f1", -e2},
                                         {"f2", e1},
                                         {"f3", e0}});
  // (6.36) typed out for the unit (e0, e)
  Matrix3 E;
  E << e0 * e0 + e1 * e1 - e2 * e2 - e3 * e3, 2 * (e1 * e2 - e0 * e3), 2 * (e1 * e3 + e0 * e2),
      2 * (e1 * e2 + e0 * e3), e0 * e0 - e1 * e1 + e2 * e2 - e3 * e3, 2 * (e2 * e3 - e0 * e1),
      2 * (e1 * e3 - e0 * e2), 2 * (e2 * e3 + e0 * e1), e0 * e0 - e1 * e1 - e2 * e2 + e3 * e3;
  const Matrix3 Q = Rz(0.3) * E;
  const Vector3 o = Vector3(1, 0, 0) + Rz(0.3) * Vector3(0.2, -0.4, 0.6);
  EXPECT_LT((rotation_at(system, "hull", at) - Q).norm(), 1e-14);
  EXPECT_LT((origin_at(system, "hull", at) - o).norm(), 1e-14);
  ASSERT_TRUE(system.find_constraint("hull_unit"));
  // axis −E2: slides along E3 then E1, turns by th about −E2
  const Vector3 oc = o + Q * Vector3(-0.2, 0, 0.7);
  EXPECT_LT((origin_at(system, "cart", at) - oc).norm(), 1e-14);
  EXPECT_LT((rotation_at(system, "cart", at) - Q * Ry(-0.9)).norm(), 1e-14);
  // a ball joint turns by its Euler parameters about the joint frame's origin
  Matrix3 F;
  const double f0 = e3, f1 = -e2, f2 = e1, f3 = e0;
  F << f0 * f0 + f1 * f1 - f2 * f2 - f3 * f3, 2 * (f1 * f2 - f0 * f3), 2 * (f1 * f3 + f0 * f2),
      2 * (f1 * f2 + f0 * f3), f0 * f0 - f1 * f1 + f2 * f2 - f3 * f3, 2 * (f2 * f3 - f0 * f1),
      2 * (f1 * f3 - f0 * f2), 2 * (f2 * f3 + f0 * f1), f0 * f0 - f1 * f1 - f2 * f2 + f3 * f3;
  EXPECT_LT((origin_at(system, "bob", at) - Vector3(0, 0, 1)).norm(), 1e-14);
  EXPECT_LT((rotation_at(system, "bob", at) - Ry(0.2) * F).norm(), 1e-14);
  EXPECT_TRUE(system.find_constraint("bob_unit"));
}

// Each mistake in a joint is refused where it is, saying what was expected.
TEST(TreeJoints, MistakesAreRefusedWhereTheyAre) {
  const std::string head = "unidyn: 1\ncoordinates: [q, r]\nbodies:\n";
  const auto refused = [&](const std::string& body, const std::string& expected, int line,
                           int column) {
    try {
      parse_model(head + body, "bad.yaml");
      ADD_FAILURE() << "no error for\n" << body;
    } catch (const ModelError& e) {
      EXPECT_NE(e.message().find(expected), std::string::npos) << e.what();
      EXPECT_EQ(e.where().line, line) << e.what();
      EXPECT_EQ(e.where().column, column) << e.what();
    }
  };
  const std::string a = "  a: {joint: {revolute: q}, mass: 1, inertia: [1, 1, 1]}\n";
  refused("  a: {joint: {parent: b, revolute: q}, mass: 1}\n", "names a body given before", 4, 23);
  refused("  a: {joint: {revolute: q, prismatic: r}, mass: 1}\n", "one motion", 4, 39);
  refused(a + "  b: {joint: {revolute: q}, mass: 1, inertia: [1, 1, 1]}\n", "already moves", 5, 25);
  refused("  a: {joint: {revolute: q, axis: [0, 0, 0]}, mass: 1}\n", "zero vector", 4, 34);
  refused("  a: {joint: {planar: [q, r, q]}, mass: 1}\n", "differ", 4, 30);
  refused("  a: {joint: {origin: [q, 0, 0]}, mass: 1}\n", "constant", 4, 23);
  refused("  a: {joint: {rpy: [0, 0, 0], rotation: {axis: [0, 0, 1], angle: 1}}, mass: 1}\n",
          "not both", 4, 14);
  refused("  a: {joint: {revolute: q}, rotation: {axis: [0, 0, 1], angle: q}, mass: 1}\n",
          "rotation", 4, 29);
  refused(
      "  a: {mass: 0, inertia: [1, 1, 1], rotation: {axis: [0, 0, 1], angle: q}, center: "
      "[0, 0, 0]}\n",
      "positive", 4, 13);
  refused("  a: {joint: {axis: [0, 0, 1]}, mass: 1}\n", "axis: is for", 4, 21);
}

}  // namespace
}  // namespace unidyn
