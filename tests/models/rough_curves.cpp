// Coulomb friction on a curve (book §2.6, §3.8): the friction takes the normal force of both
// constraints that make the curve, |N| = |λ1 g1 + λ2 g2|. models/rough-circle.yaml and
// models/rough-helix.yaml against closed forms and quadratures of the one-degree-of-freedom
// equation along the curve, m s̈ = F · t − μ_d |N| sgn ṡ with |N|² = (m κ ṡ²)² + |F_n|².
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

using test::ModelRun;
using test::run_model;

// ∫_a^b f by Simpson's rule on n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n = 4000) {
  const double h = (b - a) / n;
  double sum = f(a) + f(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * f(a + i * h);
  return sum * h / 3;
}

// The time of the phase that says `what`.
double phase_time(const ModelRun& run, const std::string& what) {
  for (const auto& phase : run.summary.phases) {
    if (phase.what == what) return phase.t;
  }
  ADD_FAILURE() << "no phase '" << what << "'";
  return NAN;
}

// §2.6: on the horizontal circle r = L, z = 0 under gravity −g E3, N = −m L θ̇² e_r + m g E3, so
// m L θ̈ = −μ_d m √(L² θ̇⁴ + g²) while θ̇ > 0: without gravity θ̇ = ω0/(1 + μ_d ω0 t) exactly.
TEST(RoughCircle, WithoutGravityTheSpinDecaysAsOneOverTime) {
  const ModelRun run = run_model("rough-circle", {{"g", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_EQ(run.summary.phases.size(), 1u) << "it slows down for ever";
  const double mu = 0.3, omega0 = 10;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "der(theta)"), omega0 / (1 + mu * omega0 * t), 1e-8 * omega0) << t;
  }
}

// With gravity it stops at T = ∫_0^ω0 L dω / (μ_d √(L² ω⁴ + g²)) and stays (nothing pushes it
// along the circle); while it slides, the friction is the book's μ_d √(λ1² + λ2²) (g1 = e_r,
// g2 = E3 are unit vectors).
TEST(RoughCircle, StopsWhenTheQuadratureSaysAndTheFrictionIsTheBooks) {
  const ModelRun run = run_model("rough-circle");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 0.2, g = 9.81, L = 0.5, mu = 0.3, omega0 = 10;
  const double stop = simpson(
      [&](double w) { return L / (mu * std::sqrt(L * L * w * w * w * w + g * g)); }, 0, omega0);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_NEAR(phase_time(run, "contact 'ring' sticks"), stop, 1e-8);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), thetadot = run.at(i, "der(theta)");
    const double lambda1 = run.at(i, "lambda(ring)"), lambda2 = run.at(i, "lambda(plane)");
    EXPECT_NEAR(lambda2, m * g, 1e-9) << t;
    if (t < stop - 1e-9) {
      EXPECT_NEAR(lambda1, -m * L * thetadot * thetadot, 1e-8) << t;
      EXPECT_NEAR(run.at(i, "friction"), -mu * std::hypot(lambda1, lambda2), 1e-9) << t;
    } else if (t > stop + 1e-9) {
      EXPECT_NEAR(thetadot, 0, 1e-12) << t;
      EXPECT_NEAR(run.at(i, "friction"), 0, 1e-9) << t;
    }
  }
}

// A circle in a vertical plane, gravity −g E2 in it: λ2 = 0, λ1 = m g sin θ − m L θ̇², so the
// normal force changes sign as the bead passes the top, and
// θ̈ = −(g/L) cos θ − μ_d |g sin θ − L θ̇²| sgn θ̇ / L (by RK4 here, with a step of 1e-5 s, on
// the output grid, up to before the bead first stops).
TEST(RoughCircle, NormalForceChangingSignOnAVerticalCircle) {
  const std::string text =
      "unidyn: 1\n"
      "parameters: {m: 0.2, g: 9.81, L: 0.5, mu_d: 0.2}\n"
      "coordinates: [r, theta, z]\n"
      "particles:\n"
      "  P: {mass: m, position: [r*cos(theta), r*sin(theta), z]}\n"
      "forces:\n"
      "  - gravity: -g*E2\n"
      "constraints:\n"
      "  - {name: ring, position: r - L, friction: {on: P, dynamic: mu_d, with: [plane]}}\n"
      "  - {name: plane, position: z}\n"
      "initial: {r: L, z: 0, theta: -1.5707963267948966, der(theta): 12}\n"
      "simulate: {t_end: 0.5, output_step: 0.01, rtol: 1e-11}\n";
  const ModelRun full = test::run_system(parse_model(text, "vertical-circle.yaml"));
  ASSERT_TRUE(full.summary.ok) << full.summary.message;
  const ModelRun run = full.on_grid(0.01);
  const double g = 9.81, L = 0.5, mu = 0.2, h = 1e-5;
  const auto rate = [&](double theta, double w) {
    return -g / L * std::cos(theta) -
           mu * std::abs(g * std::sin(theta) - L * w * w) * (w > 0 ? 1 : -1) / L;
  };
  double theta = -std::numbers::pi / 2, w = 12, t = 0;
  bool flipped = false;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    // RK4 of (θ, θ̇) up to the row's time
    while (t < run.at(i, "t") - h / 2) {
      const double k1t = w, k1w = rate(theta, w);
      const double k2t = w + h / 2 * k1w, k2w = rate(theta + h / 2 * k1t, w + h / 2 * k1w);
      const double k3t = w + h / 2 * k2w, k3w = rate(theta + h / 2 * k2t, w + h / 2 * k2w);
      const double k4t = w + h * k3w, k4w = rate(theta + h * k3t, w + h * k3w);
      theta += h / 6 * (k1t + 2 * k2t + 2 * k3t + k4t);
      w += h / 6 * (k1w + 2 * k2w + 2 * k3w + k4w);
      t += h;
    }
    EXPECT_NEAR(run.at(i, "theta"), theta, 1e-7) << t;
    EXPECT_NEAR(run.at(i, "der(theta)"), w, 1e-6) << t;
    const double lambda = run.at(i, "lambda(ring)");
    EXPECT_NEAR(lambda, 0.2 * (g * std::sin(theta) - L * w * w), 1e-6) << t;
    flipped = flipped || lambda > 0;
  }
  EXPECT_TRUE(flipped) << "the normal force must change sign for this test to mean anything";
}

struct Helix {
  double m = 1.5, g = 9.81, R = 0.8, alpha = 0.3, mu_d = 0.2;
  // θ̈ = −gα/(R(1 + α²)) − μ_d √(R² θ̇⁴ + g²/(1 + α²)) sgn θ̇ / (R √(1 + α²)), the motion along
  // the helix (s = R √(1 + α²) θ, κ = 1/(R(1 + α²)), gravity's normal part m g/√(1 + α²))
  double deceleration(double w) const {
    return g * alpha / (R * (1 + alpha * alpha)) +
           mu_d * std::sqrt(R * R * w * w * w * w + g * g / (1 + alpha * alpha)) /
               (R * std::sqrt(1 + alpha * alpha));
  }
};

// §3.8: thrown up the helix at θ̇ = 4 it stops at T = ∫ dω/θ̈, θ = ∫ ω dω/θ̈, and with
// μ_s = 0.4 ≥ α it sticks there, friction holding m g α/√(1 + α²) against m g/√(1 + α²) normal.
// While it slides the friction is μ_d times the whole normal force, which is also |λ1 ã² + λ2 ã³|
// with the book's ã² = e_r, ã³ = E3 − αθ e_r − α e_θ.
TEST(RoughHelix, StopsWhereTheQuadratureSaysAndSticks) {
  const ModelRun run = run_model("rough-helix");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Helix h;
  const double omega0 = 4;
  const double stop = simpson([&](double w) { return 1 / h.deceleration(w); }, 0, omega0);
  const double reach = simpson([&](double w) { return w / h.deceleration(w); }, 0, omega0);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_NEAR(phase_time(run, "contact 'cylinder' sticks"), stop, 1e-8);
  const double a = std::sqrt(1 + h.alpha * h.alpha);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), theta = run.at(i, "theta");
    const double friction = run.at(i, "friction"), normal = run.at(i, "normal");
    if (t < stop - 1e-9) {
      EXPECT_NEAR(friction, -h.mu_d * normal, 1e-9 * normal) << t;
      const double l1 = run.at(i, "lambda(cylinder)"), l2 = run.at(i, "lambda(helicoid)");
      const double book =
          std::sqrt(std::pow(l1 - h.alpha * theta * l2, 2) + std::pow(h.alpha * l2, 2) + l2 * l2);
      EXPECT_NEAR(book, normal, 1e-9 * normal) << t;
    } else if (t > stop + 1e-9) {
      EXPECT_NEAR(theta, reach, 1e-8) << t;
      EXPECT_NEAR(friction, h.m * h.g * h.alpha / a, 1e-9) << t;
      EXPECT_NEAR(normal, h.m * h.g / a, 1e-9) << t;
    }
  }
}

// With μ_s < α it slides back down, and friction growing with the normal force (θ̇⁴) brings it to
// the spin where they balance: R² θ̇⁴ = g² (α² − μ_d²) / (μ_d² (1 + α²)).
TEST(RoughHelix, SlidesBackDownToTheSpinWhereFrictionBalancesGravity) {
  const ModelRun run =
      run_model("rough-helix", {{"mu_s", 0.25}}, [](SimulationOptions& o) { o.t_end = 25; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Helix h;
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what,
            "contact 'cylinder' slides on (static friction too weak to hold it)");
  const double terminal = -std::pow(h.g * h.g * (h.alpha * h.alpha - h.mu_d * h.mu_d) /
                                        (h.mu_d * h.mu_d * (1 + h.alpha * h.alpha) * h.R * h.R),
                                    0.25);
  EXPECT_NEAR(run.rows.back()[run.index("der(theta)")], terminal, 1e-7 * std::abs(terminal));
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double normal = run.at(i, "normal");
    const double sign = run.at(i, "der(theta)") > 0 ? -1.0 : 1.0;
    if (std::abs(run.at(i, "der(theta)")) > 1e-9) {
      EXPECT_NEAR(run.at(i, "friction"), sign * h.mu_d * normal, 1e-9 * normal) << run.at(i, "t");
    }
  }
}

}  // namespace
}  // namespace unidyn
