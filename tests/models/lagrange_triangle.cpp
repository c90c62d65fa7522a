// Three bodies under their mutual gravitation (§5.6, Exercise 5.7): Lagrange's equilateral
// solution, and the Lagrange–Jacobi identity for any motion.
#include <cmath>
#include <numbers>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double G = 1.0, m = 1.0, a = 1.0;

// Fig. 5.6: equal masses at the corners of an equilateral triangle of side a, turning about their
// centre of mass at ω² = 3 G m/a³, keep the triangle (each side a) and turn rigidly (P1 at the
// polar angle π/2 + ω t); J = ½ Σ m r·r is constant there, so T = −½ U (Exercise 5.7(d)).
TEST(LagrangeTriangle, TurnsRigidlyWithTEqualToMinusHalfU) {
  const test::ModelRun run = test::run_model("lagrange-triangle");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double w = std::sqrt(3 * G * m / (a * a * a));
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    for (const char* side : {"side12", "side23", "side31"}) {
      EXPECT_NEAR(run.at(i, side), a, 1e-10) << side << " at " << t;
    }
    const double angle = std::atan2(run.at(i, "y1"), run.at(i, "x1"));
    EXPECT_NEAR(std::remainder(angle - (std::numbers::pi / 2 + w * t), 2 * std::numbers::pi), 0.0,
                1e-10)
        << t;
    EXPECT_NEAR(run.at(i, "T"), -0.5 * run.at(i, "U"), 1e-11) << t;
    EXPECT_NEAR(run.at(i, "U"), -3 * G * m * m / a, 1e-10) << t;
  }
}

// Exercise 5.7: J'' = 2T + U for every motion (U homogeneous of degree −1 in the positions), here
// from a start off the triangle, with J'' = Σ m (v·v + r·a) from the accelerations computed.
TEST(LagrangeTriangle, LagrangeJacobiIdentityOffTheTriangle) {
  const test::ModelRun run =
      test::run_model("lagrange-triangle", {{"der(x1)", -0.2}, {"der(y2)", -0.9}, {"x3", 0.6}},
                      [](SimulationOptions& o) { o.t_end = 3.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double spread = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double T = run.at(i, "T"), U = run.at(i, "U");
    EXPECT_NEAR(run.at(i, "Jdd"), 2 * T + U, 1e-9 * (1 + std::abs(T) + std::abs(U)))
        << run.at(i, "t");
    spread = std::max(spread, std::abs(run.at(i, "side12") - run.at(i, "side23")));
  }
  EXPECT_GT(spread, 0.01);  // not the equilateral motion
}

}  // namespace
}  // namespace unidyn
