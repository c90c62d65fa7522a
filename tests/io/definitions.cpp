// definitions: named scalar or vector sub-expressions, read after the bodies, each usable in the
// definitions after it and in every later section (forces, constraints, initial values, outputs).
#include <gtest/gtest.h>

#include <string>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// A disk's contact point, written once and used in two rolling rows and an output.
const std::string kDisk =
    "unidyn: 1\nparameters: {m: 1, R: 0.5}\ncoordinates: [x1, x2, x3, psi, theta, phi]\n"
    "bodies:\n  disk:\n    mass: m\n    inertia: {disk: {radius: R}}\n"
    "    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}\n    center: [x1, x2, x3]\n"
    "definitions:\n"
    "  arm: \"R*[cos(theta)*sin(psi), -cos(theta)*cos(psi), -sin(theta)]\"\n"
    "  contact_velocity: disk.velocity + cross(disk.omega, arm)\n"
    "  height: R*sin(theta)\n"
    "constraints:\n"
    "  - {name: ground, position: x3 - height}\n"
    "  - {name: pi1, velocity: \"dot(contact_velocity, E1)\"}\n"
    "  - {name: pi2, velocity: \"dot(contact_velocity, E2)\"}\n"
    "outputs:\n  slip: contact_velocity\n";

TEST(Definitions, UsedWhereverTheyAreKnown) {
  const System s = parse_model(kDisk, "definitions.yaml");
  ASSERT_EQ(s.definitions.size(), 3u);
  EXPECT_TRUE(s.definitions[0].is_vector);
  EXPECT_FALSE(s.definitions[2].is_vector);
  // the position constraint is x3 − R sin θ
  const Expr& x3 = s.coordinates()[2].value;
  const Expr& theta = s.coordinates()[4].value;
  const Expr R = s.parameters[1].symbol;
  EXPECT_TRUE((s.constraints[0].expression - (x3 - R * GiNaC::sin(theta))).expand().is_zero());
  // the velocity rows and the output are the contact velocity's components
  const VectorExpr& v = s.definitions[1].vector;
  EXPECT_TRUE((s.constraints[1].expression - v[0]).expand().is_zero());
  EXPECT_TRUE((s.constraints[2].expression - v[1]).expand().is_zero());
  ASSERT_EQ(s.outputs.size(), 3u);
  EXPECT_EQ(s.outputs[2].name, "slip.z");
  EXPECT_TRUE((s.outputs[2].expression - v[2]).expand().is_zero());
}

TEST(Definitions, NamesAndOrder) {
  const std::string base =
      "unidyn: 1\nparameters: {m: 1}\ncoordinates: [x]\nparticles:\n  P: {mass: m, position: "
      "[x, 0, 0]}\ndefinitions:\n";
  for (const auto& [body, expected] :
       {std::pair<std::string, std::string>{"  a: b + 1\n  b: 2\n", "unknown name 'b'"},
        {"  m: 2\n", "'m' is already defined"},
        {"  x2: x^2\n  x2: x\n", "'x2' is given twice"}}) {
    try {
      (void)parse_model(base + body, "definitions.yaml");
      ADD_FAILURE() << "no error for " << body;
    } catch (const ModelError& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace unidyn
