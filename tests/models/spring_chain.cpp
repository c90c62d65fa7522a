// Validation of models/spring-chain.yaml against §5.2 (two masses and two springs on a smooth
// plane, (5.1)–(5.2)): the equations m1ẍ1 = −K1x1 − K2(x1 − x2), m2ẍ2 = −K2(x2 − x1) are linear, so
// the motion is exactly a superposition of the two normal modes of K v = ω² M v; the plane's normal
// forces are the weights; E = T̃ + Ũ is conserved. Then the chain driven, smooth or rough, with the
// extra constraint ẋ1 x2 − ẋ2 = 0 (model text here), against RK4 of its hand-reduced equations.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <array>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "support/eigen_solvers.hpp"
#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::record;

struct Parameters {
  double m1, m2, K1, K2, g;
};

// The model's defaults.
constexpr Parameters kDefault{1.0, 2.0, 10.0, 5.0, 9.81};

// The normal modes: K v = ω² M v with K = [[K1+K2, −K2], [−K2, K2]], M = diag(m1, m2); ω²
// ascending, the modes in the columns.
test::SymmetricEigen normal_modes(const Parameters& p) {
  Eigen::Matrix2d K, M;
  K << p.K1 + p.K2, -p.K2, -p.K2, p.K2;
  M << p.m1, 0.0, 0.0, p.m2;
  return test::generalized_symmetric_eigen(K, M);
}

std::vector<std::pair<std::string, double>> parameter_overrides(const Parameters& p) {
  return {{"m1", p.m1}, {"m2", p.m2}, {"K1", p.K1}, {"K2", p.K2}, {"g", p.g}};
}

// x(t) = Σ_k c_k v_k cos ω_k t for x(0) = Σ c_k v_k, ẋ(0) = 0; returns max |x_row − x(t)| over the
// rows.
double deviation_from_modes(const test::ModelRun& run, const Eigen::Matrix2d& shapes,
                            const Eigen::Vector2d& omega, const Eigen::Vector2d& c) {
  double worst = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const Eigen::Vector2d x =
        shapes * Eigen::Vector2d(c[0] * std::cos(omega[0] * t), c[1] * std::cos(omega[1] * t));
    worst = std::max({worst, std::abs(run.at(i, "x1") - x[0]), std::abs(run.at(i, "x2") - x[1])});
  }
  return worst;
}

const test::ModelRun& default_run() {
  // about one period of the slow mode (≈ 5 s) and five of the fast one (≈ 1.6 s)
  static const test::ModelRun run =
      test::run_model("spring-chain", {}, [](SimulationOptions& o) { o.t_end = 8.0; });
  return run;
}

// The tests below assume the model file's parameter values.
TEST(SpringChain, ModelFileParameters) {
  const System system = load_model(test::model_path("spring-chain"));
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  EXPECT_EQ(value("m1"), kDefault.m1);
  EXPECT_EQ(value("m2"), kDefault.m2);
  EXPECT_EQ(value("K1"), kDefault.K1);
  EXPECT_EQ(value("K2"), kDefault.K2);
  EXPECT_EQ(value("g"), kDefault.g);
}

// §5.2 normal modes (the notes' §4.2): started in a mode, each mass moves as A v cos ωt, for the
// model's parameters and for m1 = m2, K1 = K2 where ω² = (3 ∓ √5)/2 · K/m and x1 : x2 = (√5 − 1)/2
// : 1 and −(√5 + 1)/2 : 1.
TEST(SpringChain, NormalModes) {
  // the equal chain: the generalised eigenproblem against the closed form
  const Parameters equal{1.5, 1.5, 6.0, 6.0, 9.81};
  const auto equal_modes = normal_modes(equal);
  ASSERT_EQ(equal_modes.info(), Eigen::Success);
  const double unit = equal.K1 / equal.m1;
  EXPECT_NEAR(equal_modes.eigenvalues()[0], (3.0 - std::sqrt(5.0)) / 2.0 * unit, 1e-13 * unit);
  EXPECT_NEAR(equal_modes.eigenvalues()[1], (3.0 + std::sqrt(5.0)) / 2.0 * unit, 1e-13 * unit);
  const Eigen::Matrix2d v = equal_modes.eigenvectors();
  EXPECT_NEAR(v(0, 0) / v(1, 0), (std::sqrt(5.0) - 1.0) / 2.0, 1e-13);
  EXPECT_NEAR(v(0, 1) / v(1, 1), -(std::sqrt(5.0) + 1.0) / 2.0, 1e-13);

  for (const Parameters& p : {kDefault, equal}) {
    const auto modes = normal_modes(p);
    ASSERT_EQ(modes.info(), Eigen::Success);
    const Eigen::Vector2d omega = modes.eigenvalues().cwiseSqrt();
    for (Eigen::Index k = 0; k < 2; ++k) {
      // amplitude 0.1 on x1, as in the model
      const Eigen::Vector2d shape = modes.eigenvectors().col(k) / modes.eigenvectors()(0, k);
      auto overrides = parameter_overrides(p);
      overrides.insert(
          overrides.end(),
          {{"x1", 0.1 * shape[0]}, {"x2", 0.1 * shape[1]}, {"der(x1)", 0.0}, {"der(x2)", 0.0}});
      const double t_end = 2 * kPi / omega[k];  // one period
      const auto run = test::run_model("spring-chain", overrides,
                                       [&](SimulationOptions& options) { options.t_end = t_end; });
      ASSERT_TRUE(run.summary.ok) << run.summary.message;
      Eigen::Matrix2d shapes = Eigen::Matrix2d::Zero();
      shapes.col(k) = shape;
      Eigen::Vector2d c = Eigen::Vector2d::Zero();
      c[k] = 0.1;
      const double error = deviation_from_modes(run, shapes, omega, c);
      // the equations are linear: the only error is the integration's, rtol 1e-12 on 0.1 over
      // ~10³ steps
      EXPECT_LT(error, 1e-10) << "mode " << k << ", ω = " << omega[k];
      record("mode_error_" + std::to_string(k) + (p.m1 == p.m2 ? "_equal" : "_model"), error);
    }
  }
}

// §5.2 the general solution: the model's initial state (x1, x2) = (0.1, −0.05) at rest is a
// superposition of both modes, x(t) = Σ c_k v_k cos ω_k t, at every row.
TEST(SpringChain, GeneralSolutionIsASuperpositionOfModes) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.at(0, "x1"), 0.1);
  ASSERT_EQ(run.at(0, "x2"), -0.05);
  const auto modes = normal_modes(kDefault);
  const Eigen::Vector2d omega = modes.eigenvalues().cwiseSqrt();
  const Eigen::Vector2d c = modes.eigenvectors().fullPivLu().solve(Eigen::Vector2d(0.1, -0.05));
  // both modes take part
  EXPECT_GT(std::abs(c[0] * modes.eigenvectors()(0, 0)), 1e-2);
  EXPECT_GT(std::abs(c[1] * modes.eigenvectors()(0, 1)), 1e-2);
  const double error = deviation_from_modes(run, modes.eigenvectors(), omega, c);
  // five periods of the fast mode at rtol 1e-12
  EXPECT_LT(error, 1e-9);
  record("superposition_error", error);
}

// §5.2 (5.5) without friction: the normal forces are the weights, λ(plane_y1) = m1 g,
// λ(plane_y2) = m2 g (R = λ E2 on each particle), and nothing pushes along E3.
TEST(SpringChain, NormalForcesAreTheWeights) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m1g = kDefault.m1 * kDefault.g, m2g = kDefault.m2 * kDefault.g;
  double error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    error = std::max({error, std::abs(run.at(i, "lambda(plane_y1)") - m1g) / m1g,
                      std::abs(run.at(i, "lambda(plane_y2)") - m2g) / m2g,
                      std::abs(run.at(i, "lambda(plane_z1)")) / m1g,
                      std::abs(run.at(i, "lambda(plane_z2)")) / m2g});
  }
  // the springs act along E1 only: round-off of the multipliers' solve
  EXPECT_LT(error, 1e-13);
  record("normal_force_relative_error", error);
}

// (5.1) E = T̃ + Ũ = ½m1ẋ1² + ½m2ẋ2² + ½K1x1² + ½K2(x2 − x1)² is conserved and is the energy column.
TEST(SpringChain, EnergyConserved) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Parameters& p = kDefault;
  const auto E = [&](std::size_t i) {
    const double x1 = run.at(i, "x1"), x2 = run.at(i, "x2");
    const double v1 = run.at(i, "der(x1)"), v2 = run.at(i, "der(x2)");
    return 0.5 * p.m1 * v1 * v1 + 0.5 * p.m2 * v2 * v2 + 0.5 * p.K1 * x1 * x1 +
           0.5 * p.K2 * (x2 - x1) * (x2 - x1);
  };
  const double E0 = E(0);
  ASSERT_GT(E0, 0.0);
  double drift = 0.0, column_error = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    drift = std::max(drift, std::abs(E(i) - E0));
    column_error = std::max(column_error, std::abs(run.at(i, "energy") - E(i)));
  }
  // rtol 1e-12 per step over ~2·10³ steps
  EXPECT_LT(drift / E0, 1e-10);
  EXPECT_LT(column_error / E0, 1e-12);
  record("energy_relative_drift", drift / E0);
  record("accepted_steps", double(run.summary.stats.accepted_steps));
}

// §5.2 "imposing an integrable constraint" (the notes' §1.3): the chain of (5.5), driven by
// P cos ωt on m2 and on a table rough or smooth, with ẋ1 x2 − ẋ2 = 0 added; its force is μ5 x2 E1
// on m1 and −μ5 E1 on m2.
std::string constrained_chain(double mu_d) {
  std::ostringstream text;
  text << std::setprecision(17)
       << "unidyn: 1\n"
          "parameters: {m1: 1.0, m2: 2.0, K1: 10.0, K2: 5.0, L1: 1.0, L2: 1.0, g: 9.81, "
          "P: 1.5, w: 2.0, mu_d: "
       << mu_d
       << "}\n"
          "coordinates: [x1, x2, y1, y2, z1, z2]\n"
          "particles:\n"
          "  P1: {mass: m1, position: \"[L1 + x1, y1, z1]\"}\n"
          "  P2: {mass: m2, position: \"[L1 + L2 + x2, y2, z2]\"}\n"
          "forces:\n"
          "  - gravity: -g*E2\n"
          "  - spring: {from: [0, 0, 0], to: P1, stiffness: K1, rest_length: L1}\n"
          "  - spring: {from: P1, to: P2, stiffness: K2, rest_length: L2}\n"
          "  - force: {at: P2, value: \"[P*cos(w*t), 0, 0]\"}\n"
          "constraints:\n";
  if (mu_d > 0) {
    text << "  - {name: plane_y1, position: y1, friction: {on: P1, dynamic: mu_d}}\n"
            "  - {name: plane_y2, position: y2, friction: {on: P2, dynamic: mu_d}}\n";
  } else {
    text << "  - {name: plane_y1, position: y1}\n  - {name: plane_y2, position: y2}\n";
  }
  text << "  - {name: plane_z1, position: z1}\n"
          "  - {name: plane_z2, position: z2}\n"
          "  - {name: extra, velocity: der(x1)*x2 - der(x2)}\n"
          "initial: {x1: 0.3, x2: 0.5, der(x1): 1.2, der(x2): 0.6}\n"
          "simulate: {t_end: 10, output_step: 0.01, rtol: 1e-12}\n";
  return text.str();
}

// The equations of the notes' §1.3 with the multiplier eliminated by hand: with d_i = sgn ẋ_i,
// F1 = −K1 x1 − K2 (x1 − x2) − μ_d m1 g d1, F2 = −K2 (x2 − x1) + P cos ωt − μ_d m2 g d2,
//   m1 ẍ1 = F1 + μ5 x2,  m2 ẍ2 = F2 − μ5,  and ẍ2 = x2 ẍ1 + ẋ1 ẋ2 (the constraint differentiated)
// give μ5 (1/m2 + x2²/m1) = F2/m2 − x2 F1/m1 − ẋ1 ẋ2. State (x1, ẋ1, x2, ẋ2); the directions d_i
// are held through each RK4 step, and the step where ẋ1 (and with it ẋ2 = x2 ẋ1) turns through 0
// is bisected to the turn, where both directions reverse.
struct ConstrainedChain {
  double m1, m2, K1, K2, P, w, mu_d, g;
  std::array<double, 2> forces(double t, const std::array<double, 4>& s,
                               const std::array<double, 2>& d) const {
    return {-K1 * s[0] - K2 * (s[0] - s[2]) - mu_d * m1 * g * d[0],
            -K2 * (s[2] - s[0]) + P * std::cos(w * t) - mu_d * m2 * g * d[1]};
  }
  double multiplier(double t, const std::array<double, 4>& s,
                    const std::array<double, 2>& d) const {
    const auto F = forces(t, s, d);
    return (F[1] / m2 - s[2] * F[0] / m1 - s[1] * s[3]) / (1 / m2 + s[2] * s[2] / m1);
  }
  std::array<double, 4> rates(double t, const std::array<double, 4>& s,
                              const std::array<double, 2>& d) const {
    const auto F = forces(t, s, d);
    const double mu5 = multiplier(t, s, d);
    return {s[1], (F[0] + mu5 * s[2]) / m1, s[3], (F[1] - mu5) / m2};
  }
  std::array<double, 4> step(const std::array<double, 4>& s, double t, double h,
                             const std::array<double, 2>& d) const {
    auto add = [](std::array<double, 4> a, const std::array<double, 4>& k, double f) {
      for (int j = 0; j < 4; ++j) a[j] += f * k[j];
      return a;
    };
    const auto k1 = rates(t, s, d), k2 = rates(t + h / 2, add(s, k1, h / 2), d);
    const auto k3 = rates(t + h / 2, add(s, k2, h / 2), d), k4 = rates(t + h, add(s, k3, h), d);
    std::array<double, 4> out = s;
    for (int j = 0; j < 4; ++j) out[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    return out;
  }
};

struct ConstrainedChainRun {
  const ConstrainedChain& c;
  double t = 0;
  std::array<double, 4> s;
  std::array<double, 2> d;
  bool resting = false;
  std::vector<double> switches;  // the times the masses turned, came to rest or started again

  ConstrainedChainRun(const ConstrainedChain& chain, const std::array<double, 4>& s0)
      : c(chain), s(s0), d{s0[1] > 0 ? 1.0 : -1.0, s0[3] > 0 ? 1.0 : -1.0} {}
  // Whether both masses, at rest, can start along d1 (m2 along sgn x2 · d1, since ẋ2 = x2 ẋ1)
  // with both frictions against them: ẍ1 then points along d1.
  bool can_slide(double time, double d1) const {
    const std::array<double, 2> along{d1, s[2] > 0 ? d1 : -d1};
    return d1 * c.rates(time, s, along)[1] > 0;
  }
  void advance(double t_end, double h_max) {
    while (t < t_end - 1e-15) {
      const double h = std::min(h_max, t_end - t);
      if (resting) {
        start_from_rest(h);
        continue;
      }
      const std::array<double, 4> next = c.step(s, t, h, d);
      if (c.mu_d == 0 || d[0] * next[1] > 0) {
        s = next;
        t += h;
        continue;
      }
      double lo = 0, hi = h;
      for (int k = 0; k < 80 && hi - lo > 1e-15; ++k) {
        const double mid = (lo + hi) / 2;
        (d[0] * c.step(s, t, mid, d)[1] > 0 ? lo : hi) = mid;
      }
      s = c.step(s, t, hi, d);
      t += hi;
      s[1] = s[3] = 0;  // both at rest for an instant (ẋ2 = x2 ẋ1): back the other way, or rest
      switches.push_back(t);
      if (can_slide(t, -d[0])) {
        d = {-d[0], s[2] > 0 ? -d[0] : d[0]};
      } else {
        resting = true;
      }
    }
  }
  // At rest through the next h unless sliding one way becomes consistent: then from there (the
  // instant bisected).
  void start_from_rest(double h) {
    const auto starts = [&](double time) { return can_slide(time, 1) || can_slide(time, -1); };
    if (!starts(t + h)) {
      t += h;
      return;
    }
    double lo = 0, hi = h;
    for (int k = 0; k < 80 && hi - lo > 1e-15; ++k) {
      const double mid = (lo + hi) / 2;
      (starts(t + mid) ? hi : lo) = mid;
    }
    t += hi;
    const double d1 = can_slide(t, 1) ? 1 : -1;
    d = {d1, s[2] > 0 ? d1 : -d1};
    resting = false;
    switches.push_back(t);
  }
};

struct ChainComparison {
  std::size_t rows = 0;
  double t = 0, state = 0, multiplier = 0, normal = 0, x1_range = 0;
  std::vector<double> switches;  // the oracle's
};

// The run against the oracle from its first row to the last before t_until: the largest
// differences of (x1, ẋ1, x2, ẋ2), of λ(extra) − μ5 (while sliding, away from the turns, where the
// friction's direction is the row's own; at rest the split of the holding force between the
// frictions and the constraint is not unique) and of the normal forces from the weights.
ChainComparison compare_with_oracle(const test::ModelRun& run, const ConstrainedChain& chain,
                                    double t_until) {
  ConstrainedChainRun oracle(
      chain, {run.at(0, "x1"), run.at(0, "der(x1)"), run.at(0, "x2"), run.at(0, "der(x2)")});
  ChainComparison result;
  double lowest = 1e300, highest = -1e300;
  for (std::size_t i = 1; i < run.rows.size() && run.at(i, "t") < t_until - 1e-9; ++i) {
    oracle.advance(run.at(i, "t"), 1e-4);
    const auto& s = oracle.s;
    result.state = std::max(
        {result.state, std::abs(run.at(i, "x1") - s[0]), std::abs(run.at(i, "der(x1)") - s[1]),
         std::abs(run.at(i, "x2") - s[2]), std::abs(run.at(i, "der(x2)") - s[3])});
    if (!oracle.resting && std::abs(s[1]) > 1e-6) {
      result.multiplier =
          std::max(result.multiplier,
                   std::abs(run.at(i, "lambda(extra)") - chain.multiplier(oracle.t, s, oracle.d)));
    }
    result.normal =
        std::max({result.normal, std::abs(run.at(i, "lambda(plane_y1)") - chain.m1 * chain.g),
                  std::abs(run.at(i, "lambda(plane_y2)") - chain.m2 * chain.g)});
    lowest = std::min(lowest, s[0]);
    highest = std::max(highest, s[0]);
    result.t = oracle.t;
    ++result.rows;
  }
  result.x1_range = highest - lowest;
  result.switches = oracle.switches;
  return result;
}

ConstrainedChain chain_of(const test::ModelRun& run, double mu_d) {
  return {run.parameter("m1"),
          run.parameter("m2"),
          run.parameter("K1"),
          run.parameter("K2"),
          run.parameter("P"),
          run.parameter("w"),
          mu_d,
          run.parameter("g")};
}

// The run's events after the start.
std::vector<SimulationSummary::Phase> events_of(const test::ModelRun& run) {
  std::vector<SimulationSummary::Phase> events;
  for (const auto& phase : run.summary.phases) {
    if (phase.t > 0) events.push_back(phase);
  }
  return events;
}

// §5.2, the chain with ẋ1 x2 − ẋ2 = 0: (i) the constraint is integrable with the factor 1/x2, so
// x2 e^{−x1} keeps its initial value along the run (the notes' appendix), smooth and rough, over
// the whole run; (ii) x1, x2, ẋ1, ẋ2 and the multiplier λ(extra) = μ5 agree with the equations
// above integrated here by RK4 (h = 1e-4): smooth (μ_d = 0) over the run's 10 s, rough (μ_d = 0.1)
// up to the first stop, where both masses halt together (ẋ2 = x2 ẋ1). The normal forces are the
// weights.
TEST(SpringChain, ExtraConstraintKeepsX2ExpMinusX1AndMatchesRk4) {
  for (const double mu_d : {0.0, 0.1}) {
    const test::ModelRun run = test::run_system(parse_model(constrained_chain(mu_d), "extra.yaml"));
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const auto events = events_of(run);
    ASSERT_EQ(events.empty(), mu_d == 0);
    const double t_until = mu_d > 0 ? events[0].t : 1e300;
    const ChainComparison error = compare_with_oracle(run, chain_of(run, mu_d), t_until);
    EXPECT_TRUE(error.switches.empty());
    const double invariant = run.at(0, "x2") * std::exp(-run.at(0, "x1"));
    double invariant_error = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      invariant_error = std::max(
          invariant_error, std::abs(run.at(i, "x2") * std::exp(-run.at(i, "x1")) - invariant));
    }
    EXPECT_GT(error.rows, 30u);
    EXPECT_GT(error.x1_range, mu_d > 0 ? 0.2 : 0.5);  // it moves: x2 changes by e^{Δx1}
    // rtol 1e-12 per step: x2 e^{−x1} (≈ 0.37) to round-off of the steps
    EXPECT_LT(invariant_error, 1e-10);
    // RK4 at h = 1e-4 against the run at rtol 1e-12
    EXPECT_LT(error.state, 1e-9);
    EXPECT_LT(error.multiplier, 1e-8);
    EXPECT_LT(error.normal, 1e-9);
    std::printf(
        "ẋ1 x2 − ẋ2 = 0, μ_d = %g, to t = %.4g (%zu rows): x2 e^-x1 drift %.3g over the run; RK4 "
        "vs model: state %.3g, μ5 %.3g, normal forces %.3g\n",
        mu_d, error.t, error.rows, invariant_error, error.state, error.multiplier, error.normal);
  }
}

// The rough chain with ẋ1 x2 − ẋ2 = 0 over its 10 s: ẋ1 and ẋ2 = x2 ẋ1 reach 0 together, so both
// frictions, −μ_d m_i g sgn ẋ_i ((5.5) and the notes' §1.3), turn round at that instant (t ≈
// 0.349), or both masses rest (t ≈ 1.61) until sliding one way with both frictions against it is
// consistent (t ≈ 2.25). The run — its switches (the instants of its events), state and μ5 —
// against the RK4 of the §1.3 equations above, whose directions both reverse at each turn, and
// which rests and starts by that rule (the book gives no stick rule with the constraint; with
// μ_s = μ_d it is the one Coulomb's law leaves). Both contacts are at rest at once, and the
// stick rows of the two are dependent: unidyn decides them together (integrate/friction_phases).
TEST(SpringChain, ExtraConstraintRoughBothFrictionsTurnTogether) {
  const test::ModelRun run = test::run_system(parse_model(constrained_chain(0.1), "extra.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  std::vector<double> switches;
  for (const auto& event : events_of(run)) {
    if (switches.empty() || event.t != switches.back()) switches.push_back(event.t);
  }
  const ChainComparison error = compare_with_oracle(run, chain_of(run, 0.1), 1e300);
  ASSERT_EQ(switches.size(), error.switches.size());
  double switch_error = 0;
  for (std::size_t k = 0; k < switches.size(); ++k) {
    switch_error = std::max(switch_error, std::abs(switches[k] - error.switches[k]));
  }
  EXPECT_GE(switches.size(), 4u);  // a turn, a rest, a start, a rest
  EXPECT_GT(error.rows, 999u);
  // RK4 at h = 1e-4 and bisected switches against the run at rtol 1e-12
  EXPECT_LT(switch_error, 1e-9);
  EXPECT_LT(error.state, 1e-9);
  EXPECT_LT(error.multiplier, 1e-8);
  std::printf(
      "rough chain with ẋ1 x2 − ẋ2 = 0 to t = %.4g (%zu rows; %zu turns, rests and starts, at "
      "the RK4's to %.3g s): state %.3g, μ5 %.3g\n",
      error.t, error.rows, switches.size(), switch_error, error.state, error.multiplier);
}

}  // namespace
}  // namespace unidyn
