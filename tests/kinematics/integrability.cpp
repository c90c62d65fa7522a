// Integrability of velocity constraints: Jacobi's test (1.19)/(1.21) and Frobenius' (8.18), on the
// book's examples (1.14)–(1.16), Exercises 1.10 and 1.11, Problem 2.8, §5.2's extra constraint,
// the rolling disk (10.27)–(10.28), Ex. 8.9, and the tippe top, Ex. 8.4.
#include "unidyn/kinematics/integrability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <utility>

#include "unidyn/io/model_file.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {
namespace {

// A particle at [x, y, z] with the given constraints.
System particle_with(const std::string& constraints) {
  return parse_model(
      "unidyn: 1\ncoordinates: [x, y, z]\nparticles:\n  P: {mass: 1, position: [x, y, "
      "z]}\nconstraints:\n" +
          constraints,
      "test.yaml");
}

// (1.16) ẏ − z ẋ = 0: I_c = f · rot f = −1 (the book's worked check).
TEST(Integrability, SimplestNonIntegrableConstraint) {
  const System s = particle_with("  - {name: c, velocity: der(y) - z*der(x)}\n");
  const Integrability result = constraint_integrability(s, 0);
  EXPECT_FALSE(result.integrable);
  EXPECT_EQ(result.witness, "I(x, y, z)");
  EXPECT_TRUE((result.value + 1).is_zero()) << result.value;
}

// §1.8 (1.17), after Pars: any y = f(x), z = f′(x) satisfies (1.16) (ẏ = f′ ẋ = z ẋ); the family
// f = (3Δy − Δx Σz) s² − (2Δy − Δx Σz) s³ + c (x − x_A)²(x_B − x)² + d sin²(π s)
//     + z_A (x − x_A)(x_B − x)/Δx + y_A,   s = (x − x_A)/Δx,
// joins A = (x_A, y_A, z_A) to B for every c and d: f and f′ (by unidyn's derivative) take the
// end values. ⚠ As printed, with s in place of s³, the slopes miss them.
TEST(Integrability, ParsFamilyOfPathsJoinsAAndB) {
  const GiNaC::realsymbol x("x");
  const double xA = 0.5, yA = -1.0, zA = 0.3, xB = 2.0, yB = 0.7, zB = -1.1;
  const double dx = xB - xA, dy = yB - yA, sz = zA + zB;
  const Expr s = (x - xA) / dx;
  const auto family = [&](double c, double d, int power) {
    return (3 * dy - dx * sz) * GiNaC::pow(s, 2) - (2 * dy - dx * sz) * GiNaC::pow(s, power) +
           c * GiNaC::pow(x - xA, 2) * GiNaC::pow(xB - x, 2) +
           d * GiNaC::pow(GiNaC::sin(GiNaC::Pi * s), 2) + zA * (x - xA) * (xB - x) / dx + yA;
  };
  const auto at = [&](const Expr& e, double where) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(x == where))).to_double();
  };
  for (const auto& [c, d] : {std::pair{0.0, 0.0}, std::pair{1.5, -0.7}, std::pair{-3.0, 2.0}}) {
    const Expr f = family(c, d, 3), slope = derivative(f, x);
    EXPECT_NEAR(at(f, xA), yA, 1e-14);
    EXPECT_NEAR(at(f, xB), yB, 1e-14);
    EXPECT_NEAR(at(slope, xA), zA, 1e-14);
    EXPECT_NEAR(at(slope, xB), zB, 1e-13);
    const Expr printed = derivative(family(c, d, 1), x);
    EXPECT_GT(std::abs(at(printed, xA) - zA) + std::abs(at(printed, xB) - zB), 0.1);
  }
}

// Exercise 1.10: only x ẋ + y ẏ + e(t) = 0 is integrable (a cylinder whose radius changes in time).
TEST(Integrability, Exercise110) {
  const System s = particle_with(
      "  - {name: cylinder, velocity: x*der(x) + y*der(y) + sin(t)}\n"
      "  - {name: second, velocity: z*der(y) + der(x)}\n"
      "  - {name: third, velocity: cos(z)*der(y) - sin(z)*der(x)}\n");
  EXPECT_TRUE(constraint_integrability(s, 0).integrable);
  EXPECT_FALSE(constraint_integrability(s, 1).integrable);
  EXPECT_FALSE(constraint_integrability(s, 2).integrable);
  // a position constraint is integrable by definition
  const System p = particle_with("  - {name: sphere, position: x^2 + y^2 + z^2 - 1}\n");
  EXPECT_TRUE(constraint_integrability(p, 0).integrable);
}

// Exercise 1.11 and (1.23): z ẋ + ẏ + e(t) = 0 is not integrable, but with ż = 0 the pair is (the
// particle moves on a straight line); any two independent scleronomic constraints on one particle
// are (1.23), though neither alone is. With a fourth coordinate w, ẏ − z ẋ = 0 and ẇ = 0 are not:
// the bracket of ∂x + z ∂y and ∂z is ∂y.
TEST(Integrability, SetsOfConstraints) {
  const System s = particle_with(
      "  - {name: first, velocity: z*der(x) + der(y) + cos(t)}\n"
      "  - {name: level, velocity: der(z)}\n");
  EXPECT_FALSE(constraint_integrability(s, 0).integrable);
  EXPECT_TRUE(constraint_integrability(s, 1).integrable);
  EXPECT_TRUE(set_integrability(s, {0, 1}).integrable);
  const System t = particle_with(
      "  - {name: first, velocity: der(y) - z*der(x)}\n"
      "  - {name: second, velocity: der(z) - x*der(y)}\n");
  EXPECT_FALSE(constraint_integrability(t, 0).integrable);
  EXPECT_FALSE(constraint_integrability(t, 1).integrable);
  EXPECT_TRUE(set_integrability(t, {0, 1}).integrable);
  const System w = parse_model(
      "unidyn: 1\ncoordinates: [x, y, z, w]\nparticles:\n  P: {mass: 1, position: [x, y, z]}\n"
      "  Q: {mass: 1, position: [w, 1, 0]}\nconstraints:\n"
      "  - {name: first, velocity: der(y) - z*der(x)}\n  - {name: still, velocity: der(w)}\n",
      "test.yaml");
  const Integrability pair = set_integrability(w, {0, 1});
  EXPECT_FALSE(pair.integrable);
  EXPECT_TRUE(pair.witness.starts_with("a^T S b of first")) << pair.witness;
  // three independent constraints prescribe the motion: always integrable (§1.7)
  const System u = particle_with(
      "  - {name: first, velocity: der(y) - z*der(x)}\n"
      "  - {name: second, velocity: der(z) - x*der(y)}\n"
      "  - {name: third, velocity: der(x) + y*der(z)}\n");
  EXPECT_TRUE(set_integrability(u, {0, 1, 2}).integrable);
}

// (10.27)–(10.28): the rolling disk's π3 = ẋ3 − R θ̇ cos θ is integrable (Ψ = x3 − R sin θ), π1 is
// not, and neither is the set π1, π2, π3 (Ex. 8.9).
TEST(Integrability, RollingDisk) {
  const std::string disk = R"yaml(unidyn: 1
parameters: {R: 0.5}
coordinates: [x1, x2, x3, psi, theta, phi]
bodies:
  disk:
    mass: 1
    inertia: [1, 1, 2]
    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}
    center: [x1, x2, x3]
constraints:
  - {name: pi1, velocity: "der(x1) + R*der(phi)*cos(psi) + R*der(psi)*cos(theta)*cos(psi) - R*der(theta)*sin(theta)*sin(psi)"}
  - {name: pi2, velocity: "der(x2) + R*der(phi)*sin(psi) + R*der(psi)*cos(theta)*sin(psi) + R*der(theta)*sin(theta)*cos(psi)"}
  - {name: pi3, velocity: "der(x3) - R*der(theta)*cos(theta)"}
)yaml";
  const System s = parse_model(disk, "disk.yaml");
  EXPECT_FALSE(constraint_integrability(s, 0).integrable);
  EXPECT_FALSE(constraint_integrability(s, 1).integrable);
  EXPECT_TRUE(constraint_integrability(s, 2).integrable);
  EXPECT_FALSE(set_integrability(s, {0, 1, 2}).integrable);
  EXPECT_TRUE(set_integrability(s, {2}).integrable);
  // Ex. 8.9(d): with ẋ2 = 0 and ψ̇ = 0 as well the five leave one direction of motion: integrable
  const System held = parse_model(
      disk + "  - {name: lane, velocity: der(x2)}\n  - {name: heading, velocity: der(psi)}\n",
      "held.yaml");
  EXPECT_FALSE(set_integrability(held, {0, 1, 2}).integrable);
  EXPECT_TRUE(set_integrability(held, {0, 1, 2, 3, 4}).integrable);
}

// Ex. 8.4, the tippe top (3-1-3 angles ψ, θ, φ; x_P − x̄ = −R E3 + l e3): (b) its slip
// velocities are v_s1 = ẋ1 − Ω2 (R − l cos θ) + Ω3 l sin θ cos ψ and
// v_s2 = ẋ2 + Ω1 (R − l cos θ) + Ω3 l sin θ sin ψ with Ω_i = ω · E_i (typed here from the 3-1-3
// set: ω = ψ̇ E3 + θ̇ e1′ + φ̇ e3); (e) of the rolling constraints v_P · E_i = 0 the first two are
// not integrable, the third (the height's rate) is.
TEST(Integrability, TippeTopExercise84) {
  const System s = parse_model(R"yaml(unidyn: 1
parameters: {R: 0.02, l: 0.006}
coordinates: [x1, x2, x3, psi, theta, phi]
bodies:
  top:
    mass: 1
    inertia: [1, 1, 0.8]
    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}
    center: [x1, x2, x3]
constraints:
  - {name: s1, velocity: "dot(top.velocity + cross(top.omega, l*top.e3 - R*E3), E1)"}
  - {name: s2, velocity: "dot(top.velocity + cross(top.omega, l*top.e3 - R*E3), E2)"}
  - {name: s3, velocity: "dot(top.velocity + cross(top.omega, l*top.e3 - R*E3), E3)"}
)yaml",
                               "tippe-top.yaml");
  const double R = 0.02, l = 0.006;
  const double x[6] = {0.1, -0.2, 0.014, 0.7, 1.9, -0.4};
  const double v[6] = {0.3, -0.5, 0.2, 4.0, -1.5, 60.0};
  GiNaC::exmap at;
  for (const auto& p : s.parameters) at[p.symbol] = p.value;
  const auto& q = s.coordinates();
  for (std::size_t i = 0; i < 6; ++i) {
    at[q[i].value] = x[i];
    at[q[i].rate] = v[i];
  }
  const auto value = [&](const Expr& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
  };
  const double psi = x[3], theta = x[4], dpsi = v[3], dtheta = v[4], dphi = v[5];
  const double W1 = dtheta * std::cos(psi) + dphi * std::sin(theta) * std::sin(psi);
  const double W2 = dtheta * std::sin(psi) - dphi * std::sin(theta) * std::cos(psi);
  const double W3 = dpsi + dphi * std::cos(theta);
  const double vs1 =
      v[0] - W2 * (R - l * std::cos(theta)) + W3 * l * std::sin(theta) * std::cos(psi);
  const double vs2 =
      v[1] + W1 * (R - l * std::cos(theta)) + W3 * l * std::sin(theta) * std::sin(psi);
  EXPECT_NEAR(value(s.constraints[0].expression), vs1, 1e-12);
  EXPECT_NEAR(value(s.constraints[1].expression), vs2, 1e-12);
  EXPECT_FALSE(constraint_integrability(s, 0).integrable);
  EXPECT_FALSE(constraint_integrability(s, 1).integrable);
  EXPECT_TRUE(constraint_integrability(s, 2).integrable);
}

// §1.8 (1.14): the hyperbola x y = c, z = 0 as velocity constraints y ẋ + x ẏ = 0, ż = 0:
// integrable (Ψ = x y − c); (1.15) x ẏ = 0 passes Jacobi's test too (I = 0), though no smooth Ψ
// holds for both of its branches y = const and x = 0 — the test is local.
TEST(Integrability, HyperbolaAndThePiecewiseConstraint) {
  const System hyperbola = particle_with(
      "  - {name: hyperbola, velocity: y*der(x) + x*der(y)}\n"
      "  - {name: plane, velocity: der(z)}\n");
  EXPECT_TRUE(constraint_integrability(hyperbola, 0).integrable);
  EXPECT_TRUE(set_integrability(hyperbola, {0, 1}).integrable);
  const System piecewise = particle_with("  - {name: xy, velocity: x*der(y)}\n");
  EXPECT_TRUE(constraint_integrability(piecewise, 0).integrable);
}

// Problem 2.8, (2.34): (x E3 + E2) · v = 0 is not integrable (f = (0, 1, x), f · rot f = −1);
// E2 · v + e(t) = 0 is (Ψ = y + ∫e dt).
TEST(Integrability, Problem28) {
  const System s = particle_with(
      "  - {name: first, velocity: x*der(z) + der(y)}\n"
      "  - {name: second, velocity: der(y) + cos(t)}\n");
  const Integrability first = constraint_integrability(s, 0);
  EXPECT_FALSE(first.integrable);
  EXPECT_TRUE((first.value * first.value - 1).is_zero()) << first.value;
  EXPECT_TRUE(constraint_integrability(s, 1).integrable);
}

// §5.2: ẋ1 x2 − ẋ2 = 0 on the spring chain is integrable (the factor 1/x2: x2 e^{−x1} is constant).
TEST(Integrability, SpringChainsExtraConstraint) {
  const System s = parse_model(
      "unidyn: 1\ncoordinates: [x1, x2]\nparticles:\n  P1: {mass: 1, position: [x1, 0, 0]}\n"
      "  P2: {mass: 1, position: [x2, 0, 0]}\nconstraints:\n"
      "  - {name: extra, velocity: x2*der(x1) - der(x2)}\n",
      "chain.yaml");
  EXPECT_TRUE(constraint_integrability(s, 0).integrable);
}

}  // namespace
}  // namespace unidyn
