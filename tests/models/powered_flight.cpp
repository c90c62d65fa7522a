// Exercise 9.8 (and §9.6 with drag): a spinning body under thrust, drag and the Magnus force.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

#include "support/model_run.hpp"
#include "support/rigid_kinematics.hpp"
#include "support/rk4.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// The Magnus force m B ω × v̄ is normal to v̄: no power; E changes by the work of the thrust and
// the drag, E(t) − E(0) = ∫ (thrust + drag)·v̄ dt (Simpson's rule on the 1 ms grid).
TEST(PoweredFlight, MagnusDoesNoWorkThrustAndDragDo) {
  const test::ModelRun run = test::run_model("powered-flight");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "magnus_power"), 0.0, 1e-13);
    if (i % 2 == 1) continue;
    EXPECT_NEAR(run.at(i, "E") - run.at(0, "E"), work[i], 1e-8) << run.at(i, "t");
  }
  EXPECT_GT(std::abs(work.back()), 1.0);
}

using Vec = std::array<double, 3>;

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double norm(const Vec& a) {
  return std::sqrt(dot(a, a));
}

// §9.6 and Ex. 9.8 with ω constant (M = 0, H = (2/5) m R² ω, so ω(t) = ω(t0)): the centre of mass
// obeys m x̄̈ = −m g E3 + m B ω × v̄ − ½ ρ π R² C_d |v̄| v̄ + F_t v̄/|v̄| (thrust along v̄, as in
// models/powered-flight.yaml). State (x̄, v̄).
struct Flight {
  double g, B, drag, thrust;  // drag = ρ π R² C_d / (2m), thrust = F_t / m
  Vec omega;

  std::array<double, 6> rates(const std::array<double, 6>& s) const {
    const Vec v{s[3], s[4], s[5]};
    const Vec magnus = cross(omega, v);
    const double speed = norm(v);
    std::array<double, 6> r{v[0], v[1], v[2], 0, 0, 0};
    for (int j = 0; j < 3; ++j) {
      r[3 + j] = B * magnus[j] - drag * speed * v[j] + thrust * v[j] / speed;
    }
    r[5] -= g;
    return r;
  }
};

Flight flight(const test::ModelRun& run, double thrust, const Vec& omega) {
  const double m = run.parameter("m"), R = run.parameter("R");
  return {run.parameter("g"), run.parameter("B"),
          run.parameter("rho") * std::numbers::pi * R * R * run.parameter("Cd") / (2 * m),
          thrust / m, omega};
}

struct Errors {
  double position = 0, velocity = 0;
};

// The run's x̄ and v̄ against the RK4 of `flight` (h = 1e-4 s) from the run's first row, every
// 0.25 s.
Errors compare_with_rk4(const test::ModelRun& run, const Flight& f) {
  const char* position[3] = {"x", "y", "z"};
  const char* velocity[3] = {"der(x)", "der(y)", "der(z)"};
  std::array<double, 6> s;
  for (int j = 0; j < 3; ++j) {
    s[j] = run.at(0, position[j]);
    s[3 + j] = run.at(0, velocity[j]);
  }
  Errors e;
  double t = 0;
  for (std::size_t k = 250; k < run.rows.size(); k += 250) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, static_cast<int>(std::lround((t1 - t) / 1e-4)),
                  [&f](double, const std::array<double, 6>& y) { return f.rates(y); });
    t = t1;
    for (int j = 0; j < 3; ++j) {
      e.position = std::max(e.position, std::abs(run.at(k, position[j]) - s[j]));
      e.velocity = std::max(e.velocity, std::abs(run.at(k, velocity[j]) - s[3 + j]));
    }
  }
  return e;
}

// Ex. 9.8 as models/powered-flight.yaml gives it (thrust F_t v̄/|v̄|, drag, Magnus, gravity; ω =
// Ω E1 with no moment), started also out of the E2–E3 plane (ẋ1(0) = 2 m/s): x̄(t), v̄(t) against
// the centre-of-mass equations above integrated here by RK4, over the model's 4 s; α̇ stays Ω.
TEST(PoweredFlight, ThrustDragAndMagnusFlightAgreesWithRk4) {
  const test::ModelRun run = test::run_model("powered-flight", {{"der(x)", 2.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double Omega = run.parameter("Omega");
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    EXPECT_NEAR(run.at(k, "der(alpha)"), Omega, 1e-10) << run.at(k, "t");
  }
  const Errors e = compare_with_rk4(run, flight(run, run.parameter("Ft"), {Omega, 0, 0}));
  // RK4 at h = 1e-4 s (error ~1e-13) against a run at rtol 1e-12 over 4 s (|x̄| ~ 40 m, |v̄| ~ 15
  // m/s)
  EXPECT_LT(e.position, 1e-9);
  EXPECT_LT(e.velocity, 1e-9);
  EXPECT_GT(std::abs(run.rows.back()[run.index("x")]), 1.0);
  std::printf("powered flight, RK4 vs model over 4 s: position %.3g m, velocity %.3g m/s\n",
              e.position, e.velocity);
}

// §9.6: the spinning ball with quadratic drag and the Magnus force (thrust off, F_t = 0), the
// general case the book integrates numerically, launched as in Fig. 9.6 (v̄(0) = 10(E2 + E3),
// ω = Ω E1): x̄(t), v̄(t) against RK4 of m x̄̈ = −m g E3 + m B ω × v̄ − ½ ρ A C_d |v̄| v̄.
TEST(PoweredFlight, SpinningBallWithDragAgreesWithRk4) {
  const test::ModelRun run = test::run_model("powered-flight", {{"Ft", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Errors e = compare_with_rk4(run, flight(run, 0.0, {run.parameter("Omega"), 0, 0}));
  EXPECT_LT(e.position, 1e-9);
  EXPECT_LT(e.velocity, 1e-9);
  std::printf("drag ball, RK4 vs model over 4 s: position %.3g m, velocity %.3g m/s\n", e.position,
              e.velocity);
}

// What the test computes from one row of a ball turned by Euler parameters: its basis e_i and ω
// from the Euler parameters and their rates alone (support/rigid_kinematics.hpp).
using BallPose = test::EulerParameterKinematics;

BallPose pose(const test::ModelRun& run, std::size_t k) {
  return test::euler_parameter_kinematics(run, k);
}

// The ball of §9.6 free to turn (Euler parameters, Q(0) = I), with drag and the Magnus force and
// a general spin ω(0) = Σ Ω_i E_i, all three Ω_i ≠ 0 as in (9.15).
constexpr const char* kSpinningBall = R"yaml(unidyn: 1
name: Spinning ball with drag, general spin
parameters: {m: 0.43, R: 0.11, g: 9.81, B: 0.01, rho: 1.2, Cd: 0.25, W1: 12.0, W2: -5.0, W3: 8.0}
coordinates: [x, y, z, e0, e1, e2, e3]
bodies:
  ball:
    mass: m
    inertia: {sphere: {radius: R}}
    rotation: {quaternion: [e0, e1, e2, e3]}
    center: [x, y, z]
forces:
  - gravity: -g*E3
  - force: {on: ball, value: "m*B*cross(ball.omega, ball.velocity) - rho*pi*R^2*Cd/2*norm(ball.velocity)*ball.velocity"}
initial: {e0: 1, der(x): 3, der(y): 10, der(z): 10, ball.omega: [W1, W2, W3]}
simulate: {t_end: 4, output_step: 0.001, rtol: 1e-12}
)yaml";

// §9.6, general case: M = 0 and H = (2/5) m R² ω give ω(t) = ω(t0) (ω computed here from the
// rows' Euler parameters), and Q(t) = cos ν (I − q⊗q) − sin ν εq + q⊗q with q = ω(t0)/|ω(t0)|,
// ν = |ω(t0)| t (the book's closed form, here compared with the rows' e_i = Q E_i); x̄(t), v̄(t)
// against RK4 of the centre-of-mass equations with drag and m B ω × v̄ of (9.15).
TEST(PoweredFlight, GeneralSpinWithDragKeepsOmegaAndAgreesWithRk4) {
  const test::ModelRun run = test::run_system(parse_model(kSpinningBall, "spinning-ball.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Vec omega0{run.parameter("W1"), run.parameter("W2"), run.parameter("W3")};
  const double rate = norm(omega0);
  const Vec q{omega0[0] / rate, omega0[1] / rate, omega0[2] / rate};
  double omega_error = 0, basis_error = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const BallPose p = pose(run, k);
    const double nu = rate * run.at(k, "t");
    for (int i = 0; i < 3; ++i) {
      omega_error = std::max(omega_error, std::abs(p.omega[i] - omega0[i]));
      Vec E{0, 0, 0};
      E[i] = 1;
      const Vec Ea = cross(E, q);
      for (int j = 0; j < 3; ++j) {
        const double book =
            std::cos(nu) * (E[j] - q[i] * q[j]) - std::sin(nu) * Ea[j] + q[i] * q[j];
        basis_error = std::max(basis_error, std::abs(p.basis[i][j] - book));
      }
    }
  }
  const Errors e = compare_with_rk4(run, flight(run, 0.0, omega0));
  EXPECT_LT(omega_error, 1e-9);
  EXPECT_LT(basis_error, 1e-9);
  EXPECT_LT(e.position, 1e-9);
  EXPECT_LT(e.velocity, 1e-9);
  std::printf(
      "general spin over 4 s: |omega - omega0| %.3g rad/s, Q vs closed form %.3g, RK4 vs model: "
      "position %.3g m, velocity %.3g m/s\n",
      omega_error, basis_error, e.position, e.velocity);
}

// Ex. 9.8 as the book states it: F = −m g E3 + m B ω × v̄ + f e1 − ½ ρ A C_d |v̄| v̄ and
// M = π_t × f e1, the body-fixed thrust f e1 acting at π_t = P1 e1 + P2 e2 (off the centre, so ω
// changes). Euler parameters, Q(0) = I.
constexpr const char* kBodyFixedThrust = R"yaml(unidyn: 1
name: Powered flight with a body-fixed thrust
parameters: {m: 0.43, R: 0.11, g: 9.81, B: 0.01, rho: 1.2, Cd: 0.25, f: 2.0, P1: -0.11, P2: 0.005}
coordinates: [x, y, z, e0, e1, e2, e3]
bodies:
  ball:
    mass: m
    inertia: {sphere: {radius: R}}
    rotation: {quaternion: [e0, e1, e2, e3]}
    center: [x, y, z]
forces:
  - gravity: -g*E3
  - force: {on: ball, value: "m*B*cross(ball.omega, ball.velocity) - rho*pi*R^2*Cd/2*norm(ball.velocity)*ball.velocity"}
  - force: {on: ball, point: [P1, P2, 0], value: f*ball.e1}
initial: {e0: 1, der(x): 10, der(z): 10, ball.omega: [2, 3, 5]}
simulate: {t_end: 4, output_step: 0.001, rtol: 1e-12}
)yaml";

// State (x̄, v̄, e1, e2, e3, ω): m v̄̇ = F above, (2/5) m R² ω̇ = π_t × f e1 (Euler's law for a
// sphere, H = (2/5) m R² ω), ė_i = ω × e_i.
struct BodyFixedFlight {
  double m, g, B, drag, f, mu, P1, P2;

  std::array<double, 18> rates(const std::array<double, 18>& s) const {
    const Vec v{s[3], s[4], s[5]}, e1{s[6], s[7], s[8]}, e2{s[9], s[10], s[11]},
        e3{s[12], s[13], s[14]}, w{s[15], s[16], s[17]};
    const Vec magnus = cross(w, v);
    const double speed = norm(v);
    Vec arm;
    for (int j = 0; j < 3; ++j) arm[j] = P1 * e1[j] + P2 * e2[j];
    const Vec moment = cross(arm, Vec{f * e1[0], f * e1[1], f * e1[2]});
    const Vec d1 = cross(w, e1), d2 = cross(w, e2), d3 = cross(w, e3);
    std::array<double, 18> r;
    for (int j = 0; j < 3; ++j) {
      r[j] = v[j];
      r[3 + j] = B * magnus[j] - drag * speed * v[j] + f / m * e1[j];
      r[6 + j] = d1[j];
      r[9 + j] = d2[j];
      r[12 + j] = d3[j];
      r[15 + j] = moment[j] / mu;
    }
    r[5] -= g;
    return r;
  }
};

// Ex. 9.8 (the book's body-fixed thrust f e1 at π_t, so M = π_t × f e1 ≠ 0): x̄, v̄, ω and e1
// against RK4 in the test of the book's F and M above, every 0.25 s over 4 s; and (c): Ė = the
// thrust's power f e1·(v̄ + ω × π_t) + the drag's power (the Magnus force, normal to v̄, does
// none) — E and the powers computed here from the rows, E(t) − E(0) against their integral by
// Simpson's rule.
TEST(PoweredFlight, BodyFixedThrustOfExercise98AgreesWithRk4) {
  const test::ModelRun run =
      test::run_system(parse_model(kBodyFixedThrust, "body-fixed-thrust.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = run.parameter("m"), R = run.parameter("R"), g = run.parameter("g");
  const BodyFixedFlight book{
      m,
      g,
      run.parameter("B"),
      run.parameter("rho") * std::numbers::pi * R * R * run.parameter("Cd") / (2 * m),
      run.parameter("f"),
      0.4 * m * R * R,
      run.parameter("P1"),
      run.parameter("P2")};
  const char* position[3] = {"x", "y", "z"};
  const char* velocity[3] = {"der(x)", "der(y)", "der(z)"};
  auto state = [&](std::size_t k) {
    std::array<double, 18> s;
    const BallPose p = pose(run, k);
    for (int j = 0; j < 3; ++j) {
      s[j] = run.at(k, position[j]);
      s[3 + j] = run.at(k, velocity[j]);
      for (int i = 0; i < 3; ++i) s[6 + 3 * i + j] = p.basis[i][j];
      s[15 + j] = p.omega[j];
    }
    return s;
  };
  std::array<double, 18> s = state(0);
  double t = 0, position_error = 0, velocity_error = 0, omega_error = 0, basis_error = 0;
  for (std::size_t k = 250; k < run.rows.size(); k += 250) {
    const double t1 = run.at(k, "t");
    s = test::rk4(s, t, t1, static_cast<int>(std::lround((t1 - t) / 1e-4)),
                  [&book](double, const std::array<double, 18>& y) { return book.rates(y); });
    t = t1;
    const std::array<double, 18> r = state(k);
    for (int j = 0; j < 3; ++j) {
      position_error = std::max(position_error, std::abs(r[j] - s[j]));
      velocity_error = std::max(velocity_error, std::abs(r[3 + j] - s[3 + j]));
      for (int i = 0; i < 3; ++i) {
        basis_error = std::max(basis_error, std::abs(r[6 + 3 * i + j] - s[6 + 3 * i + j]));
      }
      omega_error = std::max(omega_error, std::abs(r[15 + j] - s[15 + j]));
    }
  }
  // the moment turns the ball: ω(4) − ω(0) = ∫ M dt/μ, up to |M| t/μ = 0.01 · 4/0.00208 ≈ 19 rad/s
  const BallPose first = pose(run, 0), last = pose(run, run.rows.size() - 1);
  EXPECT_GT(std::abs(last.omega[0] - first.omega[0]) + std::abs(last.omega[1] - first.omega[1]) +
                std::abs(last.omega[2] - first.omega[2]),
            1.0);
  EXPECT_LT(position_error, 1e-9);
  EXPECT_LT(velocity_error, 1e-9);
  EXPECT_LT(omega_error, 1e-9);
  EXPECT_LT(basis_error, 1e-9);

  // Ex. 9.8(c): the powers and E from the rows
  ASSERT_EQ(run.rows.size() % 2, 1u);
  const double mu = book.mu;
  double work = 0, energy_error = 0;
  std::vector<double> power, energy;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const std::array<double, 18> r = state(k);
    const Vec v{r[3], r[4], r[5]}, e1{r[6], r[7], r[8]}, e2{r[9], r[10], r[11]},
        w{r[15], r[16], r[17]};
    Vec arm;
    for (int j = 0; j < 3; ++j) arm[j] = book.P1 * e1[j] + book.P2 * e2[j];
    const Vec point_velocity = [&] {
      const Vec c = cross(w, arm);
      return Vec{v[0] + c[0], v[1] + c[1], v[2] + c[2]};
    }();
    power.push_back(book.f * dot(e1, point_velocity) - m * book.drag * norm(v) * dot(v, v));
    energy.push_back(0.5 * m * dot(v, v) + 0.5 * mu * dot(w, w) + m * g * r[2]);
  }
  for (std::size_t k = 2; k < run.rows.size(); k += 2) {
    const double h = run.at(k, "t") - run.at(k - 1, "t");
    work += h / 3 * (power[k - 2] + 4 * power[k - 1] + power[k]);
    energy_error = std::max(energy_error, std::abs(energy[k] - energy[0] - work));
  }
  EXPECT_LT(energy_error, 1e-8);
  EXPECT_GT(std::abs(energy.back() - energy[0]), 1.0);
  std::printf(
      "body-fixed thrust, RK4 vs model over 4 s: position %.3g m, velocity %.3g m/s, omega %.3g "
      "rad/s, e_i %.3g; E - E(0) vs work of thrust and drag %.3g J\n",
      position_error, velocity_error, omega_error, basis_error, energy_error);
}

}  // namespace
}  // namespace unidyn
