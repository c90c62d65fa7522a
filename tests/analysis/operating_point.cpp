// The operating point (analysis/operating_point.hpp): the values given kept, the rest completed
// from the constraints, bad values refused with the reason.
#include "unidyn/analysis/operating_point.hpp"

#include <gtest/gtest.h>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

struct Model {
  System system;
  CompiledSystem compiled;
  explicit Model(const std::string& name)
      : system(load_model(test::model_path(name))), compiled(system, lagrange_equations(system)) {}
  OperatingPoint at(const std::vector<std::string>& texts) const {
    return operating_point(system, compiled, parse_given_values(system, texts),
                           initial_state(system, {}).parameters);
  }
  double q(const OperatingPoint& p, const std::string& name) const {
    return p.q[static_cast<Eigen::Index>(*system.find_coordinate(name))];
  }
  double qdot(const OperatingPoint& p, const std::string& name) const {
    return p.qdot[static_cast<Eigen::Index>(*system.find_coordinate(name))];
  }
};

// Values may be expressions in the parameters; what is not given starts at 0; the bicycle's pitch
// follows from its front wheel touching the ground, its other rates from rolling.
TEST(OperatingPoint, GivenKeptTheRestCompleted) {
  const Model hoop("rotating-hoop");
  const OperatingPoint p = hoop.at({"phi=acos(-g/(R0*Omega^2))"});
  EXPECT_NEAR(std::cos(hoop.q(p, "phi")), -9.81 / (0.5 * 6.264183905346329 * 6.264183905346329),
              1e-15);
  EXPECT_EQ(hoop.qdot(p, "phi"), 0.0);
  EXPECT_NEAR(p.qddot[0], 0.0, 1e-12);  // an equilibrium: the forces balance

  const Model bike("bicycle");
  const OperatingPoint b = bike.at({"der(thR)=v/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"});
  EXPECT_DOUBLE_EQ(bike.qdot(b, "thR"), 4.6 / 0.3);
  EXPECT_NEAR(bike.qdot(b, "x"), 4.6, 1e-12);  // rolling: the rear contact at rest
  EXPECT_EQ(bike.q(b, "phi"), 0.0);
  EXPECT_FALSE(b.computed.empty());
  for (const std::string& line : b.computed) {
    EXPECT_TRUE(line.starts_with("theta") || line.starts_with("der(")) << line;
  }
}

TEST(OperatingPoint, BadValuesRefused) {
  const Model pendulum("double-pendulum");
  const System& s = pendulum.system;
  EXPECT_THROW(parse_given_values(s, {"theta1"}), std::invalid_argument);         // no value
  EXPECT_THROW(parse_given_values(s, {"g=1"}), std::invalid_argument);            // a parameter
  EXPECT_THROW(parse_given_values(s, {"theta1=theta2"}), std::invalid_argument);  // a coordinate
  EXPECT_THROW(parse_given_values(s, {"theta1=t"}), std::invalid_argument);       // time
  EXPECT_THROW(parse_given_values(s, {"theta1=1", "theta1=2"}), std::invalid_argument);
  EXPECT_THROW(parse_given_values(s, {"theta1=sqrt("}), std::invalid_argument);  // a syntax error
  EXPECT_THROW(pendulum.at({"theta1=sqrt(-g)"}), std::invalid_argument);         // not real
  // the top at the gimbal lock of its 3-1-3 angles: M is singular there
  const Model top("heavy-top");
  try {
    top.at({"theta=0"});
    ADD_FAILURE() << "gimbal lock accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("gimbal lock"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace unidyn
