// §3.5, (3.9)–(3.11): a particle on a smooth sphere of radius d(t) with a force D R e_θ.
#include <array>
#include <cmath>
#include <cstdio>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// (3.10): d/dt(m d² sin²φ θ̇) = D d² sin φ — p_θ(t) − p_θ(0) is the integral of D d² sin φ
// (Simpson's rule on the 1 ms grid); (3.11): the multiplier of R − d(t) = 0 is λ = m d̈ − m d sin²φ
// θ̇² − m d φ̇² + m g cos φ.
TEST(ExpandingSphere, ApproachTwoAndTheMultiplierOfApproachOne) {
  const double m = 1.0, g = 9.81, d0 = 1.0, a = 0.2, w = 2.0;
  const test::ModelRun run = test::run_model("expanding-sphere");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const std::vector<double> impulse = test::running_integral(run, "source");
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), d = d0 + a * std::sin(w * t),
                 d2 = -a * w * w * std::sin(w * t), phi = run.at(i, "phi");
    const double lambda = m * d2 - m * d * std::pow(std::sin(phi) * run.at(i, "der(theta)"), 2) -
                          m * d * std::pow(run.at(i, "der(phi)"), 2) + m * g * std::cos(phi);
    EXPECT_NEAR(run.at(i, "lambda(sphere)"), lambda, 1e-10) << t;
    if (i % 2 == 1) continue;
    EXPECT_NEAR(run.at(i, "p_theta") - run.at(0, "p_theta"), impulse[i], 1e-9) << t;
  }
}

// §3.5, the special case of the extra constraint f_1 θ̇ + f_2 φ̇ + f_3 Ṙ + e = 0 with f_2 = 1 and
// f_1 = f_3 = e = 0: φ̇ = 0, given here as a velocity constraint on models/expanding-sphere.yaml.
constexpr const char* kConeSphere = R"yaml(unidyn: 1
name: Particle on a sphere of changing radius with phi' = 0
parameters: {m: 1.0, g: 9.81, D: 0.5, d0: 1.0, a: 0.2, w: 2.0}
coordinates: [theta, phi, R]
particles:
  P: {mass: m, position: "R*[sin(phi)*cos(theta), sin(phi)*sin(theta), cos(phi)]"}
forces:
  - gravity: -g*E3
  - force: {at: P, value: "D*R*[-sin(theta), cos(theta), 0]"}
constraints:
  - {name: sphere, position: R - d0 - a*sin(w*t)}
  - {name: cone, velocity: der(phi)}
initial: {phi: 2.0, R: d0, der(R): a*w, der(theta): 1.5, der(phi): 0}
simulate: {t_end: 4, output_step: 0.01, rtol: 1e-12}
outputs:
  x: dot(P.position, E1)
  y: dot(P.position, E2)
  z: dot(P.position, E3)
)yaml";

// With φ = φ0 and R = d(t), the θ-row of §3.5, d/dt(m d² sin²φ0 θ̇) = D d² sin φ0, is by hand
//   θ̈ = D/(m sin φ0) − 2 ḋ θ̇/d;
// the φ-row gives the multiplier of φ̇ = 0, λ_2 = −m d² sin φ0 cos φ0 θ̇² − m g d sin φ0, and the
// R-row (3.11) λ = m d̈ − m d sin²φ0 θ̇² + m g cos φ0. State (θ, θ̇).
struct ConeOnSphere {
  double m, g, D, d0, a, w, phi0;
  double d(double t) const { return d0 + a * std::sin(w * t); }
  double ddot(double t) const { return a * w * std::cos(w * t); }
  double dddot(double t) const { return -a * w * w * std::sin(w * t); }
  // the run's parameters, and φ0
  static ConeOnSphere of(const test::ModelRun& run, double polar_angle) {
    return {run.parameter("m"), run.parameter("g"), run.parameter("D"), run.parameter("d0"),
            run.parameter("a"), run.parameter("w"), polar_angle};
  }
  std::array<double, 2> rates(double t, const std::array<double, 2>& s) const {
    return {s[1], D / (m * std::sin(phi0)) - 2 * ddot(t) * s[1] / d(t)};
  }
};

// §3.5, φ̇ = 0: the particle moves on the circle of radius d(t) sin φ0 at height d(t) cos φ0 (the
// book's closed form, d typed here), with θ(t), θ̇(t) from the hand-reduced θ-row above by RK4
// (h = 1e-4 s); the multipliers of R − d = 0 and of φ̇ = 0 against (3.11) and the φ-row on that
// RK4 solution.
TEST(ExpandingSphere, ConeConstraintGivesTheCircleOfRadiusDSinPhi0) {
  const test::ModelRun run = test::run_system(parse_model(kConeSphere, "cone-sphere.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const ConeOnSphere c = ConeOnSphere::of(run, 2.0);
  const double sp = std::sin(c.phi0), cp = std::cos(c.phi0);
  std::array<double, 2> s{0.0, 1.5};
  double t = 0, circle_error = 0, theta_error = 0, lambda_error = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, 100,
                  [&c](double tau, const std::array<double, 2>& q) { return c.rates(tau, q); });
    t = t1;
    const double d = c.d(t), x = run.at(k, "x"), y = run.at(k, "y");
    circle_error = std::max(
        {circle_error, std::abs(std::hypot(x, y) - d * sp), std::abs(run.at(k, "z") - d * cp),
         std::abs(x - d * sp * std::cos(s[0])), std::abs(y - d * sp * std::sin(s[0]))});
    theta_error = std::max({theta_error, std::abs(run.at(k, "theta") - s[0]),
                            std::abs(run.at(k, "der(theta)") - s[1])});
    const double lambda = c.m * c.dddot(t) - c.m * d * sp * sp * s[1] * s[1] + c.m * c.g * cp;
    const double lambda2 = -c.m * d * d * sp * cp * s[1] * s[1] - c.m * c.g * d * sp;
    lambda_error = std::max({lambda_error, std::abs(run.at(k, "lambda(sphere)") - lambda),
                             std::abs(run.at(k, "lambda(cone)") - lambda2)});
  }
  EXPECT_GT(s[0], 6.0) << "θ must go round for the circle to mean anything";
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 4 s
  EXPECT_LT(circle_error, 1e-9);
  EXPECT_LT(theta_error, 1e-9);
  EXPECT_LT(lambda_error, 1e-8);
  std::printf("phi' = 0 over 4 s: circle %.3g m, theta %.3g, multipliers %.3g N\n", circle_error,
              theta_error, lambda_error);
}

// (3.10) written out by hand (R = d(t), φ the polar angle, θ the azimuth):
//   θ-row: m d² sin²φ θ̈ + m (2 d ḋ sin²φ + 2 d² sin φ cos φ φ̇) θ̇ = D d² sin φ,
//   φ-row: m d² φ̈ + 2 m d ḋ φ̇ − m d² sin φ cos φ θ̇² − m g d sin φ = 0,
// so θ̈ = D/(m sin φ) − 2 ḋ θ̇/d − 2 cot φ φ̇ θ̇ and φ̈ = sin φ cos φ θ̇² + g sin φ/d − 2 ḋ φ̇/d.
// State (θ, θ̇, φ, φ̇).
std::array<double, 4> sphere_rates(double t, const std::array<double, 4>& s,
                                   const ConeOnSphere& c) {
  const double d = c.d(t), dd = c.ddot(t), sp = std::sin(s[2]), cp = std::cos(s[2]);
  return {s[1], c.D / (c.m * sp) - 2 * dd * s[1] / d - 2 * cp / sp * s[3] * s[1], s[3],
          sp * cp * s[1] * s[1] + c.g * sp / d - 2 * dd * s[3] / d};
}

// §3.5: models/expanding-sphere.yaml (approach I, coordinates θ, φ, R and the multiplier of
// R − d(t) = 0) against both rows of (3.10), integrated here by RK4 (h = 1e-4 s) from the model's
// start; λ of (3.11) evaluated on that RK4 solution.
TEST(ExpandingSphere, MotionAgainstBothRowsOf310ByRk4) {
  const test::ModelRun run = test::run_model("expanding-sphere");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const ConeOnSphere c = ConeOnSphere::of(run, 0.0);
  std::array<double, 4> s{run.at(0, "theta"), run.at(0, "der(theta)"), run.at(0, "phi"),
                          run.at(0, "der(phi)")};
  double t = 0, motion_error = 0, lambda_error = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, 10, [&c](double tau, const std::array<double, 4>& q) {
      return sphere_rates(tau, q, c);
    });
    t = t1;
    motion_error =
        std::max({motion_error, std::abs(run.at(k, "theta") - s[0]),
                  std::abs(run.at(k, "der(theta)") - s[1]), std::abs(run.at(k, "phi") - s[2]),
                  std::abs(run.at(k, "der(phi)") - s[3]), std::abs(run.at(k, "R") - c.d(t))});
    const double d = c.d(t), sp = std::sin(s[2]);
    const double lambda = c.m * c.dddot(t) - c.m * d * sp * sp * s[1] * s[1] -
                          c.m * d * s[3] * s[3] + c.m * c.g * std::cos(s[2]);
    lambda_error = std::max(lambda_error, std::abs(run.at(k, "lambda(sphere)") - lambda));
  }
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 4 s
  EXPECT_LT(motion_error, 1e-9);
  EXPECT_LT(lambda_error, 1e-8);
  std::printf("(3.10) by RK4 vs model over 4 s: theta, phi and rates %.3g, lambda %.3g N\n",
              motion_error, lambda_error);
}

}  // namespace
}  // namespace unidyn
