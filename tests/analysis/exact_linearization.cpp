// M, C and K in closed form (analysis/exact_linearization.hpp) against the textbook's: the bead on
// the rotating hoop off-centre (Ex. 3.7), the double pendulum hanging (Ex. 4.1), the sleeping top's
// gyroscopic coupling (§9.7).
#include "unidyn/analysis/exact_linearization.hpp"

#include <gtest/gtest.h>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

struct Exact {
  System system;
  std::optional<ExactSecondOrder> matrices;
  Exact(const std::string& model, const std::vector<std::string>& at)
      : system(load_model(test::model_path(model))),
        matrices(exact_second_order(system, lagrange_equations(system),
                                    parse_given_values(system, at))) {}
  Expr parameter(const std::string& name) const {
    return system.parameters[*system.find_parameter(name)].symbol;
  }
};

// a − b is 0 as a rational function (after sin² + cos² = 1 where it matters).
::testing::AssertionResult equal(const Expr& a, const Expr& b) {
  if (GiNaC::normal(GiNaC::expand(a - b)).is_zero()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " is not " << b;
}

// At cos φ* = −g/(R0 Ω²): M = m R0², K = m R0² Ω² sin² φ* = m R0² Ω² − m g²/Ω².
TEST(ExactLinearization, RotatingHoopOffCentre) {
  const Exact hoop("rotating-hoop", {"phi=acos(-g/(R0*Omega^2))"});
  ASSERT_TRUE(hoop.matrices.has_value());
  const Expr m = hoop.parameter("m"), g = hoop.parameter("g"), R0 = hoop.parameter("R0"),
             W = hoop.parameter("Omega");
  EXPECT_TRUE(equal(hoop.matrices->M(0, 0), m * R0 * R0));
  EXPECT_TRUE(equal(hoop.matrices->C(0, 0), 0));
  EXPECT_TRUE(equal(hoop.matrices->K(0, 0), m * R0 * R0 * W * W - m * g * g / (W * W)));
}

TEST(ExactLinearization, DoublePendulumHanging) {
  const Exact p("double-pendulum", {"theta1=0", "theta2=0"});
  ASSERT_TRUE(p.matrices.has_value());
  const Expr m1 = p.parameter("m1"), m2 = p.parameter("m2"), l1 = p.parameter("l1"),
             l2 = p.parameter("l2"), g = p.parameter("g");
  EXPECT_TRUE(equal(p.matrices->M(0, 0), (m1 + m2) * l1 * l1));
  EXPECT_TRUE(equal(p.matrices->M(0, 1), m2 * l1 * l2));
  EXPECT_TRUE(equal(p.matrices->M(1, 1), m2 * l2 * l2));
  EXPECT_TRUE(equal(p.matrices->K(0, 0), (m1 + m2) * g * l1));
  EXPECT_TRUE(equal(p.matrices->K(0, 1), 0));
  EXPECT_TRUE(equal(p.matrices->K(1, 1), m2 * g * l2));
}

// Spinning upright at ω: A_O α'' + C ω β' − m g l α = 0, A_O β'' − C ω α' − m g l β = 0.
TEST(ExactLinearization, SleepingTopGyroscopicCoupling) {
  const Exact top("sleeping-top", {"der(gamma)=spin"});
  ASSERT_TRUE(top.matrices.has_value());
  const Expr m = top.parameter("m"), g = top.parameter("g"), l = top.parameter("l"),
             A = top.parameter("A"), C = top.parameter("C"), w = top.parameter("spin");
  EXPECT_TRUE(equal(top.matrices->M(0, 0), A + m * l * l));
  EXPECT_TRUE(equal(top.matrices->C(0, 1), C * w));
  EXPECT_TRUE(equal(top.matrices->C(1, 0), -C * w));
  EXPECT_TRUE(equal(top.matrices->K(0, 0), -m * g * l));
}

// With constraints, or a floating-point value, there is no closed form here.
TEST(ExactLinearization, NoneWithConstraints) {
  EXPECT_FALSE(Exact("spring-chain", {"x1=0", "x2=0"}).matrices.has_value());
  const System hoop = load_model(test::model_path("rotating-hoop"));
  EXPECT_FALSE(exact_second_order(hoop, lagrange_equations(hoop), {{"phi", GiNaC::numeric(0.5)}})
                   .has_value());
}

}  // namespace
}  // namespace unidyn
