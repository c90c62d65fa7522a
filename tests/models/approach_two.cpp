// Lagrange's equations, approach II (3.8): the reduced models give the book's reduced equations and
// the same motion as approach I.
#include "unidyn/equations/reduction.hpp"

#include <algorithm>
#include <cmath>

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

// Runs a model by approach I and by approach II over 2 s (t_end shortened) and compares every
// column the two share — the coordinates that remain, their rates, the multipliers of the
// constraints that remain — to `tolerance` (relative to 1 + |value|); returns the reduction.
Reduction expect_same_motion(const std::string& name, double tolerance) {
  const System full = load_model(test::model_path(name));
  Reduction reduction = eliminate_constraints(full);
  const System& reduced = reduction.system;
  SimulationOptions options = simulation_options(full.simulate);
  options.t_end = std::min(options.t_end, 2.0);
  std::vector<std::vector<double>> rows_full, rows_reduced;
  const auto s1 =
      simulate(full, CompiledSystem(full, lagrange_equations(full)), initial_state(full, {}),
               options, [&](const std::vector<double>& row) { rows_full.push_back(row); });
  const auto s2 = simulate(reduced, CompiledSystem(reduced, lagrange_equations(reduced)),
                           initial_state(reduced, {}), options,
                           [&](const std::vector<double>& row) { rows_reduced.push_back(row); });
  EXPECT_TRUE(s1.ok && s2.ok) << name << ": " << s1.message << s2.message;
  EXPECT_EQ(rows_full.size(), rows_reduced.size()) << name;
  if (rows_full.size() != rows_reduced.size()) return reduction;
  const std::vector<std::string> columns_full = simulation_columns(full);
  const std::vector<std::string> columns_reduced = simulation_columns(reduced);
  std::size_t shared = 0;
  for (std::size_t j = 0; j < columns_reduced.size(); ++j) {
    const auto i = std::find(columns_full.begin(), columns_full.end(), columns_reduced[j]) -
                   columns_full.begin();
    if (i == static_cast<std::ptrdiff_t>(columns_full.size())) continue;
    ++shared;
    for (std::size_t row = 0; row < rows_full.size(); ++row) {
      const double expected = rows_full[row][static_cast<std::size_t>(i)];
      EXPECT_NEAR(rows_reduced[row][j], expected, tolerance * (1 + std::abs(expected)))
          << name << " " << columns_reduced[j] << " t = " << rows_full[row][0];
    }
  }
  EXPECT_GT(shared, 2u) << name;
  // and the same energy
  EXPECT_NEAR(s1.energy_initial, s2.energy_initial, 1e-12 * std::abs(s1.energy_initial)) << name;
  return reduction;
}

// Approaches I and II give the same motion (helix and pendulum-cart). Bodies too: eliminating a
// ball joint's rows (linear in the centre's coordinates) reaches the centres, rotations, body
// forces, moments and the remaining rows' loads.
TEST(ApproachTwo, SameMotionAsApproachOne) {
  for (const std::string name :
       {"helix", "pendulum-cart", "unbalanced-rotor-pinned", "hinged-bodies-pinned"}) {
    expect_same_motion(name, 1e-9);
  }
}

// (3.8), (10.24): approach II with velocity constraints is the Routh–Voss form — the integrable
// constraints eliminated, the non-integrable ones kept with their multipliers, which equal
// approach I's. A constraint with friction keeps its multiplier (its normal force, §3.8), and so
// does a unilateral one (it may let go); eliminating them would silently drop the friction.
TEST(ApproachTwo, RouthVossKeepsVelocityConstraintsFrictionAndContacts) {
  const auto kept = [](const Reduction& r, const std::string& what) {
    return std::any_of(r.notes.begin(), r.notes.end(),
                       [&](const std::string& n) { return n.find(what) != std::string::npos; });
  };
  const Reduction disk = expect_same_motion("rolling-disk", 1e-8);
  EXPECT_TRUE(kept(disk, "eliminated x3 by constraint height"));
  EXPECT_TRUE(kept(disk, "kept constraint pi1: a velocity constraint"));
  const Reduction cart = expect_same_motion("braking-cart", 1e-8);
  EXPECT_TRUE(kept(cart, "eliminated z1 by constraint ground1"));
  EXPECT_TRUE(kept(cart, "kept constraint ground3: its friction needs its normal force"));
  const Reduction ball = expect_same_motion("sphere-slide-roll", 1e-8);
  EXPECT_TRUE(kept(ball, "kept constraint table: its friction"));
  for (const std::string name : {"stick-slip-oscillator", "rotating-cone", "roller-coaster"}) {
    expect_same_motion(name, 1e-8);
  }
  const Reduction string = expect_same_motion("string-through-hole", 1e-8);
  EXPECT_TRUE(kept(string, "kept constraint string: it is unilateral"));
}

}  // namespace
}  // namespace unidyn
