// The covariant form (4.30) (equations/covariant_form.hpp): the convective terms read off the
// mass matrix by Christoffel symbols (4.25), and off T's linear and rate-free parts when the
// constraints move, against the hand-derived terms of Ex. 4.1 and Ex. 3.7; and refused (no row)
// for a mass matrix that is not the system's.
#include "unidyn/equations/covariant_form.hpp"
#include "support/model_run.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
namespace {

Expr parameter(const System& s, const std::string& name) {
  for (const auto& p : s.parameters) {
    if (p.name == name) return p.symbol;
  }
  throw std::invalid_argument(name);
}

// Ex. 4.1 with absolute angles: M = [[(m1 + m2) l1², m2 l1 l2 cos(θ1 − θ2)], [·, m2 l2²]], so
// the convective terms are m2 l1 l2 sin(θ1 − θ2) θ̇2² and −m2 l1 l2 sin(θ1 − θ2) θ̇1².
TEST(CovariantForm, DoublePendulumChristoffelTerms) {
  const System s = load_model(test::model_path("double-pendulum"));
  const EquationsOfMotion eq = lagrange_equations(s);
  const auto& q = s.coordinates();
  const Expr m2 = parameter(s, "m2"), l1 = parameter(s, "l1"), l2 = parameter(s, "l2");
  const Expr k = m2 * l1 * l2 * GiNaC::sin(q[0].value - q[1].value);
  const std::vector<std::optional<Expr>> c = covariant_convective_terms(s, eq, eq.mass_matrix);
  ASSERT_TRUE(c[0] && c[1]);
  EXPECT_EQ(vanishes_identically(*c[0] - k * pow(q[1].rate, 2)), true) << *c[0];
  EXPECT_EQ(vanishes_identically(*c[1] + k * pow(q[0].rate, 2)), true) << *c[1];
  const std::optional<Expr> T = quadratic_kinetic_energy(s, eq, eq.mass_matrix);
  ASSERT_TRUE(T);
  EXPECT_EQ(vanishes_identically(*T - eq.kinetic_energy), true);
}

// Ex. 3.7, a bead on a hoop turning at Ω: T = ½ m R0² (φ̇² + Ω² sin²φ) has a rate-free part T0,
// so the convective term is −∂T0/∂φ = −m R0² Ω² sin φ cos φ.
TEST(CovariantForm, RotatingHoopRateFreeEnergy) {
  const System s = load_model(test::model_path("rotating-hoop"));
  const EquationsOfMotion eq = lagrange_equations(s);
  const Expr phi = s.coordinates()[0].value;
  const Expr m = parameter(s, "m"), R0 = parameter(s, "R0"), Omega = parameter(s, "Omega");
  const std::vector<std::optional<Expr>> c = covariant_convective_terms(s, eq, eq.mass_matrix);
  ASSERT_TRUE(c[0]);
  EXPECT_EQ(
      vanishes_identically(*c[0] + m * R0 * R0 * Omega * Omega * GiNaC::sin(phi) * GiNaC::cos(phi)),
      true)
      << *c[0];
}

// A mass matrix that is not the system's gives terms that do not match its rows: none is taken.
TEST(CovariantForm, AnotherMassMatrixIsRefused) {
  const System s = load_model(test::model_path("double-pendulum"));
  const EquationsOfMotion eq = lagrange_equations(s);
  ExprMatrix wrong = eq.mass_matrix;
  wrong(0, 1) = 2 * wrong(0, 1);
  wrong(1, 0) = 2 * wrong(1, 0);
  for (const auto& row : covariant_convective_terms(s, eq, wrong)) EXPECT_FALSE(row);
  EXPECT_FALSE(quadratic_kinetic_energy(s, eq, wrong));
}

}  // namespace
}  // namespace unidyn
