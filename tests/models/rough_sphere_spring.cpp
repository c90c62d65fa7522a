// Problem 2.7(a)–(g): a particle sliding inside a rough sphere, tied by a spring.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "support/rk4.hpp"

namespace unidyn {
namespace {

// While it slides, the constraint force's power is the friction's, −μ_d |N| |v| (the normal force
// does no work on the fixed sphere), so E = T + U (gravity and spring) decreases (2.7(g)).
TEST(RoughSphereSpring, FrictionTakesEnergyAtMuNv) {
  const double mu_d = 0.15;
  const test::ModelRun run = test::run_model("rough-sphere-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);  // it slides throughout
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double N = run.at(i, "N"), v = run.at(i, "speed");
    EXPECT_NEAR(run.at(i, "power"), -mu_d * N * v, 1e-11) << run.at(i, "t");
    EXPECT_GT(v, 0.1);
    if (i > 0) {
      EXPECT_LT(run.at(i, "E"), run.at(i - 1, "E")) << run.at(i, "t");
    }
  }
}

using Vec = std::array<double, 3>;

double dot(const Vec& u, const Vec& w) {
  return u[0] * w[0] + u[1] * w[1] + u[2] * w[2];
}

// The problem's data, read from the run (the model's parameters).
struct Data {
  double m, g, R0, K, L0, a, b, mu_d, mu_s;
  explicit Data(const test::ModelRun& run)
      : m(run.parameter("m")),
        g(run.parameter("g")),
        R0(run.parameter("R0")),
        K(run.parameter("K")),
        L0(run.parameter("L0")),
        a(run.parameter("a")),
        b(run.parameter("b")),
        mu_d(run.parameter("mu_d")),
        mu_s(run.parameter("mu_s")) {}
};

// The spherical basis at (φ, θ) (φ the polar angle from E3, θ the azimuth from E1) and the
// spring's x = R0 e_R − a E1 − b E2 with the factor K (‖x‖ − L0)/‖x‖ of its force −K(‖x‖ −
// L0)x/‖x‖.
struct Geometry {
  Vec eR, ephi, etheta, x;
  double tension_over_length;
  Geometry(const Data& d, double phi, double theta) {
    const double sp = std::sin(phi), cp = std::cos(phi), st = std::sin(theta), ct = std::cos(theta);
    eR = {sp * ct, sp * st, cp};
    ephi = {cp * ct, cp * st, -sp};
    etheta = {-st, ct, 0};
    x = {d.R0 * eR[0] - d.a, d.R0 * eR[1] - d.b, d.R0 * eR[2]};
    const double length = std::sqrt(dot(x, x));
    tension_over_length = d.K * (length - d.L0) / length;
  }
  Vec position(const Data& d) const { return {d.R0 * eR[0], d.R0 * eR[1], d.R0 * eR[2]}; }
};

// State (φ, φ̇, θ, θ̇).
using State = std::array<double, 4>;

// 2.7(e): N = N e_R with N = m g E3·e_R + K(‖x‖ − L0) x·e_R/‖x‖ − m R0 (φ̇² + sin²φ θ̇²), the e_R
// component of m a = −m g E3 − K(‖x‖ − L0) x/‖x‖ + N with a·e_R = −R0 (φ̇² + sin²φ θ̇²). (The
// reference's transcription of (e) puts a minus sign before (m g E3·e_R + K…); that contradicts the
// book's own (f) — F_c = m g E3 + K(‖x‖ − L0) x/‖x‖ at rest — and (i), N = m g cos φ − m v²/R0.)
double normal_force(const Data& d, const State& s) {
  const Geometry geo(d, s[0], s[2]);
  const double sp = std::sin(s[0]);
  return d.m * d.g * geo.eR[2] + geo.tension_over_length * dot(geo.x, geo.eR) -
         d.m * d.R0 * (s[1] * s[1] + sp * sp * s[3] * s[3]);
}

// 2.7(d), the sliding equations, solved for φ̈ and θ̈:
//   m R0 (φ̈ − sin φ cos φ θ̇²) = m g sin φ − K(‖x‖ − L0) x·e_φ/‖x‖ − μ_d |N| φ̇/s,
//   (1/(R0 sin φ)) d/dt(m R0² sin²φ θ̇) = m R0 (sin φ θ̈ + 2 cos φ φ̇ θ̇)
//                                    = −K(‖x‖ − L0) x·e_θ/‖x‖ − μ_d |N| sin φ θ̇/s,
// with s = √(φ̇² + sin²φ θ̇²) and N from (e).
State sliding_rates(const Data& d, const State& s) {
  const Geometry geo(d, s[0], s[2]);
  const double sp = std::sin(s[0]), cp = std::cos(s[0]);
  const double slip = std::sqrt(s[1] * s[1] + sp * sp * s[3] * s[3]);
  const double friction = d.mu_d * std::abs(normal_force(d, s)) / slip;
  const double phi_dd =
      sp * cp * s[3] * s[3] +
      (d.m * d.g * sp - geo.tension_over_length * dot(geo.x, geo.ephi) - friction * s[1]) /
          (d.m * d.R0);
  const double theta_dd =
      ((-geo.tension_over_length * dot(geo.x, geo.etheta) - friction * sp * s[3]) / (d.m * d.R0) -
       2 * cp * s[1] * s[3]) /
      sp;
  return {s[1], phi_dd, s[3], theta_dd};
}

// 2.7(d), (e), (g): the run (x, y, z with the sphere's multiplier, dopri5 at rtol 1e-12) against
// the book's sliding equations (d) in (φ, θ), integrated here by RK4 from the run's first row, with
// N from (e) computed here. Compared every 0.1 s over the 4 s (it slides throughout, |v| ≥ 1.6):
// the position R0 e_R(φ, θ) and velocity R0(φ̇ e_φ + sin φ θ̇ e_θ) with the run's; N with the
// run's normal force, R = λ ∂Ψ/∂r = 2λ r, i.e. N = 2 λ R0 (both signs occur: the spring pulls the
// particle off the wall when it is slow); E = ½ m v² + m g z + ½ K (‖x‖ − L0)² from the RK4 state
// with the run's E, and (g) Ė = −μ_d |N| |v| < 0 on the RK4 motion (central differences of its E).
TEST(RoughSphereSpring, SlidingAgreesWithTheBooksEquationsByRk4) {
  const test::ModelRun run = test::run_model("rough-sphere-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  ASSERT_EQ(run.summary.phases[0].what, "'sphere' slides");
  const Data d(run);
  const Vec r0{run.at(0, "x"), run.at(0, "y"), run.at(0, "z")};
  const Vec v0{run.at(0, "der(x)"), run.at(0, "der(y)"), run.at(0, "der(z)")};
  const double phi0 = std::atan2(std::hypot(r0[0], r0[1]), r0[2]),
               theta0 = std::atan2(r0[1], r0[0]);
  const Geometry geo0(d, phi0, theta0);
  State s{phi0, dot(v0, geo0.ephi) / d.R0, theta0, dot(v0, geo0.etheta) / (d.R0 * std::sin(phi0))};
  const auto energy = [&d](const State& u) {
    const Geometry geo(d, u[0], u[2]);
    const double sp = std::sin(u[0]), length = std::sqrt(dot(geo.x, geo.x));
    return d.m / 2 * d.R0 * d.R0 * (u[1] * u[1] + sp * sp * u[3] * u[3]) +
           d.m * d.g * d.R0 * geo.eR[2] + d.K / 2 * (length - d.L0) * (length - d.L0);
  };
  const auto rates = [&d](double, const State& u) { return sliding_rates(d, u); };
  const double h = 2.5e-5;  // RK4 step: 4000 steps between compared rows
  double position_error = 0, velocity_error = 0, normal_error = 0, energy_error = 0, rate_error = 0;
  double normal_min = 1e300, normal_max = -1e300, rate_max = -1e300;
  std::size_t compared = 0;
  for (std::size_t k = 0; k < run.rows.size(); k += 100) {
    if (k > 0) s = test::rk4(s, 0.0, 4000 * h, 4000, rates);
    ASSERT_NEAR(run.at(k, "t"), 1e-3 * static_cast<double>(k), 1e-12);
    const Geometry geo(d, s[0], s[2]);
    const Vec r = geo.position(d);
    const double sp = std::sin(s[0]);
    for (int j = 0; j < 3; ++j) {
      const std::string q(1, "xyz"[j]);
      const double v = d.R0 * (s[1] * geo.ephi[static_cast<std::size_t>(j)] +
                               sp * s[3] * geo.etheta[static_cast<std::size_t>(j)]);
      position_error =
          std::max(position_error, std::abs(run.at(k, q) - r[static_cast<std::size_t>(j)]));
      velocity_error = std::max(velocity_error, std::abs(run.at(k, "der(" + q + ")") - v));
    }
    const double N = normal_force(d, s);
    normal_error = std::max(normal_error, std::abs(2 * run.at(k, "lambda(sphere)") * d.R0 - N));
    normal_error = std::max(normal_error, std::abs(run.at(k, "N") - std::abs(N)));
    normal_min = std::min(normal_min, N);
    normal_max = std::max(normal_max, N);
    const double E = energy(s);
    energy_error = std::max(energy_error, std::abs(run.at(k, "E") - E));
    // (g): Ė by central differences of E along the RK4 motion (±10 steps) against −μ_d |N| |v|
    const double slip = std::sqrt(s[1] * s[1] + sp * sp * s[3] * s[3]);
    const double power = -d.mu_d * std::abs(N) * d.R0 * slip;
    const double Edot = (energy(test::rk4(s, 0.0, 10 * h, 10, rates)) -
                         energy(test::rk4(s, 0.0, -10 * h, 10, rates))) /
                        (20 * h);
    rate_error = std::max(rate_error, std::abs(Edot - power));
    rate_max = std::max(rate_max, Edot);
    ++compared;
  }
  EXPECT_EQ(compared, 41u);
  // both signs of N occur over the run, so |N| in the friction is tested on either side of 0
  EXPECT_LT(normal_min, -5.0);
  EXPECT_GT(normal_max, 2.0);
  // RK4 at h = 2.5e-5 s against a run at rtol 1e-12 over 4 s: the position differs by 1.5e-9,
  // 1.9e-10 and 5.7e-11 m at h = 1e-4, 5e-5 and 2.5e-5 s (RK4's h⁴ down to the run's own error)
  EXPECT_LT(position_error, 5e-10);
  EXPECT_LT(velocity_error, 2e-9);
  EXPECT_LT(normal_error, 1e-8);
  EXPECT_LT(energy_error, 5e-9);
  // central differences over ±0.25 ms: truncation error ~ (2.5e-4 s)² |E'''| / 6
  EXPECT_LT(rate_error, 2e-5);
  EXPECT_LT(rate_max, 0.0);  // (g): E falls at every compared time (Ė = 0 only where N = 0)
  std::printf(
      "2.7(d),(e) by RK4 vs model over 4 s: position %.3g m, velocity %.3g m/s, N %.3g N "
      "(N from %.3f to %.3f), E %.3g J; (g) Ė + μ_d|N||v| %.3g W, max Ė %.3f W\n",
      position_error, velocity_error, normal_error, normal_min, normal_max, energy_error,
      rate_error, rate_max);
}

// 2.7(f): at rest on the sphere F_c = m g E3 + K(‖x‖ − L0) x/‖x‖, whose normal part is
// N = (F_c·e_R) e_R and tangential part F_t = F_c − N; it stays at rest iff ‖F_t‖ ≤ μ_s ‖N‖.
struct AtRest {
  double normal;   // F_c·e_R
  Vec tangential;  // F_t
  double ratio;    // ‖F_t‖/|N|
};

AtRest at_rest(const Data& d, double phi, double theta) {
  const Geometry geo(d, phi, theta);
  Vec Fc{geo.tension_over_length * geo.x[0], geo.tension_over_length * geo.x[1],
         geo.tension_over_length * geo.x[2] + d.m * d.g};
  AtRest rest{dot(Fc, geo.eR), {}, 0};
  for (std::size_t j = 0; j < 3; ++j) rest.tangential[j] = Fc[j] - rest.normal * geo.eR[j];
  rest.ratio = std::sqrt(dot(rest.tangential, rest.tangential)) / std::abs(rest.normal);
  return rest;
}

// The run from rest at (φ, θ), 0.5 s.
test::ModelRun run_from_rest(const Data& d, double phi, double theta, double mu_s) {
  const double sp = std::sin(phi);
  return test::run_model("rough-sphere-spring",
                         {{"x", d.R0 * sp * std::cos(theta)},
                          {"y", d.R0 * sp * std::sin(theta)},
                          {"z", d.R0 * std::cos(phi)},
                          {"der(y)", 0.0},
                          {"mu_s", mu_s}},
                         [](SimulationOptions& options) {
                           options.t_end = 0.5;
                           options.output_step = 0.01;
                         });
}

// Expects the particle to stay at (φ, θ) with the sphere's force F_c of 2.7(f): N = 2 λ R0.
void expect_stays(const Data& d, double phi, double theta, double mu_s, double& normal_error) {
  const test::ModelRun run = run_from_rest(d, phi, theta, mu_s);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u) << phi << " " << theta;
  EXPECT_EQ(run.summary.phases[0].what, "contact 'sphere' sticks");
  const double N = at_rest(d, phi, theta).normal;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    EXPECT_NEAR(run.at(k, "x"), run.at(0, "x"), 1e-12);
    EXPECT_NEAR(run.at(k, "y"), run.at(0, "y"), 1e-12);
    EXPECT_NEAR(run.at(k, "z"), run.at(0, "z"), 1e-12);
    normal_error = std::max(normal_error, std::abs(2 * run.at(k, "lambda(sphere)") * d.R0 - N));
  }
}

// Expects it to slip at once, starting along the applied force's tangential part −F_t.
void expect_slides(const Data& d, double phi, double theta, double mu_s, double& cos_min) {
  const test::ModelRun run = run_from_rest(d, phi, theta, mu_s);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_GE(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what,
            "contact 'sphere' slides on (static friction too weak to hold it)")
      << phi << " " << theta;
  EXPECT_EQ(run.summary.phases[0].t, 0.0);
  ASSERT_NEAR(run.at(1, "t"), 0.01, 1e-12);
  const Vec dr{run.at(1, "x") - run.at(0, "x"), run.at(1, "y") - run.at(0, "y"),
               run.at(1, "z") - run.at(0, "z")};
  const Vec Ft = at_rest(d, phi, theta).tangential;
  const double c = -dot(dr, Ft) / std::sqrt(dot(dr, dr) * dot(Ft, Ft));
  cos_min = std::min(cos_min, c);
  EXPECT_GT(std::sqrt(dot(dr, dr)), 1e-6);
  EXPECT_GT(c, 0.99);
}

// 2.7(f): the static-friction condition ‖F_t‖ ≤ μ_s |N| with F_c from (f), computed here, against
// the run's decision at the start (it sticks or slips at once). On the meridian through A
// (θ = atan2(b, a)) the rest region with μ_s = 0.2 is an interval of φ around the equilibrium
// F_t = 0; its two ends, where ‖F_t‖ = μ_s |N|, are found here by bisection, and the particle is
// put at rest 0.001 rad inside (it stays, with N = 2 λ R0 as (f) gives) and 0.001 rad outside (it
// slips at once, along −F_t). At a point off that plane (φ, θ) = (2.8, 1) the threshold is tested
// in μ_s instead: μ_s = 1.005 and 0.995 times ‖F_t‖/|N|.
TEST(RoughSphereSpring, StaysAtRestWhereStaticFrictionHoldsIt) {
  const test::ModelRun probe =
      test::run_model("rough-sphere-spring", {}, [](SimulationOptions& o) { o.t_end = 0.001; });
  const Data d(probe);
  const double theta = std::atan2(d.b, d.a), mu_s = d.mu_s;
  const auto edge = [&](double lo, double hi) {  // ratio − μ_s changes sign on [lo, hi]
    const double sign_lo = at_rest(d, lo, theta).ratio - mu_s;
    EXPECT_LT(sign_lo * (at_rest(d, hi, theta).ratio - mu_s), 0.0);
    for (int i = 0; i < 60; ++i) {
      const double mid = (lo + hi) / 2;
      ((at_rest(d, mid, theta).ratio - mu_s) * sign_lo > 0 ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
  };
  const double upper = edge(2.70, 2.83), lower = edge(2.85, 3.0);  // the ratio is 0 near 2.838
  const double delta = 1e-3;
  double normal_error = 0, cos_min = 1;
  expect_stays(d, upper + delta, theta, mu_s, normal_error);
  expect_stays(d, lower - delta, theta, mu_s, normal_error);
  expect_slides(d, upper - delta, theta, mu_s, cos_min);
  expect_slides(d, lower + delta, theta, mu_s, cos_min);
  const double ratio_in = std::max(at_rest(d, upper + delta, theta).ratio,
                                   at_rest(d, lower - delta, theta).ratio),
               ratio_out = std::min(at_rest(d, upper - delta, theta).ratio,
                                    at_rest(d, lower + delta, theta).ratio);
  EXPECT_LT(ratio_in, mu_s);
  EXPECT_GT(ratio_out, mu_s);
  const double ratio = at_rest(d, 2.8, 1.0).ratio;
  EXPECT_GT(ratio, d.mu_d / 0.99);  // μ_s stays above μ_d
  expect_stays(d, 2.8, 1.0, 1.005 * ratio, normal_error);
  expect_slides(d, 2.8, 1.0, 0.995 * ratio, cos_min);
  EXPECT_LT(normal_error, 1e-10);
  std::printf(
      "2.7(f): rest interval φ ∈ [%.6f, %.6f] on θ = %.4f; ‖F_t‖/|N| %.4f inside, %.4f outside "
      "(μ_s = %.2f); at (2.8, 1) ‖F_t‖/|N| = %.4f; N at rest vs 2λR0 %.3g N; slip along −F_t "
      "cos ≥ %.6f\n",
      upper, lower, theta, ratio_in, ratio_out, mu_s, ratio, normal_error, cos_min);
}

}  // namespace
}  // namespace unidyn
