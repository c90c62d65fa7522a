// The model file reader (DESIGN.md, "Model file (YAML) — the user contract"): a valid file gives
// the System it describes; every mistake is a ModelError at the line and column of the offending
// token that says what was expected; nothing in a file is executed, and hostile input is refused.
#include "unidyn/io/model_file.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace unidyn {
namespace {

using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// The lines of a file joined with '\n' (line n of the file is element n − 1).
std::string yaml(std::initializer_list<std::string> lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

// 1-based column of `token` in `line` (which must hold it exactly once).
int column_of(const std::string& line, const std::string& token) {
  const std::size_t at = line.find(token);
  EXPECT_NE(at, std::string::npos) << token << " not in " << line;
  EXPECT_EQ(line.find(token, at + 1), std::string::npos) << token << " twice in " << line;
  return static_cast<int>(at) + 1;
}

// The start of a valid model; error cases append to it from line 6.
const std::string kLine2 = "parameters: {m: 1.5, g: 9.81, k: 10}";
const std::string kLine5 = "  P: {mass: m, position: [x, y, 0]}";
std::string base() {
  return yaml({"unidyn: 1", kLine2, "coordinates: [x, y]", "particles:", kLine5});
}

// Expects `text` to be refused with a ModelError at line:column whose message contains each of
// `expected`; the error also prints as "test.yaml:line:column: message".
void expect_error(const std::string& text, int line, int column,
                  std::initializer_list<std::string> expected) {
  try {
    parse_model(text, "test.yaml");
    ADD_FAILURE() << "no error for\n" << text;
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, "test.yaml");
    EXPECT_EQ(e.where().line, line) << e.what() << "\nfor\n" << text;
    EXPECT_EQ(e.where().column, column) << e.what() << "\nfor\n" << text;
    for (const std::string& part : expected) {
      EXPECT_NE(e.message().find(part), std::string::npos)
          << "message '" << e.message() << "' lacks '" << part << "'\nfor\n"
          << text;
    }
    EXPECT_EQ(std::string(e.what()), "test.yaml:" + std::to_string(line) + ":" +
                                         std::to_string(column) + ": " + e.message());
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ModelError: " << e.what() << "\nfor\n" << text;
  }
}

// Expects `text` to be refused with some ModelError (for hostile input, where the point is that
// nothing else happens).
void expect_refused(const std::string& text, const std::string& expected) {
  try {
    parse_model(text, "test.yaml");
    ADD_FAILURE() << "no error for a text of " << text.size() << " characters";
  } catch (const ModelError& e) {
    EXPECT_NE(e.message().find(expected), std::string::npos) << e.what();
    EXPECT_GT(e.where().line, 0) << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a ModelError: " << e.what();
  }
}

// A state at which to evaluate what a System holds: q, der(q) by name, and t.
struct State {
  std::map<std::string, double> q;
  std::map<std::string, double> rate;
  double t = 0;
};

// The number `e` is at `state`, with the parameters at their values.
double value_at(const System& system, const Expr& e, const State& state = {}) {
  GiNaC::exmap values = system.parameter_values();
  for (const auto& c : system.coordinates()) {
    if (state.q.count(c.name)) values[c.value] = state.q.at(c.name);
    if (state.rate.count(c.name)) values[c.rate] = state.rate.at(c.name);
  }
  values[system.time()] = state.t;
  const Expr v = GiNaC::evalf(e.subs(values));
  if (!is_a<numeric>(v)) {
    ADD_FAILURE() << e << " is not a number at the state: " << v;
    return NAN;
  }
  return ex_to<numeric>(v).to_double();
}

std::string printed(const Expr& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

// One model with every section and every kind of force and constraint.
const std::string kEverything = yaml({
    "unidyn: 1",                                                                         // 1
    "name: Everything at once",                                                          // 2
    "description: a test of the reader",                                                 // 3
    "reference: none",                                                                   // 4
    "parameters: {m: 2, k: 10, L0: 0.5, c: 0.3, g: 9.81, G: 6.5, F0: 1.5}",              // 5
    "coordinates: [x, y]",                                                               // 6
    "particles:",                                                                        // 7
    "  P: {mass: m, position: [x, y, 0]}",                                               // 8
    "  Q: {mass: 3*m, position: \"[0, 0, 2]\"}",                                         // 9
    "forces:",                                                                           // 10
    "  - gravity: -g*E3",                                                                // 11
    "  - spring: {from: P, to: [0, 0, 0], stiffness: k, rest_length: L0}",               // 12
    "  - spring: {from: P, to: Q, energy: k*s^4/4}",                                     // 13
    "  - damper: {from: P, to: [0, 0, 0], coefficient: c}",                              // 14
    "  - force: {at: P, value: \"[F0*sin(t), 0, der(x)]\"}",                             // 15
    "  - potential: k*y^2",                                                              // 16
    "  - gravitation: {between: [P, Q], G: G}",                                          // 17
    "constraints:",                                                                      // 18
    "  - {name: rail, position: x^2 + y^2 - 4}",                                         // 19
    "  - {name: roll, velocity: \"der(x) - 2*sin(y)*der(y) + t\"}",                      // 20
    "  - {name: floor, position: y, unilateral: true}",                                  // 21
    "  - {name: track, position: x - y, friction: {on: P, dynamic: 0.2, static: 0.3}}",  // 22
    "  - {position: x + y}",                                                             // 23
    "initial: {x: 2*L0, der(x): F0/m, y: 0.25}",                                         // 24
    "simulate: {t_end: 2.5, output_step: 0.05, method: rk4, rtol: 1e-8, atol: 1e-11, step: "
    "0.001}",                                                         // 25
    "outputs:",                                                       // 26
    "  pull: 2*rail.lambda",                                          // 27
    "  speed: norm(P.velocity)",                                      // 28
    "conserved: {Lz: \"dot(cross(P.position, m*P.velocity), E3)\"}",  // 29
});

// The names, values and places of parameters, coordinates and particles are those of the file.
TEST(ModelFile, ParametersCoordinatesParticles) {
  const System s = parse_model(kEverything, "everything.yaml");
  EXPECT_EQ(s.name, "Everything at once");
  EXPECT_EQ(s.source, "everything.yaml");
  const std::vector<std::pair<std::string, double>> parameters = {
      {"m", 2}, {"k", 10}, {"L0", 0.5}, {"c", 0.3}, {"g", 9.81}, {"G", 6.5}, {"F0", 1.5}};
  ASSERT_EQ(s.parameters.size(), parameters.size());
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    EXPECT_EQ(s.parameters[i].name, parameters[i].first);
    EXPECT_EQ(s.parameters[i].value, parameters[i].second);
    EXPECT_EQ(printed(s.parameters[i].symbol), parameters[i].first);
  }
  EXPECT_EQ(s.parameters[2].where.str(), "everything.yaml:5:27");  // L0
  ASSERT_EQ(s.coordinates().size(), 2u);
  EXPECT_EQ(s.coordinates()[0].name, "x");
  EXPECT_EQ(s.coordinates()[1].name, "y");

  ASSERT_EQ(s.particles.size(), 2u);
  EXPECT_EQ(s.particles[0].name, "P");
  EXPECT_EQ(s.particles[1].name, "Q");
  EXPECT_EQ(s.particles[1].where.str(), "everything.yaml:9:3");
  const State state{{{"x", 0.6}, {"y", 0.8}}, {}, 0};
  EXPECT_EQ(value_at(s, s.particles[0].mass), 2.0);
  EXPECT_EQ(value_at(s, s.particles[1].mass), 6.0);
  EXPECT_EQ(value_at(s, s.particles[0].position[0], state), 0.6);
  EXPECT_EQ(value_at(s, s.particles[0].position[1], state), 0.8);
  EXPECT_EQ(value_at(s, s.particles[0].position[2], state), 0.0);
  EXPECT_EQ(value_at(s, s.particles[1].position[2], state), 2.0);
}

// Each force element holds the potential and the particle forces of its kind.
TEST(ModelFile, ForcesOfEveryKind) {
  const System s = parse_model(kEverything, "everything.yaml");
  using Kind = ForceElement::Kind;
  const std::vector<Kind> kinds = {Kind::gravity, Kind::spring,    Kind::spring,     Kind::damper,
                                   Kind::force,   Kind::potential, Kind::gravitation};
  ASSERT_EQ(s.forces.size(), kinds.size());
  for (std::size_t i = 0; i < kinds.size(); ++i) {
    EXPECT_EQ(s.forces[i].kind, kinds[i]) << i;
    EXPECT_EQ(s.forces[i].where.line, static_cast<int>(11 + i)) << i;
    EXPECT_EQ(s.forces[i].where.column, 5) << i;
  }
  const double m = 2, k = 10, L0 = 0.5, c = 0.3, g = 9.81, G = 6.5, F0 = 1.5;
  const double x = 0.6, y = 0.8, xdot = 1.0, ydot = 2.0, t = 0.5;
  const State state{{{"x", x}, {"y", y}}, {{"x", xdot}, {"y", ydot}}, t};
  const auto force = [&](const ForceElement& f, std::size_t n, int axis) {
    return value_at(s, f.forces.at(n).force[axis], state);
  };

  // gravity: U = −Σ m g · r; F = m g on each particle
  const ForceElement& gravity = s.forces[0];
  EXPECT_TRUE(gravity.conservative);
  EXPECT_NEAR(value_at(s, gravity.potential, state), 3 * m * g * 2, 1e-12);
  ASSERT_EQ(gravity.forces.size(), 2u);
  EXPECT_EQ(gravity.forces[0].particle, 0u);
  EXPECT_EQ(gravity.forces[1].particle, 1u);
  EXPECT_NEAR(force(gravity, 0, 2), -m * g, 1e-12);
  EXPECT_NEAR(force(gravity, 1, 2), -3 * m * g, 1e-12);
  EXPECT_EQ(force(gravity, 0, 0), 0.0);

  // linear spring from P to the origin: |r| = 1, U = ½ k (1 − L0)², F_P = k (1 − L0) (−r)
  const ForceElement& linear = s.forces[1];
  EXPECT_TRUE(linear.conservative);
  EXPECT_NEAR(value_at(s, linear.potential, state), 0.5 * k * (1 - L0) * (1 - L0), 1e-12);
  ASSERT_EQ(linear.forces.size(), 1u);  // the fixed end is no particle
  EXPECT_EQ(linear.forces[0].particle, 0u);
  EXPECT_NEAR(force(linear, 0, 0), -k * (1 - L0) * x, 1e-12);
  EXPECT_NEAR(force(linear, 0, 1), -k * (1 - L0) * y, 1e-12);

  // spring with energy U(s) = k s⁴/4 between P and Q: s = |r_Q − r_P| = √5, U'(s) = k s³
  const ForceElement& quartic = s.forces[2];
  const double stretch = std::sqrt(5.0);
  EXPECT_NEAR(value_at(s, quartic.potential, state), k * std::pow(stretch, 4) / 4, 1e-10);
  ASSERT_EQ(quartic.forces.size(), 2u);
  // on Q (to): −U'(s) e, e = (r_Q − r_P)/s
  EXPECT_NEAR(force(quartic, 0, 2), -k * std::pow(stretch, 3) * 2 / stretch, 1e-10);
  // on P (from): +U'(s) e
  EXPECT_NEAR(force(quartic, 1, 0), k * std::pow(stretch, 3) * (-x) / stretch, 1e-10);

  // damper from P to the origin: ṡ = r·v/|r|, F_P = −c ṡ r/|r|; no potential
  const ForceElement& damper = s.forces[3];
  EXPECT_FALSE(damper.conservative);
  EXPECT_TRUE(damper.potential.is_zero());
  ASSERT_EQ(damper.forces.size(), 1u);
  const double sdot = x * xdot + y * ydot;
  EXPECT_NEAR(force(damper, 0, 0), -c * sdot * x, 1e-12);
  EXPECT_NEAR(force(damper, 0, 1), -c * sdot * y, 1e-12);
  EXPECT_EQ(force(damper, 0, 2), 0.0);

  // applied force on P: [F0 sin t, 0, der(x)]
  const ForceElement& applied = s.forces[4];
  EXPECT_FALSE(applied.conservative);
  ASSERT_EQ(applied.forces.size(), 1u);
  EXPECT_EQ(applied.forces[0].particle, 0u);
  EXPECT_NEAR(force(applied, 0, 0), F0 * std::sin(t), 1e-15);
  EXPECT_NEAR(force(applied, 0, 2), xdot, 1e-15);

  // potential in the coordinates: U = k y², no force vectors
  const ForceElement& potential = s.forces[5];
  EXPECT_TRUE(potential.conservative);
  EXPECT_TRUE(potential.forces.empty());
  EXPECT_NEAR(value_at(s, potential.potential, state), k * y * y, 1e-12);

  // gravitation between P and Q: U = −G m_P m_Q/|r_Q − r_P|, F_Q = −G m_P m_Q d/|d|³
  const ForceElement& gravitation = s.forces[6];
  EXPECT_TRUE(gravitation.conservative);
  EXPECT_NEAR(value_at(s, gravitation.potential, state), -G * m * 3 * m / stretch, 1e-12);
  ASSERT_EQ(gravitation.forces.size(), 2u);
  EXPECT_EQ(gravitation.forces[0].particle, 1u);
  EXPECT_NEAR(force(gravitation, 0, 2), -G * m * 3 * m * 2 / std::pow(stretch, 3), 1e-12);
  EXPECT_NEAR(force(gravitation, 1, 2), G * m * 3 * m * 2 / std::pow(stretch, 3), 1e-12);

  // The system's potential energy is the sum of the conservative elements'.
  double U = 0;
  for (const auto& f : s.forces) U += value_at(s, f.potential, state);
  EXPECT_NEAR(value_at(s, s.potential_energy(), state), U, 1e-10);
}

// Constraints: kinds, expressions, unilateral, friction, multipliers lambda(name), default names.
TEST(ModelFile, Constraints) {
  const System s = parse_model(kEverything, "everything.yaml");
  ASSERT_EQ(s.constraints.size(), 5u);
  const std::vector<std::string> names = {"rail", "roll", "floor", "track", "c5"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(s.constraints[i].name, names[i]);
    EXPECT_EQ(printed(s.constraints[i].multiplier), "lambda(" + names[i] + ")");
    EXPECT_EQ(s.constraints[i].where.line, static_cast<int>(19 + i));
    EXPECT_EQ(s.constraints[i].where.column, 5);
  }
  // distinct symbols, also from every other symbol of the model
  EXPECT_FALSE(s.constraints[0].multiplier.is_equal(s.constraints[1].multiplier));

  using Kind = Constraint::Kind;
  const State state{{{"x", 0.6}, {"y", 0.8}}, {{"x", 1.0}, {"y", 2.0}}, 0.5};
  EXPECT_EQ(s.constraints[0].kind, Kind::position);
  EXPECT_NEAR(value_at(s, s.constraints[0].expression, state), 1 - 4, 1e-15);
  EXPECT_EQ(s.constraints[1].kind, Kind::velocity);
  EXPECT_NEAR(value_at(s, s.constraints[1].expression, state), 1 - 2 * std::sin(0.8) * 2 + 0.5,
              1e-15);
  EXPECT_EQ(s.constraints[2].kind, Kind::position);
  EXPECT_TRUE(s.constraints[2].unilateral);
  EXPECT_FALSE(s.constraints[0].unilateral);
  EXPECT_FALSE(s.constraints[0].friction.has_value());
  ASSERT_TRUE(s.constraints[3].friction.has_value());
  EXPECT_EQ(s.constraints[3].friction->on, "P");
  EXPECT_NEAR(value_at(s, s.constraints[3].friction->dynamic_coefficient), 0.2, 1e-15);
  EXPECT_NEAR(value_at(s, s.constraints[3].friction->static_coefficient), 0.3, 1e-15);
  EXPECT_NEAR(value_at(s, s.constraints[4].expression, state), 1.4, 1e-15);

  // Without static:, the static coefficient is the dynamic one; unilateral: false is false.
  const System t =
      parse_model(base() + yaml({"constraints:", "  - {name: a, position: y, unilateral: false,",
                                 "     friction: {on: P, dynamic: 0.4}}"}),
                  "test.yaml");
  ASSERT_EQ(t.constraints.size(), 1u);
  EXPECT_FALSE(t.constraints[0].unilateral);
  ASSERT_TRUE(t.constraints[0].friction.has_value());
  EXPECT_NEAR(value_at(t, t.constraints[0].friction->static_coefficient), 0.4, 1e-15);
}

// initial: values and rates are expressions of the parameters; what is not given is 0.
// Euler parameters get their unit-norm constraint also as a factor of a product of rotations
// (a satellite's attitude in its orbiting frame): without it M is singular along e.
TEST(ModelFile, QuaternionInAProductGetsItsUnitNorm) {
  const System s = parse_model(
      yaml({"unidyn: 1", "name: q", "parameters: {w: 1}",
            "coordinates: [e0, e1, e2, e3, f0, f1, f2, f3]", "bodies:", "  b:", "    mass: 1",
            "    inertia: [1, 2, 3]",
            "    rotation: [{axis: [0, 0, 1], angle: w*t}, {quaternion: [e0, e1, e2, e3]},",
            "               {quaternion: [f0, f1, f2, f3]}]", "    center: [0, 0, 0]"}),
      "q.yaml");
  ASSERT_EQ(s.constraints.size(), 2u);
  EXPECT_EQ(s.constraints[0].name, "b_unit");
  EXPECT_EQ(s.constraints[1].name, "b_unit2");
  for (const Constraint& c : s.constraints) {
    EXPECT_TRUE(c.parametrisation);
    EXPECT_EQ(c.kind, Constraint::Kind::position);
  }
  const State unit{{{"e0", 0.6},
                    {"e1", 0.8},
                    {"e2", 0.0},
                    {"e3", 0.0},
                    {"f0", 0.0},
                    {"f1", 0.0},
                    {"f2", 0.0},
                    {"f3", 1.0}},
                   {},
                   0.0};
  EXPECT_NEAR(value_at(s, s.constraints[0].expression, unit), 0.0, 1e-15);
  EXPECT_NEAR(value_at(s, s.constraints[1].expression, unit), 0.0, 1e-15);
}

// visual: a shape in the body's basis and a colour; an inertia given as a shape is drawn as it;
// a colour not #rrggbb and a key that is neither are refused where they are.
TEST(ModelFile, BodyVisuals) {
  const auto body = [](const std::string& inertia, const std::string& visual) {
    std::vector<std::string> lines{"unidyn: 1",
                                   "name: v",
                                   "parameters: {R: 2}",
                                   "coordinates: [a]",
                                   "bodies:",
                                   "  b:",
                                   "    mass: 1",
                                   "    inertia: " + inertia,
                                   "    rotation: {axis: [0, 0, 1], angle: a}",
                                   "    center: [0, 0, 0]"};
    if (!visual.empty()) lines.push_back("    visual: " + visual);
    std::string text;
    for (const std::string& line : lines) text += line + "\n";
    return text;
  };
  const System box =
      parse_model(body("[1, 2, 3]", "{box: {a: 1, b: R, c: 3}, color: \"#aa3300\"}"), "v.yaml");
  EXPECT_EQ(box.bodies[0].visual.shape, "box");
  ASSERT_EQ(box.bodies[0].visual.dimensions.size(), 3u);
  EXPECT_EQ(box.bodies[0].visual.dimensions[1], box.parameters[0].symbol);
  EXPECT_EQ(box.bodies[0].visual.color, "#aa3300");
  const System disk = parse_model(body("{disk: {radius: R}}", ""), "v.yaml");
  EXPECT_EQ(disk.bodies[0].visual.shape, "disk");
  EXPECT_EQ(disk.bodies[0].visual.color, "");
  const System plain = parse_model(body("[1, 2, 3]", ""), "v.yaml");
  EXPECT_EQ(plain.bodies[0].visual.shape, "");
  expect_error(body("[1, 2, 3]", "{color: red}"), 11, 21, {"#rrggbb"});
  expect_error(body("[1, 2, 3]", "{teapot: {size: 1}}"), 11, 14, {"visual: has a shape"});
  expect_error(body("[1, 2, 3]", "{sphere: {}}"), 11, 22, {"sphere needs radius:"});
}

TEST(ModelFile, InitialValues) {
  const System s = parse_model(kEverything, "everything.yaml");
  ASSERT_EQ(s.initial_values.size(), 2u);
  ASSERT_EQ(s.initial_rates.size(), 2u);
  EXPECT_EQ(value_at(s, s.initial_values[0]), 1.0);   // 2*L0
  EXPECT_EQ(value_at(s, s.initial_values[1]), 0.25);  // y
  EXPECT_EQ(value_at(s, s.initial_rates[0]), 0.75);   // F0/m
  EXPECT_EQ(value_at(s, s.initial_rates[1]), 0.0);    // not given
  // exact: 2*L0 is 2 L0, not a number computed from its value
  const Expr L0 = s.parameters[2].symbol;
  EXPECT_TRUE((s.initial_values[0] - 2 * L0).is_zero()) << s.initial_values[0];
}

// simulate: every setting; a model without it gets the defaults.
TEST(ModelFile, SimulateSettings) {
  const System s = parse_model(kEverything, "everything.yaml");
  EXPECT_EQ(s.simulate.t_end, 2.5);
  EXPECT_EQ(s.simulate.output_step, 0.05);
  EXPECT_EQ(s.simulate.method, "rk4");
  EXPECT_EQ(s.simulate.rtol, 1e-8);
  EXPECT_EQ(s.simulate.atol, 1e-11);
  EXPECT_EQ(s.simulate.step, 0.001);

  const System d = parse_model(base(), "minimal.yaml");
  const SimulationSettings defaults;
  EXPECT_EQ(d.simulate.t_end, defaults.t_end);
  EXPECT_EQ(d.simulate.output_step, defaults.output_step);
  EXPECT_EQ(d.simulate.method, "dopri5");
  EXPECT_EQ(d.name, "minimal.yaml");  // no name: the file's
  EXPECT_TRUE(d.forces.empty());
  EXPECT_TRUE(d.constraints.empty());
  EXPECT_TRUE(d.outputs.empty());
  EXPECT_TRUE(d.conserved.empty());
  ASSERT_EQ(d.initial_values.size(), 2u);
  EXPECT_TRUE(d.initial_values[0].is_zero());
  EXPECT_TRUE(d.initial_rates[1].is_zero());
}

// outputs and conserved: named expressions in file order; c.lambda is the constraint's multiplier.
TEST(ModelFile, OutputsAndConserved) {
  const System s = parse_model(kEverything, "everything.yaml");
  ASSERT_EQ(s.outputs.size(), 2u);
  EXPECT_EQ(s.outputs[0].name, "pull");
  EXPECT_EQ(s.outputs[1].name, "speed");
  EXPECT_EQ(s.outputs[0].where.str(), "everything.yaml:27:3");
  EXPECT_TRUE((s.outputs[0].expression - 2 * s.constraints[0].multiplier).is_zero())
      << s.outputs[0].expression;
  const State state{{{"x", 0.6}, {"y", 0.8}}, {{"x", 3.0}, {"y", 4.0}}, 0};
  EXPECT_NEAR(value_at(s, s.outputs[1].expression, state), 5.0, 1e-15);
  ASSERT_EQ(s.conserved.size(), 1u);
  EXPECT_EQ(s.conserved[0].name, "Lz");
  // m (x ẏ − y ẋ)
  const State turning{{{"x", 0.6}, {"y", 0.8}}, {{"x", 3.0}, {"y", 1.0}}, 0};
  EXPECT_NEAR(value_at(s, s.conserved[0].expression, turning), 2 * (0.6 * 1 - 0.8 * 3), 1e-14);
}

// load_model reads a file and names it in errors; a missing file is a ModelError too.
TEST(ModelFile, LoadModelFromFile) {
  const std::string path =
      testing::TempDir() + "unidyn_model_file_" + std::to_string(getpid()) + ".yaml";
  {
    std::ofstream out(path);
    out << base() << "outputs: {r: norm(P.position) + nosuch}\n";
  }
  try {
    load_model(path);
    ADD_FAILURE() << "no error";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.where().line, 6);
    EXPECT_EQ(e.where().column, 33);  // of nosuch
    EXPECT_EQ(std::string(e.what()), path + ":6:33: " + e.message());
  }
  {
    std::ofstream out(path);
    out << base();
  }
  const System s = load_model(path);
  EXPECT_EQ(s.source, path);
  EXPECT_EQ(s.particles.size(), 1u);
  std::remove(path.c_str());

  try {
    load_model(path);
    ADD_FAILURE() << "no error for a missing file";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_NE(e.message().find("cannot open"), std::string::npos) << e.what();
  }
}

// YAML that is not YAML: the place where the YAML parser stopped.
TEST(ModelFileErrors, YamlSyntax) {
  expect_error(yaml({"unidyn: 1", "parameters: {m: 1}}"}), 2, 19, {"YAML syntax"});
  expect_error(yaml({"unidyn: 1", "coordinates: [x, y]]"}), 2, 20, {"YAML syntax"});
  expect_error(yaml({"unidyn: 1", "parameters: {m: 1, g: *nosuch}"}), 2, 23,
               {"YAML syntax", "anchor"});
  expect_error(yaml({"unidyn: 1", "particles:", "  P: {mass: 1, position: [x, 0, 0]}", " Q: 1"}), 4,
               2, {"YAML syntax"});
}

// An empty file, the version line missing or wrong.
TEST(ModelFileErrors, EmptyFileAndVersion) {
  expect_error("", 1, 1, {"empty"});
  expect_error("   \n\n", 1, 1, {"empty"});
  expect_error("# nothing but a comment\n", 1, 1, {"empty"});
  expect_error(yaml({"coordinates: [x]", "particles: {P: {mass: 1, position: [x, 0, 0]}}"}), 1, 1,
               {"missing 'unidyn: 1'"});
  expect_error(yaml({"# a comment first", "coordinates: [x]"}), 2, 1, {"missing 'unidyn: 1'"});
  expect_error(yaml({"unidyn: 2", "coordinates: [x]"}), 1, 9, {"expected 'unidyn: 1'"});
  expect_error(yaml({"unidyn: one", "coordinates: [x]"}), 1, 9, {"expected 'unidyn: 1'"});
  expect_error(yaml({"- unidyn: 1"}), 1, 1, {"mapping"});
  expect_error(yaml({"unidyn: 1"}), 1, 1, {"missing 'coordinates:'"});
  expect_error(yaml({"unidyn: 1", "coordinates: [x]"}), 1, 1, {"no particles"});
}

// A misspelt or repeated key is an error, never silently ignored.
TEST(ModelFileErrors, UnknownAndRepeatedKeys) {
  expect_error(base() + "partciles: {}\n", 6, 1,
               {"unknown key 'partciles'", "expected one of", "particles"});
  const std::string particle = "  Q: {mass: m, position: [x, 0, 0], colour: red}";
  expect_error(base() + particle + "\n", 6, column_of(particle, "colour"),
               {"unknown key 'colour'", "mass", "position"});
  const std::string spring = "  - spring: {from: P, to: [0, 0, 0], stiffnes: k}";
  expect_error(base() + "forces:\n" + spring + "\n", 7, column_of(spring, "stiffnes"),
               {"unknown key 'stiffnes'", "stiffness"});
  const std::string constraint = "  - {name: c, position: x, bilateral: true}";
  expect_error(base() + "constraints:\n" + constraint + "\n", 7, column_of(constraint, "bilateral"),
               {"unknown key 'bilateral'", "unilateral"});
  const std::string simulate = "simulate: {t_end: 1, tend: 2}";
  expect_error(base() + simulate + "\n", 6, column_of(simulate, "tend:"), {"unknown key 'tend'"});
  const std::string friction = "  - {position: y, friction: {on: P, dynamics: 0.1}}";
  expect_error(base() + "constraints:\n" + friction + "\n", 7, column_of(friction, "dynamics"),
               {"unknown key 'dynamics'", "dynamic"});
  // the same key twice: the second would otherwise hide the first
  expect_error(base() + "forces: [{gravity: -g*E3}]\nforces: []\n", 7, 1, {"'forces'", "twice"});
  expect_error(base() + "initial: {x: 1, y: 2, x: 3}\n", 6, 23, {"'x'", "twice"});
  expect_error(base() + "simulate: {t_end: 1, t_end: 2}\n", 6, 22, {"'t_end'", "twice"});
}

// An expression error inside a YAML value is placed inside the expression, however the value is
// written: plain, quoted, in a block, over several lines, with a tag or an anchor.
TEST(ModelFileErrors, ExpressionErrorInsideValue) {
  const auto particle = [](const std::vector<std::string>& lines) {
    std::string text = yaml({"unidyn: 1", kLine2, "coordinates: [x, y]", "particles:"});
    for (const auto& line : lines) text += line + "\n";
    return text;
  };
  for (const std::string line :
       {"  P: {mass: m + foo, position: [x, y, 0]}",
        "  P: {mass: \"m + foo\", position: [x, y, 0]}",
        "  P: {mass: 'm + foo', position: [x, y, 0]}", "  P: {mass: m, position: [x, m + foo, 0]}",
        "  P: {mass: m, position: \"[x, m + foo, 0]\"}",
        "  P: {mass: !!str m + foo, position: [x, y, 0]}",
        "  P: {mass: &a m + foo, position: [x, y, 0]}"}) {
    expect_error(particle({line}), 5, column_of(line, "foo"), {"unknown name 'foo'"});
  }
  // block mapping, plain and double-quoted
  for (const std::string line : {"    mass: m + foo", "    mass: \"m * (g + foo)\""}) {
    expect_error(particle({"  P:", line, "    position: [x, y, 0]"}), 6, column_of(line, "foo"),
                 {"unknown name 'foo'"});
  }
  // over several lines: the line and column of foo itself
  expect_error(particle({"  P:", "    mass: m +", "      foo", "    position: [x, y, 0]"}), 7, 7,
               {"unknown name 'foo'"});
  expect_error(particle({"  P:", "    mass: \"m +", "      g * foo\"", "    position: [x, y, 0]"}),
               7, 11, {"unknown name 'foo'"});
  expect_error(
      particle({"  P:", "    mass: |", "      m +", "        foo", "    position: [x, y, 0]"}), 8,
      9, {"unknown name 'foo'"});
  expect_error(particle({"  P:", "    mass: >-  # folded", "      m +", "", "      foo",
                         "    position: [x, y, 0]"}),
               9, 7, {"unknown name 'foo'"});
  expect_error(particle({"  P: {mass: m, position: [x,", "    y + foo, 0]}"}), 6, 9,
               {"unknown name 'foo'"});
  // a file with Windows line ends, and one with a byte-order mark
  const std::string folded =
      particle({"  P:", "    mass: m +", "      foo", "    position: [x, y, 0]"});
  std::string windows;
  for (const char c : folded) windows += c == '\n' ? std::string("\r\n") : std::string(1, c);
  expect_error(windows, 7, 7, {"unknown name 'foo'"});
  expect_error("\xEF\xBB\xBF" + folded, 7, 7, {"unknown name 'foo'"});
  // the parser's own errors, also placed inside
  const std::string unbalanced = "  P: {mass: \"m * (g + 1\", position: [x, y, 0]}";
  expect_error(
      particle({unbalanced}), 5, column_of(unbalanced, "\", "),
      {"'(' at 5:" + std::to_string(column_of(unbalanced, "(g")), "end of the expression"});
  const std::string scalar = "  P: {mass: m, position: \"m*g\"}";
  expect_error(particle({scalar}), 5, column_of(scalar, "m*g"), {"expected a vector"});
  const std::string vector = "  P: {mass: \"[m, 0, 0]\", position: [x, y, 0]}";
  expect_error(particle({vector}), 5, column_of(vector, "[m"), {"expected a scalar"});
  // in outputs, initial values and forces alike
  const std::string output = "outputs: {r: \"norm(P.position) + P.nosuch\"}";
  expect_error(base() + output + "\n", 6, column_of(output, "P.nosuch"), {"'P.nosuch'"});
  const std::string initial = "initial: {x: 2 *  * m}";
  expect_error(base() + initial + "\n", 6, column_of(initial, "* m"), {"expected"});
  const std::string gravity = "  - gravity: -g*E4";
  expect_error(base() + "forces:\n" + gravity + "\n", 7, column_of(gravity, "E4"), {"'E4'"});
}

// A name used twice, in any two sections.
TEST(ModelFileErrors, DuplicateNames) {
  // a coordinate named like a parameter
  expect_error(yaml({"unidyn: 1", "parameters: {m: 1, x: 2}", "coordinates: [y, x]"}), 3, 18,
               {"'x' is already defined"});
  // a parameter twice
  expect_error(yaml({"unidyn: 1", "parameters: {m: 1, m: 2}", "coordinates: [y]"}), 2, 20, {"'m'"});
  // a coordinate twice
  expect_error(yaml({"unidyn: 1", "coordinates: [y, y]"}), 2, 18, {"'y' is already defined"});
  // a particle named like a coordinate
  expect_error(base() + "  y: {mass: m, position: [0, 0, 0]}\n", 6, 3, {"'y' is already defined"});
  // two constraints with one name
  const std::string second = "  - {name: c, position: y}";
  expect_error(base() + "constraints:\n  - {name: c, position: x}\n" + second + "\n", 8,
               column_of(second, "c,"), {"'c' is already defined"});
  // a constraint named like a particle, a parameter or a coordinate
  for (const std::string name : {"P", "m", "x"}) {
    const std::string line = "  - {name: " + name + ", position: y}";
    expect_error(base() + "constraints:\n" + line + "\n", 7, 12, {"'" + name + "'"});
  }
  // a default name taken by an earlier constraint
  expect_error(base() + "constraints:\n  - {name: c2, position: x}\n  - {position: y}\n", 8, 5,
               {"'c2' is already defined"});
  // two outputs with one name, or an output named like a column of the CSV
  expect_error(base() + "outputs: {a: x, a: y}\n", 6, 17, {"'a'"});
  for (const std::string name : {"t", "x", "der(y)", "energy"}) {
    const std::string line = "outputs: {\"" + name + "\": x + y}";
    expect_error(base() + line + "\n", 6, 11, {name});
  }
  expect_error(base() + "constraints: [{name: c, position: x}]\noutputs: {lambda(c): x}\n", 7, 11,
               {"lambda(c)"});
  expect_error(base() + "outputs: {a: x}\nconserved: {a: y}\n", 7, 13, {"'a'"});
}

// Names the expression language defines itself, and names that are not names.
TEST(ModelFileErrors, ReservedAndInvalidNames) {
  expect_error(yaml({"unidyn: 1", "parameters: {sin: 1}", "coordinates: [x]"}), 2, 14,
               {"'sin' is a reserved word"});
  expect_error(yaml({"unidyn: 1", "parameters: {lambda: 1}", "coordinates: [x]"}), 2, 14,
               {"'lambda' is a reserved word"});
  expect_error(yaml({"unidyn: 1", "coordinates: [x, t]"}), 2, 18, {"'t' is a reserved word"});
  expect_error(yaml({"unidyn: 1", "coordinates: [pi]"}), 2, 15, {"'pi' is a reserved word"});
  expect_error(base() + "  E1: {mass: m, position: [0, 0, 0]}\n", 6, 3,
               {"'E1' is a reserved word"});
  expect_error(base() + "constraints: [{name: sin, position: x}]\n", 6, 22,
               {"'sin' is a reserved word"});
  expect_error(base() + "constraints: [{name: lambda, position: x}]\n", 6, 22,
               {"'lambda' is a reserved word"});

  expect_error(yaml({"unidyn: 1", "coordinates: [x, 2x]"}), 2, 18,
               {"'2x' is not a valid name", "letters, digits, _"});
  expect_error(yaml({"unidyn: 1", "coordinates: [x, a-b]"}), 2, 18, {"'a-b' is not a valid name"});
  expect_error(yaml({"unidyn: 1", "parameters: {\"a b\": 1}", "coordinates: [x]"}), 2, 14,
               {"'a b' is not a valid name"});
  expect_error(yaml({"unidyn: 1", "parameters: {\"\": 1}", "coordinates: [x]"}), 2, 14,
               {"not a valid name"});
  expect_error(base() + "  P.Q: {mass: m, position: [0, 0, 0]}\n", 6, 3,
               {"'P.Q' is not a valid name"});
  expect_error(base() + "constraints: [{name: a-b, position: x}]\n", 6, 22,
               {"'a-b' is not a valid name"});
  expect_error(base() + "constraints: [{name: 2c, position: x}]\n", 6, 22,
               {"'2c' is not a valid name"});
  expect_error(yaml({"unidyn: 1", "coordinates: [x, [y]]"}), 2, 18, {"single value"});
}

// Constraints: a position constraint is Ψ(q, t); a velocity constraint is linear in the rates.
TEST(ModelFileErrors, Constraints) {
  const auto constraint = [](const std::string& line) {
    return base() + "constraints:\n" + line + "\n";
  };
  const std::string rate = "  - {name: c, position: x*der(y)}";
  expect_error(constraint(rate), 7, column_of(rate, "x*"), {"position constraint", "der(y)"});
  const std::string acceleration = "  - {name: c, position: \"dot(P.acceleration, E1)\"}";
  expect_error(constraint(acceleration), 7, column_of(acceleration, "\"dot"), {"acceleration"});
  for (const std::string velocity :
       {"der(x)^2", "der(x)*der(y)", "sin(der(x))", "1/der(y)", "abs(der(x))", "x*der(y)^3",
        "sqrt(der(x)^2 + der(y)^2)", "\"dot(P.acceleration, E1)\""}) {
    const std::string line = "  - {name: c, velocity: " + velocity + "}";
    expect_error(constraint(line), 7, column_of(line, velocity), {"velocity constraint"});
  }
  // linear in the rates with coefficients in q and t is fine
  EXPECT_NO_THROW(
      parse_model(constraint("  - {velocity: \"sin(x)*der(x) + t*y*der(y) + x\"}"), "test.yaml"));
  const std::string both = "  - {name: c, position: x, velocity: der(y)}";
  expect_error(constraint(both), 7, 5, {"exactly one of position:", "velocity:"});
  expect_error(constraint("  - {name: c}"), 7, 5, {"exactly one of position:"});
  expect_error(constraint("  - x^2 + y^2"), 7, 5, {"mapping"});
  expect_error(base() + "constraints: {c: x}\n", 6, 14, {"list"});
  for (const std::string flag : {"yes", "maybe", "1"}) {
    const std::string line = "  - {name: c, position: y, unilateral: " + flag + "}";
    expect_error(constraint(line), 7, column_of(line, flag + "}"), {"unilateral", "true or false"});
  }
  const std::string on = "  - {name: c, position: y, friction: {on: Q, dynamic: 0.1}}";
  expect_error(constraint(on), 7, column_of(on, "Q"), {"on: must name a particle"});
  const std::string no_dynamic = "  - {name: c, position: y, friction: {on: P}}";
  expect_error(constraint(no_dynamic), 7, column_of(no_dynamic, "{on"), {"dynamic:"});
}

// Friction on a curve: with: names other position constraints, each in one contact; slip_speed
// belongs to the dynamic coefficient alone.
TEST(ModelFileErrors, FrictionOnACurve) {
  const auto constraints = [](const std::string& rough, const std::string& other) {
    return base() + "constraints:\n" + rough + "\n" + other + "\n";
  };
  const std::string plane = "  - {name: d, position: x - 1}";
  const auto rough = [](const std::string& with) {
    return "  - {name: c, position: y, friction: {on: P, dynamic: 0.1, with: " + with + "}}";
  };
  expect_error(constraints(rough("[e]"), plane), 7, column_of(rough("[e]"), "e]"),
               {"with: names no constraint 'e'"});
  expect_error(constraints(rough("[c]"), plane), 7, column_of(rough("[c]"), "c]"),
               {"the rough constraint itself"});
  expect_error(constraints(rough("d"), plane), 7, column_of(rough("d"), "d}"), {"a list"});
  const std::string rate = "  - {name: d, velocity: der(x)}";
  expect_error(constraints(rough("[d]"), rate), 7, column_of(rough("[d]"), "d]"),
               {"not a position constraint"});
  const std::string rough_too = "  - {name: d, position: x - 1, friction: {on: P, dynamic: 0.1}}";
  expect_error(constraints(rough("[d]"), rough_too), 7, column_of(rough("[d]"), "d]"),
               {"friction of its own"});
  const std::string twice =
      "  - {name: e, position: x, friction: {on: P, dynamic: 0.1, with: [d]}}";
  expect_error(base() + "constraints:\n" + rough("[d]") + "\n" + plane + "\n" + twice + "\n", 9,
               column_of(twice, "d]"), {"already in the with:"});
  EXPECT_NO_THROW(parse_model(constraints(rough("[d]"), plane), "test.yaml"));
  // slip_speed: in dynamic:, not in static:
  const std::string slip =
      "  - {name: c, position: y, friction: {on: P, dynamic: 0.1 + 0.2*slip_speed}}";
  const System s = parse_model(base() + "constraints:\n" + slip + "\n", "test.yaml");
  EXPECT_NEAR(value_at(s, s.constraints[0].friction->static_coefficient), 0.1, 1e-15)
      << "μ_s defaults to μ_d at no slip";
  const std::string slip_static =
      "  - {name: c, position: y, friction: {on: P, dynamic: 0.1, static: 0.2*slip_speed}}";
  expect_error(base() + "constraints:\n" + slip_static + "\n", 7, column_of(slip_static, "0.2*"),
               {"slip_speed belongs in dynamic:"});
}

// initial: only coordinates and their rates, with values in the parameters only.
TEST(ModelFileErrors, InitialValues) {
  expect_error(base() + "initial: {z: 1}\n", 6, 11, {"'z' is not a coordinate"});
  expect_error(base() + "initial: {der(z): 1}\n", 6, 11, {"'z' is not a coordinate"});
  expect_error(base() + "initial: {m: 1}\n", 6, 11, {"'m' is not a coordinate"});
  expect_error(base() + "initial: {P: 1}\n", 6, 11, {"'P' is not a coordinate"});
  for (const std::string value : {"y", "2*der(y)", "t", "\"dot(P.position, E1)\"",
                                  "\"dot(P.acceleration, E1)\"", "sqrt(-1)"}) {
    const std::string line = "initial: {x: " + value + "}";
    expect_error(base() + line + "\n", 6, 14, {"numbers and parameters only"});
  }
  expect_error(base() + "initial: [x, 1]\n", 6, 10, {"initial must be a mapping"});
}

// simulate: positive times, a known method, sensible tolerances.
TEST(ModelFileErrors, SimulateSettings) {
  const auto simulate = [](const std::string& settings) {
    return base() + "simulate: {" + settings + "}\n";
  };
  expect_error(simulate("t_end: -1"), 6, 19, {"t_end must be positive"});
  expect_error(simulate("t_end: 0"), 6, 19, {"t_end must be positive"});
  expect_error(simulate("output_step: 0"), 6, 25, {"output_step must be positive"});
  expect_error(simulate("output_step: -0.01"), 6, 25, {"output_step must be positive"});
  expect_error(simulate("method: euler"), 6, 20,
               {"method must be dopri5, dop853, rk4, cvode, rattle, rattle4, rattle6 or alf"});
  expect_error(simulate("t_end: ten"), 6, 19, {"t_end must be a number"});
  expect_error(simulate("t_end: 1e400"), 6, 19, {"t_end must be a number"});
  expect_error(simulate("t_end: .nan"), 6, 19, {"t_end must be a number"});
  expect_error(simulate("rtol: -1e-8"), 6, 18, {"rtol must be positive"});
  expect_error(simulate("rtol: 0"), 6, 18, {"rtol must be positive"});
  expect_error(simulate("atol: 0"), 6, 18, {"atol must be positive"});
  expect_error(simulate("step: -0.1"), 6, 18, {"step must not be negative"});
  expect_error(base() + "simulate: 10\n", 6, 11, {"simulate must be a mapping"});
  // a parameter is an expression (2*L): a unit after the number is not one
  expect_error(yaml({"unidyn: 1", "parameters: {m: 1 kg}", "coordinates: [x]"}), 2, 19,
               {"expected an operator such as '*' or '+' before 'kg'"});
}

// Forces: points that exist, two different particles, one law per spring, three components.
TEST(ModelFileErrors, Forces) {
  const auto force = [](const std::string& line) { return base() + "forces:\n" + line + "\n"; };
  const std::string at = "  - force: {at: R, value: [1, 0, 0]}";
  expect_error(force(at), 7, column_of(at, "R"), {"at: must name a particle"});
  const std::string fixed = "  - force: {at: [0, 0, 0], value: [1, 0, 0]}";
  expect_error(force(fixed), 7, column_of(fixed, "[0"), {"at"});
  const std::string one = "  - gravitation: {between: [P], G: 1}";
  expect_error(force(one), 7, column_of(one, "[P]"), {"two particles"});
  const std::string twice = "  - gravitation: {between: [P, P], G: 1}";
  expect_error(force(twice), 7, column_of(twice, "[P"), {"two different particles"});
  const std::string three = "  - gravitation: {between: [P, P, P], G: 1}";
  expect_error(force(three), 7, column_of(three, "[P"), {"two particles"});
  const std::string unknown = "  - gravitation: {between: [P, S], G: 1}";
  expect_error(force(unknown), 7, column_of(unknown, "S]"), {"not a particle"});
  const std::string both = "  - spring: {from: P, to: [0, 0, 0], stiffness: k, energy: k*s^4}";
  expect_error(force(both), 7, column_of(both, "{from"), {"either stiffness:", "or energy:"});
  const std::string neither = "  - spring: {from: P, to: [0, 0, 0]}";
  expect_error(force(neither), 7, column_of(neither, "{from"), {"either stiffness:"});
  const std::string stretch = "  - spring: {from: P, to: [0, 0, 0], stiffness: k*s}";
  expect_error(force(stretch), 7, column_of(stretch, "s}"), {"unknown name 's'"});
  const std::string no_end = "  - spring: {from: P, stiffness: k}";
  expect_error(force(no_end), 7, column_of(no_end, "{from"), {"from: and to:"});
  const std::string same = "  - spring: {from: P, to: P, stiffness: k}";
  expect_error(force(same), 7, column_of(same, "{from"), {"two different points"});
  const std::string same_damper = "  - damper: {from: [0, 0, 1], to: [0, 0, 1], coefficient: 1}";
  expect_error(force(same_damper), 7, column_of(same_damper, "{from"), {"two different points"});
  const std::string damper = "  - damper: {from: P, to: [0, 0, 0]}";
  expect_error(force(damper), 7, column_of(damper, "{from"), {"coefficient:"});
  const std::string short_gravity = "  - gravity: [0, -9.81]";
  expect_error(force(short_gravity), 7, column_of(short_gravity, "["), {"three components"});
  const std::string scalar_gravity = "  - gravity: -9.81";
  expect_error(force(scalar_gravity), 7, column_of(scalar_gravity, "-9"), {"expected a vector"});
  expect_error(force("  - magnet: 1"), 7, 5, {"unknown force 'magnet'", "gravity, spring"});
  expect_error(force("  - {gravity: -g*E3, potential: x}"), 7, 5, {"each force is one of"});
  expect_error(base() + "forces: {gravity: -g*E3}\n", 6, 9, {"forces must be a list"});
  expect_error(base() + "  Q: {mass: m, position: [x, y]}\n", 6, 26, {"three components"});
  expect_error(base() + "  Q: {mass: m, position: [x, y, 0, 1]}\n", 6, 26, {"three components"});
  // a potential is U(q, t); forces and positions may not depend on accelerations
  const std::string potential = "  - potential: der(x)^2";
  expect_error(force(potential), 7, column_of(potential, "der"), {"der(x)"});
  const std::string energy = "  - spring: {from: P, to: [0, 0, 0], energy: der(y)*s}";
  expect_error(force(energy), 7, column_of(energy, "der"), {"der(y)"});
  const std::string accelerated = "  - force: {at: P, value: \"-m*P.acceleration\"}";
  expect_error(force(accelerated), 7, column_of(accelerated, "\"-m"), {"acceleration"});
  expect_error(base() + "  Q: {mass: m, position: \"[der(x), 0, 0]\"}\n", 6, 26, {"der(x)"});
}

// Nothing in a file is executed: shell or script text is only ever a parse error.
TEST(ModelFileErrors, NothingIsExecuted) {
  const std::string sentinel = testing::TempDir() + "unidyn_executed_" + std::to_string(getpid());
  std::remove(sentinel.c_str());
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"\"$(touch " + sentinel + ")\"", "'$'"},
      {"\"`touch " + sentinel + "`\"", "'`'"},
      {"\"__import__('os').system('touch " + sentinel + "')\"", "'''"},
      {"\"system(touch)\"", "unknown name"},
      {"\"m; touch " + sentinel + "\"", "';'"},
  };
  for (const auto& [value, expected] : cases) {
    const std::string line = "  Q: {mass: " + value + ", position: [0, 0, 0]}";
    const std::string text = base() + line + "\n";
    try {
      parse_model(text, "test.yaml");
      ADD_FAILURE() << "no error for " << value;
    } catch (const ModelError& e) {
      EXPECT_EQ(e.where().line, 6) << e.what();
      EXPECT_GT(e.where().column, 12) << e.what();
      EXPECT_NE(e.message().find(expected), std::string::npos) << e.what();
    }
  }
  EXPECT_FALSE(std::filesystem::exists(sentinel));
  // the error of "$(rm -rf /)" is at the '$'
  const std::string rm = "  Q: {mass: \"$(rm -rf /)\", position: [0, 0, 0]}";
  expect_error(base() + rm + "\n", 6, column_of(rm, "$"), {"unexpected character '$'"});
}

// Huge or deeply nested input is refused with a ModelError, never a crash or a hang.
TEST(ModelFileErrors, HostileInput) {
  const std::string before = base() + "  Q: {mass: \"";
  const std::string after = "\", position: [0, 0, 0]}\n";
  // a 1 MB expression, valid but for its length
  std::string sum = "m";
  while (sum.size() < 1'000'000) sum += " + m";
  expect_refused(before + sum + after, "too long");
  // a 1 MB name
  expect_refused(before + std::string(1'000'000, 'a') + after, "too long");
  // nesting of parentheses and calls
  expect_refused(before + std::string(20'000, '(') + "m" + std::string(20'000, ')') + after,
                 "nested too deeply");
  std::string calls = "m";
  for (int i = 0; i < 5000; ++i) calls = "sin(" + calls + ")";
  expect_refused(before + calls + after, "nested too deeply");
  // nesting of YAML sequences and mappings
  expect_refused("unidyn: 1\nparameters: " + std::string(100'000, '[') + std::string(100'000, ']'),
                 "YAML");
  std::string maps;
  for (int i = 0; i < 50'000; ++i) maps += "{a: ";
  expect_refused("unidyn: 1\nparameters: " + maps + "1" + std::string(50'000, '}') + "\n", "YAML");
  // exponential aliases (a "billion laughs") where a number is expected
  std::string laughs = "unidyn: 1\nreference: [&a0 [lol]";
  for (int i = 1; i < 40; ++i) {
    laughs += ", &a" + std::to_string(i) + " [*a" + std::to_string(i - 1) + ", *a" +
              std::to_string(i - 1) + "]";
  }
  laughs += "]\nparameters: {m: *a39}\ncoordinates: [x]\n";
  expect_refused(laughs, "must be a single value");
  // a number too large for GiNaC to be asked to compute
  expect_refused(before + "10^100000" + after, "");
  // binary garbage
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage += static_cast<char>((i * 7919) % 256);
  try {
    parse_model(garbage, "garbage.yaml");
    ADD_FAILURE() << "garbage accepted";
  } catch (const ModelError&) {
  }
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// Joints and loads on bodies: what they name must exist, axes are numbers, points on a body are
// constant on its basis, a moving point of no mass carries no force.
TEST(ModelFileErrors, BodyJointsAndLoads) {
  const std::string body =
      yaml({"unidyn: 1", "parameters: {m: 1, K: 2}", "coordinates: [x, a, b, c]", "bodies:",
            "  B: {mass: m, inertia: [1, 2, 3], rotation: {euler: 3-1-3, "
            "angles: [a, b, c]}, center: [x, 0, 0]}"});
  const auto constraint = [&](const std::string& line) {
    return body + "constraints:\n" + line + "\n";
  };
  const auto force = [&](const std::string& line) { return body + "forces:\n" + line + "\n"; };
  const std::string unknown = "  - {name: j, pin: {body: C, axis: [0, 0, 1]}}";
  expect_error(constraint(unknown), 7, column_of(unknown, "C,"), {"body: must name a body"});
  const std::string symbolic = "  - {name: j, pin: {body: B, axis: [0, 0, m]}}";
  expect_error(constraint(symbolic), 7, column_of(symbolic, "[0"), {"vector of numbers"});
  const std::string zero = "  - {name: j, pin: {body: B, axis: [0, 0, 0]}}";
  expect_error(constraint(zero), 7, column_of(zero, "[0"), {"cannot be zero"});
  const std::string twice = "  - {name: j, ball: {body: B, to: B}}";
  expect_error(constraint(twice), 7, column_of(twice, "{body"), {"two different bodies"});
  const std::string moving = "  - {name: j, ball: {body: B, point: [x, 0, 0]}}";
  expect_error(constraint(moving), 7, column_of(moving, "[x"), {"constant on its basis"});
  const std::string no_axis = "  - {name: j, pin: {body: B}}";
  expect_error(constraint(no_axis), 7, column_of(no_axis, "{body"), {"needs axis:"});
  const std::string both = "  - {name: j, ball: {body: B}, position: x}";
  expect_error(constraint(both), 7, 5, {"exactly one of"});
  const std::string clash = "  - {name: j, ball: {body: B}}\n  - {name: j_1, position: x}";
  expect_error(constraint(clash), 8, column_of("  - {name: j_1, position: x}", "j_1"),
               {"already defined"});
  const std::string free_point = "  - spring: {from: [x, 0, 1], to: [0, 0, 0], stiffness: K}";
  expect_error(force(free_point), 7, column_of(free_point, "[x"), {"neither a particle nor"});
  const std::string no_body = "  - spring: {from: {on: C}, to: [0, 0, 0], stiffness: K}";
  expect_error(force(no_body), 7, column_of(no_body, "C}"), {"on: must name a body"});
  const std::string not_angle = "  - torsion_spring: {on: B, angle: x, stiffness: K}";
  expect_error(force(not_angle), 7, column_of(not_angle, "x,"),
               {"the angle of a joint", "Euler angles"});
  const std::string no_normal = "  - {name: r, rolling: {body: B, at: B.center}}";
  expect_error(constraint(no_normal), 7, column_of(no_normal, "{body"), {"normal:"});
  // a curved surface that is not a cylinder about E1, E2 or E3, one that moves, one with no normal
  const std::string bent = "  - {name: r, rolling: {body: B, at: B.center, normal: [1, x, x]}}";
  expect_error(constraint(bent), 7, column_of(bent, "[1"), {"perpendicular to one of E1, E2, E3"});
  const std::string moving_surface =
      "  - {name: r, rolling: {body: B, at: B.center, normal: [0, 1, t]}}";
  expect_error(constraint(moving_surface), 7, column_of(moving_surface, "[0, 1"),
               {"cannot depend on t"});
  const std::string no_direction =
      "  - {name: r, rolling: {body: B, at: B.center, normal: [0, 0, 0]}}";
  expect_error(constraint(no_direction), 7, column_of(no_direction, "[0"), {"cannot be zero"});
  const std::string gradient = "  - gravity_gradient: {on: B}";
  expect_error(force(gradient), 7, column_of(gradient, "{on"), {"GM:"});
}

}  // namespace
}  // namespace unidyn
