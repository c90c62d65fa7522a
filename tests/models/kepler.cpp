// Validation of models/kepler.yaml against the book's closed forms for the Kepler problem (§2.8,
// (2.6)–(2.18), Kepler's laws): the orbit is the conic (2.15) with e from (2.18) (with m³, the
// misprint corrected), its period is T = 2π a^{3/2}/√(GM), the time along it obeys Kepler's
// equation, E and H_O·E3 are constant, and the circular orbit (2.11)–(2.12) stays circular.
#include <gtest/gtest.h>

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include <fstream>
#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::record;

// The orbit's elements from the model's initial state, computed here from the book's formulas
// (the particle starts at θ = 0 with ṙ = 0, which is the pericentre when w0 r0 exceeds the circular
// speed).
struct Orbit {
  double GM, m, r0, w0;
  double energy;  // (2.17) E0 = (m/2) v·v − GMm/r
  double h;       // ĥ/m = r² θ̇
  double p;       // semi-latus rectum ĥ²/(GMm²)  (the book's r0 of (2.11), (2.15))
  double e;       // (2.18) with m³: E0 = G²M²m³/(2ĥ²)(e² − 1)
  double a;       // semi-major axis, a = −GMm/(2E)
  double period;  // T = 2π a^{3/2}/√(GM)
  double n;       // mean motion 2π/T
};

Orbit orbit(double G, double M, double m, double r0, double w0) {
  Orbit o{};
  o.GM = G * M;
  o.m = m;
  o.r0 = r0;
  o.w0 = w0;
  o.energy = 0.5 * m * r0 * r0 * w0 * w0 - o.GM * m / r0;
  o.h = r0 * r0 * w0;
  o.p = o.h * o.h / o.GM;
  const double hat_h = m * o.h;
  o.e = std::sqrt(1.0 + 2.0 * o.energy * hat_h * hat_h / (o.GM * o.GM * m * m * m));
  o.a = -o.GM * m / (2.0 * o.energy);
  o.period = 2.0 * kPi * std::pow(o.a, 1.5) / std::sqrt(o.GM);
  o.n = 2.0 * kPi / o.period;
  return o;
}

// The default parameters of kepler.yaml: G = M = 1, m = 0.001, r0 = 1, w0 = 1.2.
Orbit default_orbit() {
  return orbit(1.0, 1.0, 0.001, 1.0, 1.2);
}

const test::ModelRun& default_run() {
  static const test::ModelRun run = test::run_model("kepler");
  return run;
}

// Time since pericentre at true anomaly θ (any number of revolutions) by Kepler's equation:
// tan(E/2) = √((1−e)/(1+e)) tan(θ/2), n t = E − e sin E.
double kepler_time(const Orbit& o, double theta) {
  const double revolutions = std::floor((theta + kPi) / (2.0 * kPi));
  const double reduced = theta - 2.0 * kPi * revolutions;  // in [−π, π)
  const double E = 2.0 * std::atan2(std::sqrt(1.0 - o.e) * std::sin(reduced / 2.0),
                                    std::sqrt(1.0 + o.e) * std::cos(reduced / 2.0));
  return (E - o.e * std::sin(E) + 2.0 * kPi * revolutions) / o.n;
}

// The tests below assume the model file's parameter values.
TEST(Kepler, ModelFileParameters) {
  const System system = load_model(test::model_path("kepler"));
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  EXPECT_EQ(value("G"), 1.0);
  EXPECT_EQ(value("M"), 1.0);
  EXPECT_EQ(value("m"), 0.001);
  EXPECT_EQ(value("r0"), 1.0);
  EXPECT_EQ(value("w0"), 1.2);
}

// The oracle's own numbers agree with each other: e from (2.18) is the e that puts the starting
// point at the pericentre of (2.15), and a(1 − e²) = p.
TEST(Kepler, OrbitElementsAreConsistent) {
  const Orbit o = default_orbit();
  EXPECT_NEAR(o.p / (1.0 + o.e), o.r0, 1e-14);
  EXPECT_NEAR(o.a * (1.0 - o.e * o.e), o.p, 1e-14);
  EXPECT_NEAR(o.e, 0.44, 1e-14);
}

// Kepler's third law: T = 2π a^{3/2}/√(GM) with a = −GMm/(2E); after one period the particle is
// back at the pericentre, θ advanced by 2π.
TEST(Kepler, ReturnsAfterOnePeriod) {
  const Orbit o = default_orbit();
  const auto run =
      test::run_model("kepler", {}, [&](SimulationOptions& options) { options.t_end = o.period; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_EQ(run.at(last, "t"), o.period);
  // rtol 1e-12 over ~10³ steps leaves a global error of order 1e-10 in r and θ
  EXPECT_NEAR(run.at(last, "r"), o.r0, 1e-9);
  EXPECT_NEAR(run.at(last, "theta") - 2.0 * kPi, 0.0, 1e-9);
  EXPECT_NEAR(run.at(last, "der(r)"), 0.0, 1e-9);
  EXPECT_NEAR(run.at(last, "der(theta)"), o.w0, 1e-9);
  record("r_error", run.at(last, "r") - o.r0);
  record("theta_error", run.at(last, "theta") - 2.0 * kPi);
  // and not before: θ < 2π at the previous row
  EXPECT_LT(run.at(last - 1, "theta"), 2.0 * kPi);
}

// (2.15) Every point of the orbit lies on the conic r(θ) = p/(1 + e cos θ) (θ_p = 0 from (2.16)).
TEST(Kepler, OrbitIsTheConic) {
  const Orbit o = default_orbit();
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_GT(run.at(run.rows.size() - 1, "theta"), 2.0 * kPi);  // more than one revolution
  double worst = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double conic = o.p / (1.0 + o.e * std::cos(run.at(i, "theta")));
    worst = std::max(worst, std::abs(run.at(i, "r") - conic));
  }
  // the orbit's shape is fixed by E and H, which drift by ~1e-12 relative at rtol 1e-12
  EXPECT_LT(worst, 1e-10);
  record("max_conic_error", worst);
  record("accepted_steps", double(run.summary.stats.accepted_steps));
}

// (2.8), (2.17) E = T + U and H_O·E3 = m r² θ̇ keep their initial values (computed here from the
// initial state).
TEST(Kepler, EnergyAndAngularMomentumConserved) {
  const Orbit o = default_orbit();
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double H0 = o.m * o.h;
  double energy_error = 0.0, momentum_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    energy_error = std::max(energy_error, std::abs(run.at(i, "energy") - o.energy));
    momentum_error = std::max(momentum_error, std::abs(run.at(i, "H3") - H0));
    // the H3 column is m r² θ̇ of the row itself
    const double r = run.at(i, "r");
    EXPECT_NEAR(run.at(i, "H3"), o.m * r * r * run.at(i, "der(theta)"), 1e-15 * H0);
  }
  // relative to |E| ~ GMm/r: the local error per step is ≤ rtol, accumulated over ~10³ steps
  EXPECT_LT(energy_error / std::abs(o.energy), 1e-10);
  EXPECT_LT(momentum_error / H0, 1e-10);
  record("energy_relative_error", energy_error / std::abs(o.energy));
  record("H3_relative_error", momentum_error / H0);
}

// Kepler's equation: the time of flight from pericentre to θ is (E − e sin E)/n; in particular the
// apocentre θ = π is reached at T/2, where r = a(1 + e) and ṙ = 0.
TEST(Kepler, TimeOfFlightByKeplersEquation) {
  const Orbit o = default_orbit();
  const auto run = test::run_model(
      "kepler", {}, [&](SimulationOptions& options) { options.t_end = 0.5 * o.period; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_EQ(run.at(last, "t"), 0.5 * o.period);
  EXPECT_NEAR(run.at(last, "theta"), kPi, 1e-9);
  EXPECT_NEAR(run.at(last, "r"), o.a * (1.0 + o.e), 1e-9);
  EXPECT_NEAR(run.at(last, "der(r)"), 0.0, 1e-9);
  record("apocentre_theta_error", run.at(last, "theta") - kPi);
  record("apocentre_r_error", run.at(last, "r") - o.a * (1.0 + o.e));

  // at every row of the longer default run (more than a revolution)
  const auto& full = default_run();
  double worst = 0.0;
  for (std::size_t i = 0; i < full.rows.size(); ++i) {
    worst = std::max(worst, std::abs(kepler_time(o, full.at(i, "theta")) - full.at(i, "t")));
  }
  // a phase error δθ is a time error δθ/θ̇ with θ̇ ≥ h/r_apo² ≈ 0.18 s⁻¹; δθ ~ 2e-11 rad per
  // revolution at rtol 1e-12 (ReturnsAfterOnePeriod), so ≲ 1e-10 s
  EXPECT_LT(worst, 1e-9);
  record("max_kepler_time_error", worst);
}

// (2.11)–(2.12) With w0 = √(GM/r0³) the orbit is a circle traversed at the Kepler frequency.
TEST(Kepler, CircularOrbitStaysCircular) {
  const auto run = test::run_model("kepler", {{"G", 1.0}, {"M", 1.0}, {"r0", 1.0}, {"w0", 1.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double radius_error = 0.0, phase_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    radius_error = std::max(radius_error, std::abs(run.at(i, "r") - 1.0));
    phase_error = std::max(phase_error, std::abs(run.at(i, "theta") - run.at(i, "t")));
  }
  // r is neutrally stable (its perturbations oscillate at the orbital frequency, no growth): the
  // error stays at the per-step level
  EXPECT_LT(radius_error, 1e-11);
  EXPECT_LT(phase_error, 1e-9);
  record("max_radius_error", radius_error);
  record("max_phase_error", phase_error);
}

// §2.8: with no angular momentum (w0 = 0) the particle falls straight in and reaches the centre in
// finite time; r(t) of the radial fall from rest at r0 solves t = √(r0³/(2GM)) (√(x(1 − x)) +
// arccos √x), x = r/r0 (energy conservation, ṙ² = 2GM (1/r − 1/r0)): at r = r0/1000 the run,
// stopped there by a `stop_when`, ends at that time; θ stays 0.
TEST(Kepler, RadialFallWithoutAngularMomentum) {
  std::ifstream file(test::model_path("kepler"));
  std::stringstream text;
  text << file.rdbuf() << "stop_when: [r - r0/1000]\n";
  const test::ModelRun run =
      test::run_system(parse_model(text.str(), "kepler-fall.yaml"), {{"w0", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_TRUE(run.summary.stopped);
  const double GM = 1.0, r0 = 1.0, x = 1e-3;
  const double t_fall =
      std::sqrt(r0 * r0 * r0 / (2 * GM)) * (std::sqrt(x * (1 - x)) + std::acos(std::sqrt(x)));
  EXPECT_NEAR(run.summary.last_row_time, t_fall, 1e-9);
  EXPECT_LT(t_fall, kPi / 2 * std::sqrt(r0 * r0 * r0 / (2 * GM)));  // before the collision at r = 0
  for (std::size_t i = 0; i < run.rows.size(); ++i) EXPECT_EQ(run.at(i, "theta"), 0.0);
}

// Figs. 2.6, 2.8: from the pericentre r0 = 1 at speed w0 (G M = 1) the orbit is the conic
// r (1 + e cos θ) = p with p = w0², e = w0² − 1: the circle (the equilibrium (w, w') = (1, 0)) at
// w0 = 1, the parabola (e = 1) at w0 = √2 and a hyperbola (e = 1.5) at w0 = √2.5.
TEST(Kepler, CircleParabolaAndHyperbolaOfFigures26And28) {
  for (const double e : {0.0, 1.0, 1.5}) {
    const double w0 = std::sqrt(1 + e), p = w0 * w0;
    const test::ModelRun run =
        test::run_model("kepler", {{"w0", w0}}, [](SimulationOptions& o) { o.t_end = 5.0; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double r = run.at(i, "r"), theta = run.at(i, "theta");
      EXPECT_NEAR(r * (1 + e * std::cos(theta)), p, 1e-9)
          << "e = " << e << ", t = " << run.at(i, "t");
    }
    if (e >= 1) {
      EXPECT_GT(run.rows.back()[run.index("r")], 3.0) << e;  // escaping
    }
  }
}

}  // namespace
}  // namespace unidyn
