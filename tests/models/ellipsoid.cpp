// Exercise 3.9: a particle on a smooth ellipsoid under gravity. models/ellipsoid.yaml (Cartesian
// coordinates and the constraint x²/a² + y²/b² + z²/c² = 1, approach I) against the two
// second-order equations in coordinates on the surface — x = a cos φ, y = b sin φ cos θ,
// z = c sin φ sin θ, no constraint — started at the same point with the same velocity.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
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

// The two second-order equations of Exercise 3.9 (b), derived here by hand. On the surface
// x = a cos φ, y = b sin φ cos θ, z = c sin φ sin θ,
//   T = ½ m (M11 φ̇² + 2 M12 φ̇ θ̇ + M22 θ̇²),   U = m g c sin φ sin θ,
//   M11 = a² sin²φ + cos²φ (b² cos²θ + c² sin²θ),
//   M12 = (c² − b²) sin φ cos φ sin θ cos θ,
//   M22 = sin²φ (b² sin²θ + c² cos²θ),
// and Lagrange's equations d/dt ∂T/∂q̇ − ∂T/∂q = −∂U/∂q, divided by m, are
//   M11 φ̈ + M12 θ̈ + ½ M11,φ φ̇² + M11,θ φ̇ θ̇ + (M12,θ − ½ M22,φ) θ̇² = −g c cos φ sin θ,
//   M12 φ̈ + M22 θ̈ + (M12,φ − ½ M11,θ) φ̇² + M22,φ φ̇ θ̇ + ½ M22,θ θ̇² = −g c sin φ cos θ,
// with M11,φ = 2 sin φ cos φ (a² − b² cos²θ − c² sin²θ), M11,θ = 2 (c² − b²) cos²φ sin θ cos θ,
// M12,φ = (c² − b²) cos 2φ sin θ cos θ, M12,θ = (c² − b²) sin φ cos φ cos 2θ,
// M22,φ = 2 sin φ cos φ (b² sin²θ + c² cos²θ), M22,θ = 2 (b² − c²) sin²φ sin θ cos θ.
// State (φ, φ̇, θ, θ̇).
struct EllipsoidSurface {
  double g, a, b, c;
  std::array<double, 4> rates(const std::array<double, 4>& s) const {
    const double sp = std::sin(s[0]), cp = std::cos(s[0]), st = std::sin(s[2]), ct = std::cos(s[2]),
                 dp = s[1], dt = s[3];
    const double a2 = a * a, b2 = b * b, c2 = c * c;
    const double M11 = a2 * sp * sp + cp * cp * (b2 * ct * ct + c2 * st * st);
    const double M12 = (c2 - b2) * sp * cp * st * ct;
    const double M22 = sp * sp * (b2 * st * st + c2 * ct * ct);
    const double M11p = 2 * sp * cp * (a2 - b2 * ct * ct - c2 * st * st);
    const double M11t = 2 * (c2 - b2) * cp * cp * st * ct;
    const double M12p = (c2 - b2) * (cp * cp - sp * sp) * st * ct;
    const double M12t = (c2 - b2) * sp * cp * (ct * ct - st * st);
    const double M22p = 2 * sp * cp * (b2 * st * st + c2 * ct * ct);
    const double M22t = 2 * (b2 - c2) * sp * sp * st * ct;
    const double f1 =
        -g * c * cp * st - 0.5 * M11p * dp * dp - M11t * dp * dt - (M12t - 0.5 * M22p) * dt * dt;
    const double f2 =
        -g * c * sp * ct - (M12p - 0.5 * M11t) * dp * dp - M22p * dp * dt - 0.5 * M22t * dt * dt;
    const double det = M11 * M22 - M12 * M12;
    return {dp, (M22 * f1 - M12 * f2) / det, dt, (M11 * f2 - M12 * f1) / det};
  }
};

// Exercise 3.9 (b), (c): models/ellipsoid.yaml (approach I, Cartesian coordinates and a
// multiplier) against the two second-order equations above, typed by hand and integrated here by
// RK4 (h = 1e-4 s) from the same point and velocity: x, y, z and their rates over 4 s.
TEST(Ellipsoid, CartesianRunAgainstTheTwoHandDerivedSurfaceEquationsByRk4) {
  const test::ModelRun run = test::run_model("ellipsoid", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const EllipsoidSurface e{run.parameter("g"), run.parameter("a"), run.parameter("b"),
                           run.parameter("c")};
  const double x0 = run.at(0, "x"), y0 = run.at(0, "y"), vx = run.at(0, "der(x)"),
               vy = run.at(0, "der(y)");
  ASSERT_LT(run.at(0, "z"), 0.0);
  const double phi = std::acos(x0 / e.a);
  const double theta = -std::acos(y0 / (e.b * std::sin(phi)));  // sin θ < 0: below, z < 0
  const double dphi = -vx / (e.a * std::sin(phi));
  const double dtheta =
      (e.b * std::cos(phi) * std::cos(theta) * dphi - vy) / (e.b * std::sin(phi) * std::sin(theta));
  std::array<double, 4> s{phi, dphi, theta, dtheta};
  double position_error = 0, velocity_error = 0, farthest = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    s = test::rk4(s, run.at(k - 1, "t"), run.at(k, "t"), 100,
                  [&e](double, const std::array<double, 4>& q) { return e.rates(q); });
    const double sp = std::sin(s[0]), cp = std::cos(s[0]), st = std::sin(s[2]), ct = std::cos(s[2]);
    const std::array<double, 3> r{e.a * cp, e.b * sp * ct, e.c * sp * st};
    const std::array<double, 3> v{-e.a * sp * s[1], e.b * (cp * ct * s[1] - sp * st * s[3]),
                                  e.c * (cp * st * s[1] + sp * ct * s[3])};
    const char* names[3] = {"x", "y", "z"};
    for (int j = 0; j < 3; ++j) {
      position_error = std::max(position_error, std::abs(run.at(k, names[j]) - r[j]));
      velocity_error = std::max(velocity_error,
                                std::abs(run.at(k, std::string("der(") + names[j] + ")") - v[j]));
    }
    farthest = std::max(farthest, std::hypot(r[0] - x0, r[1] - y0));
  }
  EXPECT_GT(farthest, 0.3) << "it must move for the comparison to mean anything";
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 4 s
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(velocity_error, 1e-8);
  std::printf(
      "Ex. 3.9 RK4 of the two equations vs the Cartesian run over 4 s: position %.3g m, "
      "velocity %.3g m/s\n",
      position_error, velocity_error);
}

}  // namespace
}  // namespace unidyn
