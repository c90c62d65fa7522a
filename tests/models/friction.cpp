// Coulomb friction with stick–slip (§2.11, (2.27)–(2.31)): a block on a rough incline, and the
// roller coaster, against closed forms and the book's equation of motion and stick intervals.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

constexpr double g = 9.81, pi = 3.14159265358979323846;

// Pushed up the slope at v0 = 2 the block decelerates at a = g (sin β + μ_d cos β) and stops at
// t* = v0/a, x* = −v0²/(2a); with tan β ≤ μ_s it stays, held by −m g sin β (2.30); with tan β > μ_s
// it slides back at g (sin β − μ_d cos β).
TEST(Friction, BlockOnAnIncline) {
  const double m = 2.0, mu_d = 0.25;
  for (const double beta : {0.2, 0.4}) {
    const test::ModelRun run = test::run_model("block-incline", {{"beta", beta}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const double a = g * (std::sin(beta) + mu_d * std::cos(beta)), t_stop = 2 / a;
    ASSERT_EQ(run.summary.phases.size(), 2u);
    EXPECT_EQ(run.summary.phases[0].what, "'plane' slides");
    EXPECT_NEAR(run.summary.phases[1].t, t_stop, 1e-10);
    const bool sticks = std::tan(beta) <= 0.3;
    EXPECT_EQ(run.summary.phases[1].what, sticks ? "contact 'plane' sticks"
                                                 : "contact 'plane' slides on (static friction "
                                                   "too weak to hold it)");
    const double down = g * (std::sin(beta) - mu_d * std::cos(beta));
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t");
      EXPECT_NEAR(run.at(i, "normal_force"), m * g * std::cos(beta), 1e-9) << t;
      if (t < t_stop) {
        EXPECT_NEAR(run.at(i, "der(x)"), -2 + a * t, 1e-9) << t;
        EXPECT_NEAR(run.at(i, "friction_force"), mu_d * m * g * std::cos(beta), 1e-9) << t;
      } else if (sticks) {
        EXPECT_NEAR(run.at(i, "x"), -2 * 2 / (2 * a), 1e-9) << t;
        EXPECT_NEAR(run.at(i, "friction_force"), -m * g * std::sin(beta), 1e-9) << t;
      } else {
        EXPECT_NEAR(run.at(i, "der(x)"), down * (t - t_stop), 1e-9) << t;
        EXPECT_NEAR(run.at(i, "friction_force"), -mu_d * m * g * std::cos(beta), 1e-9) << t;
      }
    }
  }
}

// (2.27) m ((1 + f'²) ẍ + f'' f' ẋ²) = −m g f' − μ_d √(1 + f'²) ‖N‖ sgn ẋ with (2.28)
// ‖N‖ = m |g + f'' ẋ²| / √(1 + f'²), f = A cos(π x/L0), holds along every sliding stretch; the cart
// comes to rest only where |f'| ≤ μ_s: |x − k| ≤ arcsin(μ_s L0/(π A))/π = 0.124755 (footnote 17).
TEST(Friction, RollerCoasterEquationAndStickIntervals) {
  const double m = 1.0, A = 0.25, mu_d = 0.1, mu_s = 0.3;
  const double half_width = std::asin(mu_s / (pi * A)) / pi;
  EXPECT_NEAR(half_width, 0.124755, 5e-7);
  for (const double speed : {0.5, 2.0, 4.0}) {
    const test::ModelRun run = test::run_model("roller-coaster", {{"der(x1)", speed}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double x = run.at(i, "x1"), v = run.at(i, "der(x1)"), acc = run.at(i, "ax");
      if (std::abs(v) < 1e-3) continue;
      const double f1 = -A * pi * std::sin(pi * x), f2 = -A * pi * pi * std::cos(pi * x);
      const double root = std::sqrt(1 + f1 * f1);
      const double normal = m * std::abs(g + f2 * v * v) / root;
      const double residual = m * ((1 + f1 * f1) * acc + f2 * f1 * v * v) + m * g * f1 +
                              mu_d * root * normal * (v > 0 ? 1 : -1);
      EXPECT_NEAR(residual, 0.0, 1e-8) << "x = " << x << " v = " << v;
      ++checked;
    }
    EXPECT_GT(checked, 100u);
    // it rests at last, and only inside a stick interval; where it turned without sticking
    // |f'| > μ_s
    const auto& phases = run.summary.phases;
    EXPECT_EQ(phases.back().what, "contact 'track' sticks") << "speed " << speed;
    for (std::size_t k = 1; k < phases.size(); ++k) {
      std::size_t row = 0;
      while (row + 1 < run.rows.size() && run.at(row + 1, "t") <= phases[k].t) ++row;
      const double x = run.at(row, "x1");  // within a row of the event: the cart is nearly still
      const double distance = std::abs(x - std::round(x));
      if (phases[k].what == "contact 'track' sticks") {
        EXPECT_LE(distance, half_width + 1e-6) << "x = " << x;
      } else {
        EXPECT_GT(distance, half_width - 1e-3) << "x = " << x;
      }
    }
    const double x_end = run.rows.back()[1];
    EXPECT_LE(std::abs(x_end - std::round(x_end)), half_width + 1e-9);
    EXPECT_NEAR(run.rows.back()[4], 0.0, 1e-9);  // der(x1) at rest
  }
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// (5.5)–(5.6) with K2 = 0 and no drive: m1 alone is the classical Coulomb oscillator. Each half
// cycle (π/ω, ω = √(K1/m1)) is harmonic about c_k = δ sgn X_k, δ = μ_d m g/K1, from the turning
// point X_k to X_{k+1} = 2 c_k − X_k; it sticks at the first turning point with |K1 X_k| ≤ μ_s m g.
TEST(Friction, CoulombOscillatorDecaysAndSticks) {
  const test::ModelRun run =
      test::run_model("stick-slip-oscillator",
                      {{"K2", 0.0}, {"P", 0.0}, {"x2", 0.0}, {"mu_d", 0.05}, {"mu_s", 0.08}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1.0, K = 50.0, mu_d = 0.05, mu_s = 0.08, omega = std::sqrt(K / m);
  const double delta = mu_d * m * g / K, hold = mu_s * m * g / K, half = pi / omega;
  // the turning points and the half cycle where it sticks
  std::vector<double> X{0.2};
  while (std::abs(X.back()) > hold) {
    const double c = delta * (X.back() > 0 ? 1 : -1);
    X.push_back(2 * c - X.back());
  }
  const double t_stick = half * double(X.size() - 1);
  std::size_t sticks = 0;
  for (const auto& phase : run.summary.phases) {
    if (phase.what == "contact 'table1' sticks" && phase.t > 0) {
      EXPECT_NEAR(phase.t, t_stick, 1e-9);
      ++sticks;
    }
  }
  EXPECT_EQ(sticks, 1u);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const auto k = std::min(static_cast<std::size_t>(t / half), X.size() - 1);
    double expected = X.back();
    if (t < t_stick) {
      const double c = delta * (X[k] > 0 ? 1 : -1);
      expected = c + (X[k] - c) * std::cos(omega * (t - half * double(k)));
    }
    EXPECT_NEAR(run.at(i, "x1"), expected, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "x2"), 0.0, 1e-12) << t;  // m2 stays stuck
  }
}

// Driven (P = 3, μ_d = 0.2, μ_s = 0.3), the masses alternate between sliding and sticking; while
// m1 sticks it stays put and (5.6) |K1 x10 + K2 (x10 − x2)| ≤ μ_s m1 g holds.
TEST(Friction, DrivenOscillatorSticksAndSlips) {
  const test::ModelRun run = test::run_model("stick-slip-oscillator");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double K1 = 50.0, K2 = 30.0, mu_s = 0.3, m1 = 1.0;
  // m1's stuck intervals, from its events
  std::vector<std::pair<double, double>> stuck;
  for (const auto& phase : run.summary.phases) {
    if (phase.what == "contact 'table1' sticks") stuck.emplace_back(phase.t, 1e300);
    if (phase.what == "contact 'table1' slips (static friction exceeded)" && !stuck.empty()) {
      stuck.back().second = phase.t;
    }
  }
  ASSERT_GE(stuck.size(), 2u);
  std::size_t checked = 0;
  for (const auto& [from, to] : stuck) {
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t");
      if (t <= from || t >= to) continue;
      const double x1 = run.at(i, "x1"), x2 = run.at(i, "x2");
      EXPECT_NEAR(run.at(i, "der(x1)"), 0.0, 1e-10) << t;
      EXPECT_LE(std::abs(K1 * x1 + K2 * (x1 - x2)), mu_s * m1 * g + 1e-9) << t;
      ++checked;
    }
  }
  EXPECT_GT(checked, 20u);
}

// (5.5)–(5.6) written here and integrated by RK4 with their stick–slip logic: while mass i slides
// (direction d_i = sgn ẋ_i), m_i ẍ_i = F_i − μ_d m_i g d_i with F_1 = −K1 x1 − K2 (x1 − x2),
// F_2 = −K2 (x2 − x1) + P cos ωt ((5.5), N_i = m_i g); while it is stuck, ẋ_i = 0 and it stays so
// while |F_i| ≤ μ_s m_i g ((5.6): for m1, |K1 x10 + K2 (x10 − x2)| ≤ μ_s m1 g). When a sliding
// mass comes to rest it sticks if |F_i| ≤ μ_s m_i g, else slides on in the direction of F_i; a
// stuck one slips, in the direction of F_i, when |F_i| reaches μ_s m_i g. Events are located by
// bisection on the RK4 step.
struct DrivenChain {
  double m[2], K1, K2, P, w, mu_d, mu_s;
  // the spring forces and the drive on each mass
  std::array<double, 2> spring(double t, const std::array<double, 4>& y) const {
    return {-K1 * y[0] - K2 * (y[0] - y[2]), -K2 * (y[2] - y[0]) + P * std::cos(w * t)};
  }
  // y = (x1, ẋ1, x2, ẋ2); d_i = ±1 sliding that way, 0 stuck
  std::array<double, 4> rates(double t, const std::array<double, 4>& y,
                              const std::array<int, 2>& d) const {
    const auto F = spring(t, y);
    std::array<double, 4> r{};
    for (int i = 0; i < 2; ++i) {
      if (d[i] == 0) continue;
      r[2 * i] = y[2 * i + 1];
      r[2 * i + 1] = (F[i] - mu_d * m[i] * g * d[i]) / m[i];
    }
    return r;
  }
  std::array<double, 4> rk4_step(double t, const std::array<double, 4>& y,
                                 const std::array<int, 2>& d, double h) const {
    auto add = [](std::array<double, 4> a, const std::array<double, 4>& k, double f) {
      for (int j = 0; j < 4; ++j) a[j] += f * k[j];
      return a;
    };
    const auto k1 = rates(t, y, d), k2 = rates(t + h / 2, add(y, k1, h / 2), d);
    const auto k3 = rates(t + h / 2, add(y, k2, h / 2), d), k4 = rates(t + h, add(y, k3, h), d);
    std::array<double, 4> out = y;
    for (int j = 0; j < 4; ++j) out[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    return out;
  }
  // < 0 once mass i's phase has to end: a sliding one has come to rest, a stuck one's spring
  // force exceeds μ_s m_i g
  double switching(int i, double t, const std::array<double, 4>& y,
                   const std::array<int, 2>& d) const {
    if (d[i] != 0) return d[i] * y[2 * i + 1];
    return mu_s * m[i] * g - std::abs(spring(t, y)[i]);
  }
};

struct ChainEvent {
  double t;
  std::string what;
};

struct HybridChain {
  const DrivenChain& c;
  double t = 0;
  std::array<double, 4> y;
  std::array<int, 2> d{};
  std::vector<ChainEvent> events;

  HybridChain(const DrivenChain& chain, const std::array<double, 4>& y0) : c(chain), y(y0) {
    const auto F = c.spring(0, y);
    for (int i = 0; i < 2; ++i) {  // at rest at the start: stuck unless the springs overcome μ_s
      d[i] = std::abs(F[i]) <= c.mu_s * c.m[i] * g ? 0 : (F[i] > 0 ? 1 : -1);
    }
  }
  bool ends(const std::array<double, 4>& z, double at) const {
    return c.switching(0, at, z, d) < 0 || c.switching(1, at, z, d) < 0;
  }
  void advance(double t_end, double h_max) {
    while (t < t_end - 1e-15) {
      const double h = std::min(h_max, t_end - t);
      std::array<double, 4> z = c.rk4_step(t, y, d, h);
      if (!ends(z, t + h)) {
        y = z;
        t += h;
        continue;
      }
      double lo = 0, hi = h;  // the phase ends within (lo, hi]
      for (int k = 0; k < 80 && hi - lo > 1e-15; ++k) {
        const double mid = (lo + hi) / 2;
        (ends(c.rk4_step(t, y, d, mid), t + mid) ? hi : lo) = mid;
      }
      y = c.rk4_step(t, y, d, hi);
      t += hi;
      for (int i = 0; i < 2; ++i) {
        if (c.switching(i, t, y, d) >= 0) continue;
        const double F = c.spring(t, y)[i];
        const std::string name = "contact 'table" + std::to_string(i + 1) + "' ";
        if (d[i] != 0) {
          y[2 * i + 1] = 0;
          if (std::abs(F) <= c.mu_s * c.m[i] * g) {
            d[i] = 0;
            events.push_back({t, name + "sticks"});
          } else {
            d[i] = F > 0 ? 1 : -1;
            events.push_back({t, name + "slides on (static friction too weak to hold it)"});
          }
        } else {
          d[i] = F > 0 ? 1 : -1;
          events.push_back({t, name + "slips (static friction exceeded)"});
        }
      }
    }
  }
};

// §5.2 (5.5)–(5.6): models/stick-slip-oscillator.yaml (K1 = 50, K2 = 30, P = 3, ω = 4, μ_d = 0.2,
// μ_s = 0.3, from x1 = 0.2, x2 = 0.3 at rest) against the equations above integrated here by RK4
// (h = 1e-4) over its 10 s: the same sequence of stick, slip and slide-on events of both masses at
// the same times, and x1, x2 at every row (stuck stretches included).
TEST(Friction, DrivenTwoMassChainAgreesWithRk4OfEquations55And56) {
  const test::ModelRun run = test::run_model("stick-slip-oscillator");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.parameter("L1"), 0.0);
  ASSERT_EQ(run.parameter("L2"), 0.0);
  ASSERT_EQ(run.parameter("g"), g);
  const DrivenChain chain{{run.parameter("m1"), run.parameter("m2")},
                          run.parameter("K1"),
                          run.parameter("K2"),
                          run.parameter("P"),
                          run.parameter("w"),
                          run.parameter("mu_d"),
                          run.parameter("mu_s")};
  HybridChain oracle(
      chain, {run.at(0, "x1"), run.at(0, "der(x1)"), run.at(0, "x2"), run.at(0, "der(x2)")});
  EXPECT_EQ(oracle.d[0], -1);  // m1 pulled back by 7 N > μ_s m1 g
  EXPECT_EQ(oracle.d[1], 0);   // m2: the spring and the drive cancel at t = 0
  double position_error = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    oracle.advance(run.at(i, "t"), 1e-4);
    position_error = std::max({position_error, std::abs(run.at(i, "x1") - oracle.y[0]),
                               std::abs(run.at(i, "x2") - oracle.y[2])});
  }
  std::printf("(5.5)-(5.6) RK4 vs model over 10 s: x1 and x2 %.3g\n", position_error);
  // RK4 at h = 1e-4 (ω h ≈ 1e-3) with bisected events against a run at rtol 1e-12
  EXPECT_LT(position_error, 1e-9);
  std::vector<ChainEvent> events;
  for (const auto& phase : run.summary.phases) {
    if (phase.t > 0) events.push_back({phase.t, phase.what});
  }
  ASSERT_EQ(events.size(), oracle.events.size());
  EXPECT_GT(events.size(), 30u);
  double time_error = 0;
  for (std::size_t k = 0; k < events.size(); ++k) {
    EXPECT_EQ(events[k].what, oracle.events[k].what) << "t = " << events[k].t;
    time_error = std::max(time_error, std::abs(events[k].t - oracle.events[k].t));
  }
  EXPECT_LT(time_error, 1e-8);
  std::printf("(5.5)-(5.6) RK4 vs model: %zu events, times %.3g s\n", events.size(), time_error);
}

// Painlevé's paradox: a uniform rod (length 2l) whose lower end slides on a rough floor, at θ from
// the vertical, with the end moving away from under it. Its end's normal acceleration is
// (N/m)(1 + 3 sin²θ − 3 μ sinθ cosθ) + …: beyond μ_c = (1 + 3 sin²θ)/(3 sinθ cosθ) no normal force
// is consistent with the friction it brings, and the run stops saying so (1.9447 at θ = 0.9); just
// below it slides on.
TEST(Friction, PainleveParadoxIsReportedBeyondItsThreshold) {
  const std::string rod = R"(unidyn: 1
parameters: {m: 1.0, g: 9.81, l: 0.5, mu: 1.0}
coordinates: [x, y, theta]
bodies:
  rod:
    mass: m
    inertia: {rod: {length: 2*l}}
    rotation: {axis: [0, 1, 0], angle: theta}
    center: [x, 0, y]
forces:
  - gravity: -g*E3
constraints:
  - name: floor
    position: dot(rod.center - l*rod.e3, E3)
    friction: {on: rod, at: rod.center - l*rod.e3, dynamic: mu}
initial: {theta: 0.9, der(x): -3}
simulate: {t_end: 0.2, output_step: 0.01}
)";
  const double theta = 0.9;
  const double critical =
      (1 + 3 * std::pow(std::sin(theta), 2)) / (3 * std::sin(theta) * std::cos(theta));
  const System system = parse_model(rod, "painleve.yaml");
  const test::ModelRun below = test::run_system(system, {{"mu", 0.99 * critical}}, {}, true);
  EXPECT_TRUE(below.summary.ok) << below.summary.message;
  const test::ModelRun beyond = test::run_system(system, {{"mu", 1.01 * critical}}, {}, true);
  EXPECT_FALSE(beyond.summary.ok);
  EXPECT_NE(beyond.summary.message.find("Painlevé"), std::string::npos) << beyond.summary.message;
}

}  // namespace
}  // namespace unidyn
