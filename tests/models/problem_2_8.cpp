// Problem 2.8: a particle under gravity −mg E3 held by the two constraints (2.34),
// (x E3 + E2)·v = 0 and E2·v + e(t) = 0, with the constraint force F_c = μ1 (x E3 + E2) + μ2 E2.
// The model is given here as text; its motion and multipliers are compared with the equations
// reduced by hand below, integrated here by RK4, and E = ½ m |v|² + m g z is shown to change by
// the work of F_c computed along that hand solution (part (c)).
#include <array>
#include <cmath>
#include <cstdio>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// e(t) = e0 cos ωt; x(0) = 1 and ẋ(0) = 0.5 keep x away from 0 (the first constraint's f = (0, 1,
// x) gives ż = e/x).
constexpr const char* kProblem28 = R"yaml(unidyn: 1
name: Problem 2.8
parameters: {m: 1.0, g: 9.81, e0: 0.8, w: 2.0}
coordinates: [x, y, z]
particles:
  P: {mass: m, position: [x, y, z]}
forces:
  - gravity: -g*E3
constraints:
  - {name: first, velocity: x*der(z) + der(y)}
  - {name: second, velocity: der(y) + e0*cos(w*t)}
initial: {x: 1.0, der(x): 0.5, der(y): -0.8, der(z): 0.8}
simulate: {t_end: 4, output_step: 0.01, rtol: 1e-12}
)yaml";

// By hand, from m a = −mg E3 + μ1 (x E3 + E2) + μ2 E2 and the constraints ẏ + x ż = 0, ẏ + e = 0:
//   x-row: m ẍ = 0, so ẋ = u constant;  the constraints: ẏ = −e(t), ż = e(t)/x;
//   then z̈ = ė/x − e u/x², ÿ = −ė, and the z- and y-rows give
//   μ1 = m (z̈ + g)/x,   μ2 = m ÿ − μ1 = −m ė − μ1.
// The power of F_c is F_c·v = μ1 (ẏ + x ż) + μ2 ẏ = −μ2 e: the first constraint's force does no
// work, the second (rheonomic, e ≠ 0) does. State (x, y, z, W) with W = ∫ F_c·v dt.
struct Problem28 {
  double m, g, e0, w, u;
  double e(double t) const { return e0 * std::cos(w * t); }
  double edot(double t) const { return -e0 * w * std::sin(w * t); }
  // (μ1, μ2) at time t and abscissa x
  std::array<double, 2> multipliers(double t, double x) const {
    const double zdd = edot(t) / x - e(t) * u / (x * x);
    const double mu1 = m * (zdd + g) / x;
    return {mu1, -m * edot(t) - mu1};
  }
  std::array<double, 4> rates(double t, const std::array<double, 4>& s) const {
    const double x = s[0], ydot = -e(t), zdot = e(t) / x;
    const auto [mu1, mu2] = multipliers(t, x);
    // F_c = (0, μ1 + μ2, μ1 x), v = (u, ẏ, ż)
    return {u, ydot, zdot, (mu1 + mu2) * ydot + mu1 * x * zdot};
  }
};

// Problem 2.8 (b), (c): the run's x, y, z and the multipliers μ1 = lambda(first), μ2 =
// lambda(second) against the hand-reduced equations above by RK4 (h = 1e-4 s); E(t) − E(0) from
// the run's rows against W(t) = ∫ F_c·v dt computed along the hand solution; E changes by more
// than 1 J (the second constraint moves: its force's power −μ2 e is not zero).
TEST(Problem28Motion, MotionMultipliersAndEnergyChangeAgainstHandReducedEquationsByRk4) {
  const test::ModelRun run = test::run_system(parse_model(kProblem28, "problem-2-8.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Problem28 p{run.parameter("m"), run.parameter("g"), run.parameter("e0"), run.parameter("w"),
                    run.at(0, "der(x)")};
  auto energy = [&](std::size_t k) {
    const double vx = run.at(k, "der(x)"), vy = run.at(k, "der(y)"), vz = run.at(k, "der(z)");
    return 0.5 * p.m * (vx * vx + vy * vy + vz * vz) + p.m * p.g * run.at(k, "z");
  };
  std::array<double, 4> s{run.at(0, "x"), run.at(0, "y"), run.at(0, "z"), 0.0};
  double t = 0, position_error = 0, rate_error = 0, multiplier_error = 0, work_error = 0;
  double largest_change = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, 100,
                  [&p](double tau, const std::array<double, 4>& q) { return p.rates(tau, q); });
    t = t1;
    position_error = std::max({position_error, std::abs(run.at(k, "x") - s[0]),
                               std::abs(run.at(k, "y") - s[1]), std::abs(run.at(k, "z") - s[2])});
    rate_error = std::max({rate_error, std::abs(run.at(k, "der(y)") + p.e(t)),
                           std::abs(run.at(k, "der(z)") - p.e(t) / s[0])});
    const auto [mu1, mu2] = p.multipliers(t, s[0]);
    multiplier_error = std::max({multiplier_error, std::abs(run.at(k, "lambda(first)") - mu1),
                                 std::abs(run.at(k, "lambda(second)") - mu2)});
    const double change = energy(k) - energy(0);
    work_error = std::max(work_error, std::abs(change - s[3]));
    largest_change = std::max(largest_change, std::abs(change));
    // the run's own energy column is the same E
    EXPECT_NEAR(run.at(k, "energy"), energy(k), 1e-12) << t;
  }
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 4 s
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(rate_error, 1e-9);
  EXPECT_LT(multiplier_error, 1e-8);
  EXPECT_LT(work_error, 1e-8);
  EXPECT_GT(largest_change, 1.0) << "E must change for the comparison to mean anything";
  std::printf(
      "RK4 vs model over 4 s: position %.3g m, rates %.3g m/s, multipliers %.3g N; "
      "|E - E0 - W| %.3g J with max |E - E0| %.3g J\n",
      position_error, rate_error, multiplier_error, work_error, largest_change);
}

}  // namespace
}  // namespace unidyn
