// Lagrange's equations, approach II (3.8): the reduced models give the book's reduced equations and
// the same motion as approach I.
#include "unidyn/equations/reduction.hpp"

#include "support/model_run.hpp"
#include "support/oracles.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

bool vanishes(const Expr& e) {
  return simplify(e).is_zero();
}

Expr parameter(const System& s, const std::string& name) {
  return s.parameters[*s.find_parameter(name)].symbol;
}

// (3.18): on the helix, approach II leaves θ with m(1 + α²)R² θ̈ = −m g α R
TEST(ApproachTwo, HelixGivesBookEquation) {
  const Reduction reduction = eliminate_constraints(load_model(test::model_path("helix")));
  const System& s = reduction.system;
  ASSERT_EQ(s.coordinates().size(), 1u);
  EXPECT_EQ(s.coordinates()[0].name, "theta");
  EXPECT_TRUE(s.constraints.empty());
  const EquationsOfMotion eq = lagrange_equations(s);
  const Expr m = parameter(s, "m"), R = parameter(s, "R"), alpha = parameter(s, "alpha"),
             g = parameter(s, "g");
  EXPECT_TRUE(vanishes(eq.mass_matrix(0, 0) - m * (1 + alpha * alpha) * R * R));
  EXPECT_TRUE(vanishes(eq.forcing[0] + m * g * alpha * R));
}

// (5.11)–(5.12): the pendulum and cart reduce to x, r, θ with the book's mass matrix and forcing
TEST(ApproachTwo, PendulumCartGivesBookEquations) {
  const Reduction reduction = eliminate_constraints(load_model(test::model_path("pendulum-cart")));
  const System& s = reduction.system;
  ASSERT_EQ(s.coordinates().size(), 3u);
  const EquationsOfMotion eq = lagrange_equations(s);
  const Expr m1 = parameter(s, "m1"), m2 = parameter(s, "m2"), g = parameter(s, "g"),
             K = parameter(s, "K"), L0 = parameter(s, "L0");
  const Expr r = s.coordinates()[1].value, th = s.coordinates()[2].value;
  const Expr dr = s.coordinates()[1].rate, dth = s.coordinates()[2].rate;
  const Expr M[3][3] = {{m1 + m2, m2 * cos(th), -m2 * r * sin(th)},
                        {m2 * cos(th), m2, 0},
                        {-m2 * r * sin(th), 0, m2 * r * r}};
  // M q̈ = −f with the book's f (r > 0, so √(r²) = r)
  const Expr f[3] = {-2 * m2 * dr * dth * sin(th) - m2 * r * dth * dth * cos(th),
                     -m2 * r * dth * dth + m2 * g * sin(th) + K * (r - L0),
                     2 * m2 * r * dr * dth + m2 * g * r * cos(th)};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      EXPECT_TRUE(vanishes(
          eq.mass_matrix(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) - M[i][j]));
    }
    // r > 0: (r²)^(−1/2) = 1/r
    const Expr forcing = simplify(eq.forcing[static_cast<std::size_t>(i)])
                             .subs(GiNaC::pow(GiNaC::pow(r, 2), GiNaC::numeric(-1, 2)) == 1 / r);
    EXPECT_TRUE(vanishes(forcing + f[i])) << i << ": " << simplify(forcing + f[i]);
  }
}

// A constraint that cannot be solved for a coordinate (the rod x² + y² + z² = L²) stays, with its
// multiplier, and a note says so
TEST(ApproachTwo, NonlinearConstraintIsKept) {
  const Reduction reduction =
      eliminate_constraints(load_model(test::model_path("spherical-pendulum-cartesian")));
  EXPECT_EQ(reduction.system.constraints.size(), 1u);
  EXPECT_EQ(reduction.system.coordinates().size(), 3u);
  ASSERT_EQ(reduction.notes.size(), 1u);
  EXPECT_NE(reduction.notes[0].find("kept constraint rod"), std::string::npos);
}

// Approaches I and II give the same motion (helix and pendulum-cart over 2 s)
// Bodies too: eliminating a ball joint's rows (linear in the centre's coordinates) reaches the
// centres, rotations, body forces, moments and the remaining rows' loads.
TEST(ApproachTwo, SameMotionAsApproachOne) {
  for (const std::string name :
       {"helix", "pendulum-cart", "unbalanced-rotor-pinned", "hinged-bodies-pinned"}) {
    const System full = load_model(test::model_path(name));
    const System reduced = eliminate_constraints(full).system;
    SimulationOptions options = simulation_options(full.simulate);
    options.t_end = 2.0;
    std::vector<std::vector<double>> rows_full, rows_reduced;
    const auto s1 =
        simulate(full, CompiledSystem(full, lagrange_equations(full)), initial_state(full, {}),
                 options, [&](const std::vector<double>& row) { rows_full.push_back(row); });
    const auto s2 = simulate(reduced, CompiledSystem(reduced, lagrange_equations(reduced)),
                             initial_state(reduced, {}), options,
                             [&](const std::vector<double>& row) { rows_reduced.push_back(row); });
    ASSERT_TRUE(s1.ok && s2.ok);
    ASSERT_EQ(rows_full.size(), rows_reduced.size());
    // the reduced model's coordinates are the full model's, minus the eliminated ones
    const auto& q_full = full.coordinates();
    const auto& q_reduced = reduced.coordinates();
    for (std::size_t j = 0; j < q_reduced.size(); ++j) {
      std::size_t i = 0;
      while (q_full[i].name != q_reduced[j].name) ++i;
      for (std::size_t row = 0; row < rows_full.size(); ++row) {
        EXPECT_NEAR(rows_full[row][1 + i], rows_reduced[row][1 + j], 1e-9)
            << name << " " << q_full[i].name;
      }
    }
    // and the same energy
    EXPECT_NEAR(s1.energy_initial, s2.energy_initial, 1e-12 * std::abs(s1.energy_initial));
  }
}

}  // namespace
}  // namespace unidyn
