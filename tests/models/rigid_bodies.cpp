// Rigid bodies (Ch. 7–9): the torque-free body of Figs. 9.2–9.4, the heavy top and the compound
// pendulum against Euler's equations, the top's classical equations and closed forms.
#include <array>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

// Euler's equations (9.11) for a torque-free body, λ1 ω̇1 = (λ2 − λ3) ω2 ω3 and cyclic, by RK4.
std::array<double, 3> euler_equations(std::array<double, 3> w, double l1, double l2, double l3,
                                      double t_end, int steps) {
  const auto f = [&](const std::array<double, 3>& x) {
    return std::array<double, 3>{(l2 - l3) * x[1] * x[2] / l1, (l3 - l1) * x[2] * x[0] / l2,
                                 (l1 - l2) * x[0] * x[1] / l3};
  };
  const double h = t_end / steps;
  for (int s = 0; s < steps; ++s) {
    const auto k1 = f(w);
    std::array<double, 3> y;
    for (int i = 0; i < 3; ++i) y[i] = w[i] + h / 2 * k1[i];
    const auto k2 = f(y);
    for (int i = 0; i < 3; ++i) y[i] = w[i] + h / 2 * k2[i];
    const auto k3 = f(y);
    for (int i = 0; i < 3; ++i) y[i] = w[i] + h * k3[i];
    const auto k4 = f(y);
    for (int i = 0; i < 3; ++i) w[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
  return w;
}

// §9.5 case (i): λ = (2, 4, 5), ω(0) = 0.5 E2 + 5 E3. The body components of ω follow Euler's
// equations; at t = 10 they are (0.2800, 0.3638, 5.0063) (notes §4.2); T = 63, |H|² = 629
TEST(RigidBodies, TorqueFreeBodyFollowsEulersEquations) {
  const test::ModelRun run = test::run_model("torque-free-body");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::size_t last = run.rows.size() - 1;
  ASSERT_DOUBLE_EQ(run.at(last, "t"), 10.0);
  const auto w = euler_equations({0.0, 0.5, 5.0}, 2, 4, 5, 10.0, 20000);
  EXPECT_NEAR(run.at(last, "w1"), w[0], 1e-8);
  EXPECT_NEAR(run.at(last, "w2"), w[1], 1e-8);
  EXPECT_NEAR(run.at(last, "w3"), w[2], 1e-8);
  EXPECT_NEAR(run.at(last, "w1"), 0.2800, 5e-5);
  EXPECT_NEAR(run.at(last, "w2"), 0.3638, 5e-5);
  EXPECT_NEAR(run.at(last, "w3"), 5.0063, 5e-5);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "energy"), 63.0, 1e-10);
    const Vec3 H(run.at(i, "Hx"), run.at(i, "Hy"), run.at(i, "Hz"));
    EXPECT_NEAR(H.squaredNorm(), 629.0, 1e-9);
  }
}

// (9.13) An axisymmetric body (λ1 = λ2 = 4, λ3 = 5): ω3 = Ω stays constant and (ω1, ω2) turns at
// the rate ν = (λ3 − λ1) Ω / λ1, ω1 = a cos νt, ω2 = a sin νt
TEST(RigidBodies, AxisymmetricBodyClosedForm) {
  const double Omega = 5.0, a = 0.5, nu = (5.0 - 4.0) * Omega / 4.0;
  const test::ModelRun run = test::run_model(
      "torque-free-body",
      {{"l1", 4.0}, {"l2", 4.0}, {"der(psi)", Omega}, {"der(theta)", 0.0}, {"der(phi)", a}},
      [](SimulationOptions& o) { o.t_end = 5; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "w1"), a * std::cos(nu * t), 1e-9) << "t = " << t;
    EXPECT_NEAR(run.at(i, "w2"), a * std::sin(nu * t), 1e-9) << "t = " << t;
    EXPECT_NEAR(run.at(i, "w3"), Omega, 1e-9) << "t = " << t;
  }
}

// Fig. 9.1, an axisymmetric body (λ1 = λ2 = A < λ3 = C) spun about a transverse axis: the
// linearisation is inconclusive (a double zero eigenvalue, tests/analysis/modes.cpp), but the
// motion is not stable. From Euler's equations (9.11), ω3 = ε stays and (ω1, ω2) turns at
// ν = (C − A) ε / A: with ω(0) = ω e1 + ε e3, ω1 = ω cos νt, ω2 = ω sin νt, so however small ε the
// spin leaves e1 altogether (ω2 = ω at t = π/(2ν)), as the book states.
TEST(RigidBodies, AxisymmetricBodyLeavesATransverseAxis) {
  const double A = 4.0, C = 7.0, omega = 5.0, epsilon = 0.02, nu = (C - A) * epsilon / A;
  const test::ModelRun run = test::run_system(parse_model(R"yaml(unidyn: 1
parameters: {A: 4.0, C: 7.0}
coordinates: [e0, e1, e2, e3]
bodies:
  body:
    mass: 1
    inertia: [A, A, C]
    rotation: {quaternion: [e0, e1, e2, e3]}
    center: [0, 0, 0]
# Q(0) = I, omega(0) = 5 E1 + 0.02 E3 (de = omega/2 at e = (1, 0, 0, 0))
initial: {e0: 1, der(e1): 2.5, der(e3): 0.01}
simulate: {t_end: 110, output_step: 0.1, rtol: 1e-12}
outputs:
  w1: dot(body.omega, body.e1)
  w2: dot(body.omega, body.e2)
  w3: dot(body.omega, body.e3)
)yaml",
                                                          "transverse-spin.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double error = 0, largest_w2 = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    error = std::max({error, std::abs(run.at(i, "w1") - omega * std::cos(nu * t)),
                      std::abs(run.at(i, "w2") - omega * std::sin(nu * t)),
                      std::abs(run.at(i, "w3") - epsilon)});
    largest_w2 = std::max(largest_w2, std::abs(run.at(i, "w2")));
  }
  EXPECT_LT(error, 1e-8);
  // the perturbation of ω is ε = 0.02; its deviation from ω e1 reaches the whole of ω
  EXPECT_GT(largest_w2, 0.999 * omega);
  std::printf("transverse spin: |ω - closed form| %.3g, largest ω2 %.6g of ω = %g\n", error,
              largest_w2, omega);
}

// (9.16)–(9.17), Fig. 9.6: the Magnus force bends the flight of a spinning ball; (x2, x3) and
// (ẋ2, ẋ3) at t = 4 s for each BΩ (notes §4.3, the closed form (9.17) to 4 decimals). The ball's
// inertia comes from the shape {sphere: {radius: R}}.
TEST(RigidBodies, SpinningBallMagnusTrajectories) {
  struct Row {
    double k, x2, x3, v2, v3;
  };
  const Row table[] = {
      {-0.5, 3.7097, -65.7066, -22.853, -31.095}, {-0.2, 30.7641, -53.6795, -0.736, -35.393},
      {0.0, 40.0000, -38.4800, 10.000, -29.240},  {0.2, 40.9716, -23.3502, 14.670, -21.046},
      {0.5, 32.6622, -9.0607, 14.530, -12.909},   {1.0, 22.5598, -7.2538, 17.254, -6.680}};
  for (const Row& r : table) {
    // BΩ = k with Ω = 20 rad/s
    const test::ModelRun run = test::run_model("spinning-ball", {{"B", r.k / 20.0}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const std::size_t last = run.rows.size() - 1;
    EXPECT_NEAR(run.at(last, "y"), r.x2, 6e-5) << "B Omega = " << r.k;
    EXPECT_NEAR(run.at(last, "z"), r.x3, 6e-5) << "B Omega = " << r.k;
    EXPECT_NEAR(run.at(last, "der(y)"), r.v2, 6e-4) << "B Omega = " << r.k;
    EXPECT_NEAR(run.at(last, "der(z)"), r.v3, 6e-4) << "B Omega = " << r.k;
    EXPECT_NEAR(run.at(last, "x"), 0.0, 1e-12);
    // the spin is untouched: ω = Ω E1 (no moment on the ball)
    EXPECT_NEAR(run.at(last, "der(alpha)"), 20.0, 1e-10);
  }
}

// A torque-free run of 1000 periods of the wobble (2.05 s, notes §4.2) keeps the energy and |H|
// to 1e-9 relative
TEST(RigidBodies, TorqueFreeBodyThousandPeriods) {
  const test::ModelRun run = test::run_model("torque-free-body", {}, [](SimulationOptions& o) {
    o.t_end = 2100;
    o.output_step = 1;
  });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-9);
  const double H0 = std::sqrt(629.0);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Vec3 H(run.at(i, "Hx"), run.at(i, "Hy"), run.at(i, "Hz"));
    EXPECT_LT(std::abs(H.norm() - H0), 1e-9 * H0) << "t = " << run.at(i, "t");
    EXPECT_LT((H - Vec3(0, 2, 25)).norm(), 1e-9 * H0) << "t = " << run.at(i, "t");
  }
}

// Upward and downward zero crossings of a column, interpolated linearly between rows.
std::vector<double> zero_crossings(const test::ModelRun& run, const std::string& column) {
  std::vector<double> crossings;
  for (std::size_t i = 1; i < run.rows.size(); ++i) {
    const double a = run.at(i - 1, column), b = run.at(i, column);
    if ((a < 0) != (b < 0)) {
      const double t0 = run.at(i - 1, "t"), t1 = run.at(i, "t");
      crossings.push_back(t0 + (t1 - t0) * a / (a - b));
    }
  }
  return crossings;
}

// §9.5 case (ii), ω(0) = 5 E2 + 0.1 E3, with Euler parameters (no singularity): ω2 changes sign at
// t ≈ 2.229, 6.686, 11.143 (notes §4.2), e2 turns over (e2 · E2 ≈ −1), the unit norm holds, and
// the body components follow Euler's equations
TEST(RigidBodies, QuaternionBodyCaseTwo) {
  const test::ModelRun run = test::run_model("torque-free-quaternion");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto crossings = zero_crossings(run, "w2");
  ASSERT_GE(crossings.size(), 3u);
  EXPECT_NEAR(crossings[0], 2.229, 2e-3);
  EXPECT_NEAR(crossings[1], 6.686, 2e-3);
  EXPECT_NEAR(crossings[2], 11.143, 2e-3);
  double lowest = 1;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    lowest = std::min(lowest, run.at(i, "e2_E2"));
    const double norm = std::hypot(run.at(i, "e0"), run.at(i, "e1"), run.at(i, "e2"));
    EXPECT_NEAR(norm * norm + std::pow(run.at(i, "e3"), 2), 1.0, 1e-12);
    EXPECT_NEAR(run.at(i, "energy"), 50.025, 1e-9);
  }
  EXPECT_LT(lowest, -0.99);
  const auto w = euler_equations({0.0, 5.0, 0.1}, 2, 4, 5, 10.0, 40000);
  const std::size_t row = 1000;  // t = 10
  ASSERT_DOUBLE_EQ(run.at(row, "t"), 10.0);
  EXPECT_NEAR(run.at(row, "w1"), w[0], 1e-7);
  EXPECT_NEAR(run.at(row, "w2"), w[1], 1e-7);
  EXPECT_NEAR(run.at(row, "w3"), w[2], 1e-7);
}

// The same case with 3-2-1 Euler angles passes within 0.009 rad of their singularity (notes §4.2)
// and still agrees with the Euler parameters; the summary reports the closest approach
TEST(RigidBodies, EulerAnglesNearGimbalLock) {
  const test::ModelRun angles =
      test::run_model("torque-free-body", {{"der(psi)", 0.1}, {"der(theta)", 5.0}},
                      [](SimulationOptions& o) { o.t_end = 12; });
  const test::ModelRun quaternion =
      test::run_model("torque-free-quaternion", {}, [](SimulationOptions& o) { o.t_end = 12; });
  ASSERT_TRUE(angles.summary.ok) << angles.summary.message;
  EXPECT_LT(angles.summary.closest_gimbal_lock, 0.01);
  EXPECT_GT(angles.summary.closest_gimbal_lock, 1e-4);
  for (std::size_t i = 0; i < angles.rows.size(); ++i) {
    for (const char* w : {"w1", "w2", "w3"}) {
      EXPECT_NEAR(angles.at(i, w), quaternion.at(i, w), 1e-7) << "t = " << angles.at(i, "t");
    }
  }
}

// A top started at θ = 1e-7 is at the 3-1-3 singularity: the run stops with a message that says
// what to do, keeping its first row
TEST(RigidBodies, GimbalLockStopsTheRun) {
  // started just off the lock (|[g1, g2, g3]| = sin θ = 2e-4) and heading into it
  const test::ModelRun run =
      test::run_model("heavy-top", {{"theta", 2e-4}, {"der(theta)", -1.0}, {"der(psi)", 1.0}});
  EXPECT_FALSE(run.summary.ok);
  EXPECT_NE(run.summary.message.find("gimbal lock"), std::string::npos) << run.summary.message;
  EXPECT_NE(run.summary.message.find("quaternion"), std::string::npos);
  EXPECT_GE(run.rows.size(), 1u);
}

// §9.7: the heavy top keeps E, H_O·E3 and H_O·e3 = C ω3, and θ(t) follows the classical
// one-degree-of-freedom equation A′θ̈ = A′ψ̇² sinθ cosθ − C ω3 ψ̇ sinθ + m g l sinθ with
// ψ̇ = (p_ψ − C ω3 cosθ)/(A′ sin²θ), A′ = A + m l², integrated here by RK4
TEST(RigidBodies, HeavyTopIntegralsAndNutation) {
  const test::ModelRun run =
      test::run_model("heavy-top", {}, [](SimulationOptions& o) { o.t_end = 2; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1, g = 9.81, l = 0.05, A = 0.004, C = 0.002, A1 = A + m * l * l;
  const double theta0 = 0.3, w3 = 60.0;  // ω3 = φ̇ + ψ̇ cos θ at the start (ψ̇ = 0)
  const double p_psi = C * w3 * std::cos(theta0);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "H_Oe3"), C * w3, 1e-12);
    EXPECT_NEAR(run.at(i, "H_O3"), p_psi, 1e-12);
    EXPECT_NEAR(run.at(i, "energy"), run.at(0, "energy"), 1e-10 * run.at(0, "energy"));
  }
  // θ'' from the reduced equation, by RK4 to t = 2
  const auto theta_rate = [&](double th, double dth) {
    const double dpsi = (p_psi - C * w3 * std::cos(th)) / (A1 * std::sin(th) * std::sin(th));
    return std::array<double, 2>{dth, (A1 * dpsi * dpsi * std::sin(th) * std::cos(th) -
                                       C * w3 * dpsi * std::sin(th) + m * g * l * std::sin(th)) /
                                          A1};
  };
  double th = theta0, dth = 0;
  const int steps = 200000;
  const double h = 2.0 / steps;
  for (int s = 0; s < steps; ++s) {
    const auto k1 = theta_rate(th, dth);
    const auto k2 = theta_rate(th + h / 2 * k1[0], dth + h / 2 * k1[1]);
    const auto k3 = theta_rate(th + h / 2 * k2[0], dth + h / 2 * k2[1]);
    const auto k4 = theta_rate(th + h * k3[0], dth + h * k3[1]);
    th += h / 6 * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0]);
    dth += h / 6 * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1]);
  }
  const std::size_t last = run.rows.size() - 1;
  EXPECT_NEAR(run.at(last, "theta"), th, 1e-8);
  EXPECT_NEAR(run.at(last, "der(theta)"), dth, 1e-6);
}

// A body swinging about a fixed axis: small oscillations have period 2π √((C + m d²)/(m g d))
TEST(RigidBodies, CompoundPendulumPeriod) {
  const test::ModelRun run = test::run_model("compound-pendulum", {{"theta", 1e-4}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 2, g = 9.81, d = 0.3, C = 0.025;
  const double period = 2 * test::kPi * std::sqrt((C + m * d * d) / (m * g * d));
  // upward zero crossings of θ, interpolated linearly between rows
  std::vector<double> crossings;
  for (std::size_t i = 1; i < run.rows.size(); ++i) {
    const double a = run.at(i - 1, "theta"), b = run.at(i, "theta");
    if (a < 0 && b >= 0) {
      const double t0 = run.at(i - 1, "t"), t1 = run.at(i, "t");
      crossings.push_back(t0 + (t1 - t0) * (-a) / (b - a));
    }
  }
  ASSERT_GE(crossings.size(), 3u);
  const double measured = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  // linear interpolation of a sine over a step of 0.01 s: error ≈ h²/period² ≈ 1e-4 relative at
  // most
  EXPECT_NEAR(measured, period, 2e-5 * period);
}

// §9.5: a torque-free body with equal moments turns at its constant initial ω about a fixed axis:
// from Q(0) = I, Q(t) = L(|ω0| t, ω0/|ω0|), i.e. Euler parameters e0 = cos(|ω0| t/2),
// e = sin(|ω0| t/2) ω0/|ω0| (ω0 = 5 E2 + 0.1 E3 of torque-free-quaternion).
TEST(RigidBodies, SphericalBodyTurnsAboutAFixedAxis) {
  const test::ModelRun run =
      test::run_model("torque-free-quaternion", {{"l1", 4.0}, {"l2", 4.0}, {"l3", 4.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double w = std::sqrt(25.0 + 0.01), axis[3] = {0.0, 5.0 / w, 0.1 / w};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "e0"), std::cos(w * t / 2), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "e1"), std::sin(w * t / 2) * axis[0], 1e-9) << t;
    EXPECT_NEAR(run.at(i, "e2"), std::sin(w * t / 2) * axis[1], 1e-9) << t;
    EXPECT_NEAR(run.at(i, "e3"), std::sin(w * t / 2) * axis[2], 1e-9) << t;
  }
}

// §10.2: a free body with its centre in spherical coordinates (R, Θ, Φ; Φ from E3) and 3-1-3 angles
// has T = m/2 (Ṙ² + R² Φ̇² + R² sin²Φ Θ̇²) + λ1/2 (ψ̇ sin φ sin θ + θ̇ cos φ)² + λ2/2 (ψ̇ cos φ sin θ −
// θ̇ sin φ)² + λ3/2 (ψ̇ cos θ + φ̇)² (10.5); at Φ = 0, θ = 0 both charts are singular and the motion
// Θ̇ = 1, ψ̇ = −φ̇ = 1 has T = 0.
TEST(RigidBodies, FreeBodyKineticEnergyAndItsSingularCharts) {
  const System system = parse_model(R"yaml(unidyn: 1
parameters: {m: 2.0, l1: 1.0, l2: 2.0, l3: 2.5}
coordinates: [R, Theta, Phi, psi, theta, phi]
bodies:
  body:
    mass: m
    inertia: [l1, l2, l3]
    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}
    center: "R*[sin(Phi)*cos(Theta), sin(Phi)*sin(Theta), cos(Phi)]"
initial: {R: 1.0, Phi: 1.0, theta: 1.0}
)yaml",
                                    "free-body.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  std::vector<double> seen(compiled.observation_count());
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(6), no_lambda(0);
  const auto T_of = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
    compiled.observe(0, q, qdot, none, no_lambda, start.parameters, seen, data);
    return seen[0];
  };
  const double m = 2.0, l1 = 1.0, l2 = 2.0, l3 = 2.5;
  Eigen::VectorXd q(6), qdot(6);
  q << 1.5, 0.3, 0.8, 0.4, 1.1, -0.6;
  qdot << 0.2, -0.7, 0.5, 1.3, 0.9, -0.4;
  const double R = q[0], Ph = q[2], th = q[4], ph = q[5];
  const double Rd = qdot[0], Thd = qdot[1], Phd = qdot[2], psd = qdot[3], thd = qdot[4],
               phd = qdot[5];
  const double T = m / 2 * (Rd * Rd + R * R * Phd * Phd + std::pow(R * std::sin(Ph) * Thd, 2)) +
                   l1 / 2 * std::pow(psd * std::sin(ph) * std::sin(th) + thd * std::cos(ph), 2) +
                   l2 / 2 * std::pow(psd * std::cos(ph) * std::sin(th) - thd * std::sin(ph), 2) +
                   l3 / 2 * std::pow(psd * std::cos(th) + phd, 2);
  EXPECT_NEAR(T_of(q, qdot), T, 1e-12 * T);
  Eigen::VectorXd singular(6), moving(6);
  singular << 1.5, 0.3, 0.0, 0.4, 0.0, -0.6;
  moving << 0.0, 1.0, 0.0, 1.0, 0.0, -1.0;
  EXPECT_NEAR(T_of(singular, moving), 0.0, 1e-15);
}

}  // namespace
}  // namespace unidyn
