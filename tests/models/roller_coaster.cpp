// The roller coaster of §2.11 (Figs. 2.12–2.14) beyond its sliding equation (tests/models/
// friction.cpp): without friction its equilibria are the crests and the bottoms of the track
// y = A cos(π x1/L0); with static friction μ_s ≥ π A/L0 (the steepest slope |f'|) the cart can rest
// anywhere on it.
#include <cmath>
#include <numbers>
#include <optional>
#include <set>

#include "support/linearized_model.hpp"
#include "support/model_run.hpp"
#include "unidyn/analysis/equilibria.hpp"

namespace unidyn {
namespace {

constexpr double g = 9.81, A = 0.25, L0 = 1.0, pi = std::numbers::pi;

// Smooth (μ = 0): m (1 + f'²) ẍ = −m g f' − m f'' f' ẋ² (2.27), so the equilibria are the x with
// f' = 0: the crests x1 = 2k L0 (saddles of the energy: unstable) and the bottoms (2k + 1) L0,
// where ẍ = −g f'' δx gives the frequency ω = π √(g A)/L0 (π √(A/L0) in the book's units).
TEST(RollerCoaster, CrestsUnstableBottomsOscillateAtPiRootGA) {
  const System system = load_model(test::model_path("roller-coaster"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const EquilibriumSearchResult found =
      find_equilibria(system, compiled, parse_given_values(system, {}),
                      initial_state(system, {{"mu_d", 0.0}, {"mu_s", 0.0}}).parameters);
  // Newton's steps carry some starts past their box: every equilibrium found is a crest or a
  // bottom, and those within the starts' box (x1 within 2.6 of 0.3) are all found
  const std::size_t x1 = *system.find_coordinate("x1"), y = *system.find_coordinate("y");
  std::set<long> found_at;
  for (const Equilibrium& e : found.equilibria) {
    const double x = e.point.q[x1];
    const long k = std::lround(x / L0);
    EXPECT_NEAR(x, static_cast<double>(k) * L0, 1e-9);
    found_at.insert(k);
    const bool crest = k % 2 == 0;
    EXPECT_NEAR(e.point.q[y], crest ? A : -A, 1e-9);
    ASSERT_FALSE(e.modes.modes.empty());
    EXPECT_EQ(e.potential_minimum, std::optional<bool>(!crest)) << x;
    if (crest) {
      // δẍ = +g A π²/L0² δx: the eigenvalues ±π √(g A)/L0, real
      EXPECT_EQ(e.modes.verdict, Stability::unstable) << x;
      EXPECT_NEAR(std::abs(e.modes.modes[0].eigenvalue.real()), pi * std::sqrt(g * A) / L0, 1e-8);
    } else {
      EXPECT_EQ(e.modes.verdict, Stability::linearly_stable) << x;
      ASSERT_EQ(e.modes.modes.size(), 1u);
      EXPECT_NEAR(e.modes.modes[0].damped_frequency, pi * std::sqrt(g * A) / L0, 1e-8);
    }
  }
  for (long k = -2; k <= 2; ++k) EXPECT_TRUE(found_at.contains(k)) << k;
}

// Put down at rest at the steepest point x1 = L0/2 (|f'| = π A/L0 = 0.785): with μ_s just above
// π A/L0 the cart stays there, and so anywhere; just below it slides at once.
TEST(RollerCoaster, RestsAnywhereOnlyIfStaticFrictionExceedsPiAOverL0) {
  const double steepest = pi * A / L0;
  for (const double factor : {1.01, 0.99}) {
    const test::ModelRun run = test::run_model("roller-coaster",
                                               {{"mu_s", factor * steepest},
                                                {"mu_d", 0.5 * steepest},
                                                {"x1", 0.5 * L0},
                                                {"y", 0.0},
                                                {"der(x1)", 0.0},
                                                {"der(y)", 0.0}},
                                               [](SimulationOptions& o) { o.t_end = 2.0; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const double moved = std::abs(run.rows.back()[run.index("x1")] - 0.5 * L0);
    if (factor > 1) {
      EXPECT_LT(moved, 1e-12) << "held by μ_s = " << factor * steepest;
    } else {
      EXPECT_GT(moved, 0.1) << "μ_s = " << factor * steepest << " cannot hold it";
    }
  }
}

}  // namespace
}  // namespace unidyn
