// Exercise 3.8(a): a particle on the rough parabolic surface x − y² = −4 in the non-orthogonal
// coordinates (1.6) (models/rough-parabolic-surface.yaml), against the same particle in Cartesian
// coordinates — other coordinates, other equations — and Coulomb's law μ_d |N| at every row.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

TEST(RoughParabolicSurface, SameMotionAsInCartesianCoordinatesWithCoulombFriction) {
  const test::ModelRun run = test::run_model("rough-parabolic-surface");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const test::ModelRun cartesian = test::run_system(parse_model(R"(unidyn: 1
parameters: {m: 1.0, g: 9.81, mu_d: 0.15}
coordinates: [x, y, z]
particles:
  P: {mass: m, position: [x, y, z]}
forces:
  - gravity: -g*E2
constraints:
  - {name: surface, position: x - y^2 + 4, friction: {on: P, dynamic: mu_d}}
initial: {x: -1.75, y: 1.5, der(x): 1.5, der(y): 0.5, der(z): 2.0}
simulate: {t_end: 1.5, output_step: 0.01, rtol: 1e-12}
)",
                                                                "cartesian.yaml"));
  ASSERT_TRUE(cartesian.summary.ok) << cartesian.summary.message;
  ASSERT_EQ(run.rows.size(), cartesian.rows.size());
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    for (const std::string c : {"x", "y", "z"}) {
      EXPECT_NEAR(run.at(i, c), cartesian.at(i, c), 1e-9) << c << " at " << t;
    }
    EXPECT_NEAR(run.at(i, "friction"), 0.15 * std::abs(run.at(i, "normal")), 1e-10) << t;
  }
  // it slides the whole time (the test means something only if it moves)
  EXPECT_EQ(run.summary.phases.size(), 1u);
  EXPECT_GT(std::abs(run.rows.back()[run.index("z")] - run.at(0, "z")), 1.0);
}

}  // namespace
}  // namespace unidyn
