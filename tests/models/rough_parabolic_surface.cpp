// Exercise 3.8(a): a particle on the rough parabolic surface x − y² = −4 in the non-orthogonal
// coordinates (1.6) (models/rough-parabolic-surface.yaml), against the same particle in Cartesian
// coordinates — other coordinates, other equations — and Coulomb's law μ_d |N| at every row; and
// against the book's equations in the coordinates (1.6), written and integrated by RK4 here.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
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

// Ex. 3.8(a) by hand in the coordinates (1.6), q1 = y, q2 = x − y², q3 = z:
// r = (q2 + q1²) E1 + q1 E2 + q3 E3, a_1 = 2 q1 E1 + E2, a_2 = E1, a_3 = E3, a^2 = E1 − 2 q1 E2
// (a^2 · a_1 = a^2 · a_3 = 0, a^2 · a_2 = 1). On the surface q2 = −4 (q̇2 = 0) v = q̇1 a_1 + q̇3 a_3
// and T = (m/2)((1 + 4 q1²) q̇1² + q̇3²). The book's F_c = λ a^2 − μ_d |λ| |a^2| v/|v| and
// gravity −m g E2 in Lagrange's equations (3.1), d/dt(∂T/∂q̇^i) − ∂T/∂q^i = F · a_i, at q̇2 = 0:
//   i = 1: m (1 + 4 q1²) q̈1 + 4 m q1 q̇1² = −m g + F_f · a_1,
//   i = 3: m q̈3 = F_f · a_3,
// with F_f · a_1 = −μ_d |λ| |a^2| (1 + 4 q1²) q̇1/|v|, F_f · a_3 = −μ_d |λ| |a^2| q̇3/|v|,
// |v|² = (1 + 4 q1²) q̇1² + q̇3². The normal force from the normal acceleration: a · a^2 = ẍ − 2 y ÿ
// = 2 q̇1² (x = y² − 4 gives ẍ = 2 ẏ² + 2 y ÿ), so m a · a^2 = F · a^2 = 2 m g q1 + λ |a^2|² and
//   λ = 2 m (q̇1² − g q1)/(1 + 4 q1²)
// (|a^2| λ is the curvature's m κ v² less gravity's normal part, times |a^2|² / |a^2|).
using BookState = std::array<double, 4>;  // q1, q̇1, q3, q̇3

struct BookParabola {
  double m, g, mu_d;
  double lambda(const BookState& s) const {
    return 2 * m * (s[1] * s[1] - g * s[0]) / (1 + 4 * s[0] * s[0]);
  }
  double speed(const BookState& s) const {
    return std::sqrt((1 + 4 * s[0] * s[0]) * s[1] * s[1] + s[3] * s[3]);
  }
  double friction(const BookState& s) const {  // μ_d |λ| |a^2|
    return mu_d * std::abs(lambda(s)) * std::sqrt(1 + 4 * s[0] * s[0]);
  }
  BookState rates(const BookState& s) const {
    const double q1 = s[0], q1d = s[1], metric = 1 + 4 * q1 * q1;
    const double f = friction(s) / speed(s);
    const double q1dd = (-m * g - f * metric * q1d - 4 * m * q1 * q1d * q1d) / (m * metric);
    return {q1d, q1dd, s[3], -f * s[3] / m};
  }
};

// Ex. 3.8(a): the model's run against the book's equations in the coordinates (1.6) written above
// and integrated here by RK4 from the model's start (q1 = 1.5, q̇1 = 0.5, q3 = 0, q̇3 = 2): q1, q3,
// their rates, x = q1² − 4, the multiplier λ, the contact force's normal part λ |a^2| and its
// friction part μ_d |λ| |a^2|, and E = T + m g q1 with the T above. The oracle's |v| stays well
// above 0 over the 1.5 s (it slides throughout, no sticking).
TEST(RoughParabolicSurface, MotionNormalForceAndFrictionAgreeWithBookEquationsByRk4) {
  const test::ModelRun run = test::run_model("rough-parabolic-surface");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  const BookParabola P{run.parameter("m"), run.parameter("g"), run.parameter("mu_d")};
  BookState s{1.5, 0.5, 0.0, 2.0};
  ASSERT_EQ(run.at(0, "q1"), s[0]);
  ASSERT_EQ(run.at(0, "der(q1)"), s[1]);
  ASSERT_EQ(run.at(0, "der(q3)"), s[3]);
  double t = 0, position_error = 0, rate_error = 0, lambda_error = 0, force_error = 0;
  double energy_error = 0, speed_min = 1e300;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    if (t1 > t) {
      s = test::rk4(s, t, t1, 20, [&P](double, const BookState& q) { return P.rates(q); });
      t = t1;
    }
    position_error =
        std::max({position_error, std::abs(run.at(k, "q1") - s[0]),
                  std::abs(run.at(k, "q3") - s[2]), std::abs(run.at(k, "x") - (s[0] * s[0] - 4))});
    EXPECT_EQ(run.at(k, "q2"), -4.0) << t;
    rate_error = std::max(
        {rate_error, std::abs(run.at(k, "der(q1)") - s[1]), std::abs(run.at(k, "der(q3)") - s[3])});
    const double lambda = P.lambda(s), a2 = std::sqrt(1 + 4 * s[0] * s[0]);
    lambda_error = std::max(lambda_error, std::abs(run.at(k, "lambda(surface)") - lambda));
    force_error = std::max({force_error, std::abs(run.at(k, "normal") - lambda * a2),
                            std::abs(run.at(k, "friction") - P.friction(s))});
    const double T = P.m / 2 * ((1 + 4 * s[0] * s[0]) * s[1] * s[1] + s[3] * s[3]);
    energy_error = std::max(energy_error, std::abs(run.at(k, "energy") - (T + P.m * P.g * s[0])));
    speed_min = std::min(speed_min, P.speed(s));
  }
  // RK4 at h = 5e-4 s (error ~1e-12) against a run at rtol 1e-12 over 1.5 s
  EXPECT_LT(position_error, 1e-8);
  EXPECT_LT(rate_error, 1e-8);
  EXPECT_LT(lambda_error, 1e-8);
  EXPECT_LT(force_error, 1e-8);
  EXPECT_LT(energy_error, 1e-8);
  EXPECT_GT(speed_min, 0.1) << "it must slide throughout";
  EXPECT_GT(std::abs(run.rows.back()[run.index("q3")]), 1.0);
  std::printf(
      "(1.6) equations by RK4 vs model over 1.5 s: q %.3g, q' %.3g, lambda %.3g N, normal and "
      "friction %.3g N, E %.3g J; min |v| %.3f m/s\n",
      position_error, rate_error, lambda_error, force_error, energy_error, speed_min);
}

}  // namespace
}  // namespace unidyn
