// Exercise 3.9: a particle on a smooth ellipsoid under gravity. models/ellipsoid.yaml (Cartesian
// coordinates and the constraint x²/a² + y²/b² + z²/c² = 1, approach I) against the two
// second-order equations in coordinates on the surface — x = a cos φ, y = b sin φ cos θ,
// z = c sin φ sin θ, no constraint — started at the same point with the same velocity.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

TEST(Ellipsoid, SameMotionInCoordinatesOnTheSurface) {
  // der(z) left out: computed from the constraint, as `unidyn simulate` does
  const test::ModelRun run = test::run_model("ellipsoid", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  const double a = 1.2, b = 0.8, x0 = 0.3, y0 = 0.2, vx = 0.4, vy = 1.2;
  const double phi = std::acos(x0 / a);
  const double theta = -std::acos(y0 / (b * std::sin(phi)));  // below: z < 0
  const double dphi = -vx / (a * std::sin(phi));
  const double dtheta =
      (b * std::cos(phi) * std::cos(theta) * dphi - vy) / (b * std::sin(phi) * std::sin(theta));
  const test::ModelRun surface =
      test::run_system(parse_model(R"(unidyn: 1
parameters: {m: 0.5, g: 9.81, a: 1.2, b: 0.8, c: 0.5}
coordinates: [phi, th]
particles:
  P: {mass: m, position: "[a*cos(phi), b*sin(phi)*cos(th), c*sin(phi)*sin(th)]"}
forces:
  - gravity: -g*E3
simulate: {t_end: 4, output_step: 0.01, rtol: 1e-12}
outputs:
  x: dot(P.position, E1)
  y: dot(P.position, E2)
  z: dot(P.position, E3)
)",
                                   "surface.yaml"),
                       {{"phi", phi}, {"th", theta}, {"der(phi)", dphi}, {"der(th)", dtheta}});
  ASSERT_TRUE(surface.summary.ok) << surface.summary.message;
  ASSERT_EQ(run.rows.size(), surface.rows.size());
  EXPECT_NEAR(surface.at(0, "z"), run.at(0, "z"), 1e-15);
  double farthest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    for (const std::string c : {"x", "y", "z"}) {
      EXPECT_NEAR(surface.at(i, c), run.at(i, c), 1e-8) << c << " at " << run.at(i, "t");
    }
    farthest = std::max(farthest, std::hypot(run.at(i, "x") - x0, run.at(i, "y") - y0));
  }
  EXPECT_GT(farthest, 0.3) << "it must move for the comparison to mean anything";
}

}  // namespace
}  // namespace unidyn
