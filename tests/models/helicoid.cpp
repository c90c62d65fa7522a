// Exercise 3.5: a particle on a smooth helicoid z = αθ under gravity.
#include <array>
#include <cmath>
#include <cstdio>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// (3.24): d/dt(m (r² + α²) θ̇) = −m g α, so p = m (r² + α²) θ̇ falls linearly, p(t) = p(0) − m g α t;
// r̈ = r θ̇²; and H_O·E3 = m r² θ̇ is not conserved (it changes sign here).
TEST(Helicoid, Equations324AndTheAngularMomentumNotConserved) {
  const double m = 1.0, g = 9.81, alpha = 0.3;
  const test::ModelRun run = test::run_model("helicoid");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double least = 1e9, most = -1e9;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "p_theta"), run.at(0, "p_theta") - m * g * alpha * t, 1e-10) << t;
    EXPECT_NEAR(run.at(i, "rdd"), run.at(i, "r") * std::pow(run.at(i, "der(theta)"), 2), 1e-10);
    least = std::min(least, run.at(i, "H3"));
    most = std::max(most, run.at(i, "H3"));
  }
  EXPECT_LT(least, 0.0);
  EXPECT_GT(most, 0.0);
}

// Exercise 3.5 (c): models/helicoid.yaml with the extra non-integrable constraint r θ̇ + h(t) = 0,
// here h(t) = −(h0 + h1 sin ωt) (so θ̇(0) = h0/r(0) = 2, the model's start), given as text.
constexpr const char* kSteeredHelicoid = R"yaml(unidyn: 1
name: Particle on a smooth helicoid with r theta' + h(t) = 0
parameters: {m: 1.0, g: 9.81, alpha: 0.3, h0: 2.0, h1: 0.5, w: 3.0}
coordinates: [theta, r, nu]
particles:
  P: {mass: m, position: "[r*cos(theta), r*sin(theta), nu + alpha*theta]"}
forces:
  - gravity: -g*E3
constraints:
  - {name: helicoid, position: nu}
  - {name: steer, velocity: r*der(theta) - h0 - h1*sin(w*t)}
initial: {r: 1.0, der(theta): 2.0, der(r): 0.1}
simulate: {t_end: 3, output_step: 0.01, rtol: 1e-12}
outputs:
  Fr: "dot(P.constraint_force, [cos(theta), sin(theta), 0])"
  Ftheta: "dot(P.constraint_force, [-sin(theta), cos(theta), 0])"
  Fz: dot(P.constraint_force, E3)
)yaml";

// By hand, from T = ½ m (ṙ² + r² θ̇² + (ν̇ + α θ̇)²), U = m g (ν + α θ), the constraints ν = 0
// (multiplier λ1, row ν) and r θ̇ + h = 0 (multiplier λ2, coefficient r in the θ-row):
//   θ: d/dt(m (r² + α²) θ̇) = −m g α + λ2 r,   r: m r̈ − m r θ̇² = 0,   ν: m α θ̈ = −m g + λ1;
// with θ̇ = −h/r the r-row is the second-order ODE r̈ = h²/r, θ follows from θ̇ = −h/r, and
//   θ̈ = −ḣ/r + h ṙ/r²,   λ2 = (m (2 r ṙ θ̇ + (r² + α²) θ̈) + m g α)/r,   λ1 = m (α θ̈ + g);
// the constraint force is F_c = λ1 a³ + λ2 r a¹ = λ1 E3 + (λ2 − α λ1/r) e_θ (no e_r part).
// State (r, ṙ, θ).
struct SteeredHelicoid {
  double m, g, alpha, h0, h1, w;
  double h(double t) const { return -(h0 + h1 * std::sin(w * t)); }
  double hdot(double t) const { return -h1 * w * std::cos(w * t); }
  std::array<double, 3> rates(double t, const std::array<double, 3>& s) const {
    return {s[1], h(t) * h(t) / s[0], -h(t) / s[0]};
  }
};

// Exercise 3.5 (c): r(t), ṙ(t), θ(t), θ̇(t) of the run against the hand-reduced r̈ = h²/r,
// θ̇ = −h/r above by RK4 (h = 1e-4 s); the multipliers λ1 (helicoid), λ2 (steer) and the
// constraint force m a − F (the run's P.constraint_force, from its acceleration) against the hand
// formulas on that RK4 solution.
TEST(Helicoid, PartCWithTheConstraintRThetaDotPlusHAgainstHandReducedEquationsByRk4) {
  const test::ModelRun run = test::run_system(parse_model(kSteeredHelicoid, "steered.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const SteeredHelicoid p{run.parameter("m"),  run.parameter("g"),  run.parameter("alpha"),
                          run.parameter("h0"), run.parameter("h1"), run.parameter("w")};
  const double m = p.m, alpha = p.alpha;
  std::array<double, 3> s{run.at(0, "r"), run.at(0, "der(r)"), run.at(0, "theta")};
  double t = 0, motion_error = 0, multiplier_error = 0, force_error = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, 100,
                  [&p](double tau, const std::array<double, 3>& q) { return p.rates(tau, q); });
    t = t1;
    const double r = s[0], rdot = s[1], thetadot = -p.h(t) / r;
    motion_error = std::max(
        {motion_error, std::abs(run.at(k, "r") - r), std::abs(run.at(k, "der(r)") - rdot),
         std::abs(run.at(k, "theta") - s[2]), std::abs(run.at(k, "der(theta)") - thetadot)});
    const double thetaddot = -p.hdot(t) / r + p.h(t) * rdot / (r * r);
    const double lambda2 =
        (m * (2 * r * rdot * thetadot + (r * r + alpha * alpha) * thetaddot) + m * p.g * alpha) / r;
    const double lambda1 = m * (alpha * thetaddot + p.g);
    multiplier_error = std::max({multiplier_error, std::abs(run.at(k, "lambda(steer)") - lambda2),
                                 std::abs(run.at(k, "lambda(helicoid)") - lambda1)});
    force_error = std::max({force_error, std::abs(run.at(k, "Fr")),
                            std::abs(run.at(k, "Ftheta") - (lambda2 - alpha * lambda1 / r)),
                            std::abs(run.at(k, "Fz") - lambda1)});
  }
  EXPECT_GT(s[0], 2.0) << "r must grow (r̈ = h²/r > 0) for the comparison to mean anything";
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 3 s
  EXPECT_LT(motion_error, 1e-9);
  EXPECT_LT(multiplier_error, 1e-8);
  EXPECT_LT(force_error, 1e-8);
  std::printf("Ex. 3.5(c) over 3 s: motion %.3g, multipliers %.3g N, constraint force %.3g N\n",
              motion_error, multiplier_error, force_error);
}

}  // namespace
}  // namespace unidyn
