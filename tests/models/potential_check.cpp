// Whether a force element has a potential (equations/potential_check.hpp): Problem 2.1's four
// forces, Ziegler's constant moment and the torsion spring (Ex. 8.7), forces that depend on the
// rates or on time.
#include "unidyn/equations/potential_check.hpp"

#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/io/potential_text.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// The value of an expression of the coordinates x1, x2, x3 and the parameter L0 = 0.5.
double at(const System& system, const Expr& e, double x1, double x2, double x3) {
  GiNaC::exmap values;
  const double x[3] = {x1, x2, x3};
  for (std::size_t i = 0; i < 3; ++i) values[system.coordinates()[i].value] = x[i];
  values[system.parameters[*system.find_parameter("L0")].symbol] = 0.5;
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
}

// Problem 2.1: only x2 E1 + x1 E2 is conservative, with U = −x1 x2; x1 E1 + x3 E2 has
// ∂Φ_x2/∂x3 − ∂Φ_x3/∂x2 = 1, x1 x2 E1 has ∂Φ_x1/∂x2 − ∂Φ_x2/∂x1 = x1, and L0 e_θ =
// L0 (−x2, x1, 0)/r has −L0/r there.
TEST(PotentialCheck, FourForcesOfProblem21) {
  const System system = load_model(test::model_path("four-forces"));
  ASSERT_EQ(system.forces.size(), 4u);
  const PotentialCheck first = potential_check(system, 0), second = potential_check(system, 1),
                       third = potential_check(system, 2), fourth = potential_check(system, 3);
  EXPECT_FALSE(first.conservative);
  EXPECT_EQ(first.witness, "dPhi_x2/dx3 - dPhi_x3/dx2");
  EXPECT_TRUE((first.value - 1).is_zero()) << first.value;
  ASSERT_TRUE(second.conservative) << second.witness;
  ASSERT_TRUE(second.potential.has_value());
  const Expr x1 = system.coordinates()[0].value, x2 = system.coordinates()[1].value;
  EXPECT_TRUE((*second.potential + x1 * x2).expand().is_zero()) << *second.potential;
  EXPECT_FALSE(third.conservative);
  EXPECT_EQ(third.witness, "dPhi_x1/dx2 - dPhi_x2/dx1");
  EXPECT_TRUE((third.value - x1).is_zero()) << third.value;
  EXPECT_FALSE(fourth.conservative);
  EXPECT_EQ(fourth.witness, "dPhi_x1/dx2 - dPhi_x2/dx1");
  EXPECT_NEAR(at(system, fourth.value, 0.6, -0.8, 0.3), -0.5 / 1.0, 1e-14);
  // as `unidyn derive` says it
  const std::vector<std::string> lines = potential_lines(system);
  ASSERT_EQ(lines.size(), 4u);
  // (and, read from its file, the element is conservative with that U everywhere)
  EXPECT_EQ(lines[1], "force (line 10) is conservative: U = " + to_text(*second.potential) +
                          " (in the energy and in -dU/dq)");
  EXPECT_TRUE(system.forces[1].conservative && system.forces[1].potential_proven);
  EXPECT_FALSE(system.forces[0].conservative || system.forces[2].conservative ||
               system.forces[3].conservative);
  EXPECT_TRUE(lines[0].starts_with("force (line 9) is not conservative: dPhi_x2/dx3")) << lines[0];
}

// Ex. 8.7: Ziegler's constant moment M E3 (3-1-3 angles) has Φ = (M, 0, M cos θ), whose
// ∂Φ_θ/∂φ − ∂Φ_φ/∂θ = M sin θ ≠ 0; the torsion spring's −K ψ g¹ has Φ = (−K ψ, 0, 0) and
// U = ½ K ψ².
TEST(PotentialCheck, ZieglersMomentAndTheTorsionSpring) {
  const System system = load_model(test::model_path("ziegler-moment"));
  const PotentialCheck ziegler = potential_check(system, 0), spring = potential_check(system, 1);
  const Expr M = system.parameters[0].symbol, K = system.parameters[1].symbol;
  const Expr psi = system.coordinates()[0].value, theta = system.coordinates()[1].value;
  EXPECT_FALSE(ziegler.conservative);
  EXPECT_EQ(ziegler.witness, "dPhi_theta/dphi - dPhi_phi/dtheta");
  EXPECT_TRUE(simplify(ziegler.value - M * GiNaC::sin(theta)).is_zero()) << ziegler.value;
  ASSERT_TRUE(spring.conservative) << spring.witness;
  ASSERT_TRUE(spring.potential.has_value());
  EXPECT_TRUE((*spring.potential - K * psi * psi / 2).expand().is_zero()) << *spring.potential;
}

// A damper's force depends on the rates and a drive on time: no potential U(q).
TEST(PotentialCheck, RatesAndTimeHaveNone) {
  const System system = load_model(test::model_path("damped-forced-chain"));
  EXPECT_EQ(potential_check(system, 2).witness, "depends on der(x1)");  // the first damper
  EXPECT_EQ(potential_check(system, 4).witness, "depends on t");        // P0 cos(w t)
  EXPECT_TRUE(potential_check(system, 0).conservative);                 // a spring
}

}  // namespace
}  // namespace unidyn
