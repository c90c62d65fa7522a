// A particle on a smooth paraboloid of revolution under gravity (book Exercise 3.1, parabolic
// coordinates {u, v, θ} on v = c, (3.20)): models/paraboloid.yaml against the book's conserved h
// and E, the reduced equation (3.20) integrated by RK4, and the normal force.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::ModelRun;
using test::run_model;

using Vec = std::array<double, 3>;

// The row at time t (rows are at exact multiples of the output step).
std::size_t row_at(const ModelRun& run, double t) {
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    if (std::abs(run.at(k, "t") - t) < 1e-12) return k;
  }
  ADD_FAILURE() << "no row at t = " << t;
  return 0;
}

// Ex. 1.5 / 3.1: r = uv e_r + (u² − v²)/2 E3; a_1 = v e_r + u E3, a_2 = u e_r − v E3,
// a_3 = uv e_θ; v = u̇ a_1 + v̇ a_2 + θ̇ a_3.
Vec velocity(const ModelRun& run, std::size_t k) {
  const double u = run.at(k, "u"), v = run.at(k, "v"), theta = run.at(k, "theta");
  const double ud = run.at(k, "der(u)"), vd = run.at(k, "der(v)"), td = run.at(k, "der(theta)");
  const double c = std::cos(theta), s = std::sin(theta);
  const double radial = v * ud + u * vd;  // along e_r
  const double tangential = u * v * td;   // along e_θ
  return {radial * c - tangential * s, radial * s + tangential * c, u * ud - v * vd};
}

// The book's h = m u² c² θ̇ and E = (m/2)(u² + c²)u̇² + h²/(2 m u² c²) + (mg/2)(u² − c²), with v = c.
struct Integrals {
  double h, E;
};

Integrals book_integrals(const ModelRun& run, std::size_t k) {
  const double m = run.parameter("m"), g = run.parameter("g"), c = run.parameter("c");
  const double u = run.at(k, "u"), ud = run.at(k, "der(u)");
  const double h = m * u * u * c * c * run.at(k, "der(theta)");
  const double E = 0.5 * m * (u * u + c * c) * ud * ud + h * h / (2 * m * u * u * c * c) +
                   0.5 * m * g * (u * u - c * c);
  return {h, E};
}

// Ex. 3.1(b), (c): h = H_O·E3 = m u² c² θ̇ and E are conserved. The model's energy column is
// T + U with U = −m g·r = mgz = (mg/2)(u² − c²) on v = c, and T on v = c, v̇ = 0 is the book's
// (m/2)(u² + c²)u̇² + (m/2)u²c²θ̇² = … + h²/(2mu²c²): the same E with the same zero of U, so the
// difference must be a constant, and that constant 0.
TEST(Paraboloid, ConservedAngularMomentumAndEnergy) {
  const ModelRun run = run_model("paraboloid");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size(), 1001u);
  const Integrals first = book_integrals(run, 0);
  const double offset0 = run.at(0, "energy") - first.E;
  double h_drift = 0.0, e_drift = 0.0, offset_change = 0.0, u_min = 1e300, u_max = 0.0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const Integrals now = book_integrals(run, k);
    h_drift = std::max(h_drift, std::abs(now.h - first.h));
    e_drift = std::max(e_drift, std::abs(now.E - first.E));
    offset_change = std::max(offset_change, std::abs(run.at(k, "energy") - now.E - offset0));
    EXPECT_NEAR(run.at(k, "h"), now.h, 1e-14 * std::abs(first.h));
    u_min = std::min(u_min, run.at(k, "u"));
    u_max = std::max(u_max, run.at(k, "u"));
  }
  // rtol 1e-12 over 10 s
  EXPECT_LT(h_drift, 1e-10 * std::abs(first.h));
  EXPECT_LT(e_drift, 1e-10 * std::abs(first.E));
  EXPECT_LT(offset_change, 1e-13 * std::abs(first.E));
  EXPECT_LT(std::abs(offset0), 1e-13 * std::abs(first.E));
  EXPECT_GT(u_max - u_min, 0.1);  // the orbit is not circular: u really moves
  std::printf("h drift %.3g (h %.6g), E drift %.3g (E %.6g), energy - E = %.3g (change %.3g)\n",
              h_drift, first.h, e_drift, first.E, offset0, offset_change);
}

// (3.20): m(u² + c²)ü + m u̇² u − h²/(m u³ c²) = −mgu, integrated by RK4 here from the model's
// initial state, agrees with u(t) at t = 5.
TEST(Paraboloid, AgreesWithReducedEquationByRk4) {
  const ModelRun run = run_model("paraboloid", {}, [](SimulationOptions& o) { o.t_end = 5.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = run.parameter("m"), g = run.parameter("g"), c = run.parameter("c");
  const double h = book_integrals(run, 0).h;
  using State = std::array<double, 2>;
  const auto rates = [&](const State& s) {
    const double u = s[0], ud = s[1];
    return State{ud, (-m * g * u - m * ud * ud * u + h * h / (m * u * u * u * c * c)) /
                         (m * (u * u + c * c))};
  };
  const auto rk4 = [&](State s, int n) {
    const double dt = 5.0 / n;
    for (int i = 0; i < n; ++i) {
      const State k1 = rates(s);
      const State k2 = rates({s[0] + dt / 2 * k1[0], s[1] + dt / 2 * k1[1]});
      const State k3 = rates({s[0] + dt / 2 * k2[0], s[1] + dt / 2 * k2[1]});
      const State k4 = rates({s[0] + dt * k3[0], s[1] + dt * k3[1]});
      for (int j = 0; j < 2; ++j) s[j] += dt / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
    }
    return s;
  };
  const State s0{run.at(0, "u"), run.at(0, "der(u)")};
  // h = 5e-4 and 1e-3: O(h⁴) error, their difference bounds it
  const State fine = rk4(s0, 10000), coarse = rk4(s0, 5000);
  EXPECT_LT(std::abs(fine[0] - coarse[0]), 1e-9);
  const std::size_t k = row_at(run, 5.0);
  const double e_u = std::abs(run.at(k, "u") - fine[0]);
  const double e_rate = std::abs(run.at(k, "der(u)") - fine[1]);
  EXPECT_LT(e_u, 1e-8);
  EXPECT_LT(e_rate, 1e-8);
  std::printf("RK4 vs model at t = 5: u %.3g, u' %.3g (RK4 h vs 2h: %.3g)\n", e_u, e_rate,
              std::abs(fine[0] - coarse[0]));
}

// Ex. 3.1(b): the normal force. unidyn's R = λ(surface) grad(v − c) = λ a², and a²·a_2 = 1, so
// λ = R·a_2 = (m a − F)·a_2 = (m a + mg E3)·(u e_r − c E3). Here a is the finite-difference
// derivative of the velocity computed from the rows, independent of the model's equations. The
// book's N = −(m u̇² c + m u² c θ̇² + mgc) a² says λ = −(m u̇² c + m u² c θ̇² + mgc); the v-row of
// Lagrange's equations (approach I) gives the same: with v = c, v̇ = v̈ = 0,
// λ = d/dt(m(u² + v²)v̇) − m(u̇² + v̇²)v − m u² v θ̇² + ∂U/∂v = −m u̇² c − m u² c θ̇² − mgc.
TEST(Paraboloid, NormalForceMultiplier) {
  const double step = 1e-3;
  const ModelRun run = run_model("paraboloid", {}, [&](SimulationOptions& o) {
    o.t_end = 2.0;
    o.output_step = step;
  });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = run.parameter("m"), g = run.parameter("g"), c = run.parameter("c");
  double fd_error = 0.0, book_error = 0.0, scale = 0.0;
  for (std::size_t k = 2; k + 2 < run.rows.size(); ++k) {
    // fourth-order central difference of the rows' velocities: truncation (h⁴/30)|v⁽⁵⁾| ~ 1e-11,
    // round-off ~ε|v|/h ~ 1e-12, and the dense output's error (~1e-12 at rtol 1e-12) over h ~ 1e-9
    const Vec vm2 = velocity(run, k - 2), vm1 = velocity(run, k - 1), vp1 = velocity(run, k + 1),
              vp2 = velocity(run, k + 2);
    Vec a{};
    for (int i = 0; i < 3; ++i) a[i] = (8 * (vp1[i] - vm1[i]) - (vp2[i] - vm2[i])) / (12 * step);
    const double u = run.at(k, "u"), theta = run.at(k, "theta");
    const Vec a2{u * std::cos(theta), u * std::sin(theta), -c};
    const double lambda_fd = m * a[0] * a2[0] + m * a[1] * a2[1] + (m * a[2] + m * g) * a2[2];
    const double ud = run.at(k, "der(u)"), td = run.at(k, "der(theta)");
    const double lambda_book = -(m * ud * ud * c + m * u * u * c * td * td + m * g * c);
    const double lambda = run.at(k, "lambda(surface)");
    scale = std::max(scale, std::abs(lambda_book));
    fd_error = std::max(fd_error, std::abs(lambda - lambda_fd));
    book_error = std::max(book_error, std::abs(lambda - lambda_book));
  }
  EXPECT_LT(fd_error, 1e-8 * scale);
  EXPECT_LT(book_error, 1e-11 * scale);
  std::printf("lambda(surface): vs m a - F (finite differences) %.3g, vs book %.3g (scale %.3g)\n",
              fd_error, book_error, scale);
}

// Exercise 3.1(a): a free particle in parabolic coordinates (u, v, θ) under gravity −m g E3 has
//   d/dt(m (u² + v²) u̇) − m (u̇² + v̇²) u − m v² u θ̇² = F·a₁ = −m g u,
//   d/dt(m (u² + v²) v̇) − m (u̇² + v̇²) v − m u² v θ̇² = F·a₂ = m g v,   d/dt(m u² v² θ̇) = 0:
// M = m diag(u² + v², u² + v², u² v²) and f from these rows, at random states.
TEST(Paraboloid, FreeParticleInParabolicCoordinatesOfExercise31a) {
  const double m = 0.7, g = 9.81;
  const System system = parse_model(R"yaml(unidyn: 1
parameters: {m: 0.7, g: 9.81}
coordinates: [u, v, theta]
particles:
  P: {mass: m, position: "[u*v*cos(theta), u*v*sin(theta), (u^2 - v^2)/2]"}
forces:
  - gravity: -g*E3
initial: {u: 1, v: 1}
)yaml",
                                    "parabolic.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  const SimulationStart start = initial_state(system, {});
  for (int k = 0; k < 10; ++k) {
    const double u = 0.5 + 0.1 * k, v = 1.4 - 0.08 * k, ud = 0.3 - 0.07 * k, vd = 0.2 * k - 0.5,
                 thd = 1.1 - 0.15 * k;
    Eigen::VectorXd q(3), qdot(3), qddot, lambda;
    q << u, v, 0.3 * k;
    qdot << ud, vd, thd;
    compiled.solve(0, q, qdot, start.parameters, qddot, lambda, data);
    const double s = u * u + v * v, lead = 2 * m * (u * ud + v * vd);
    const Eigen::Vector3d M(m * s, m * s, m * u * u * v * v);
    const Eigen::Vector3d f(
        -lead * ud + m * (ud * ud + vd * vd) * u + m * v * v * u * thd * thd - m * g * u,
        -lead * vd + m * (ud * ud + vd * vd) * v + m * u * u * v * thd * thd + m * g * v,
        -2 * m * (u * v * v * ud + u * u * v * vd) * thd);
    EXPECT_LT((data.mass_matrix - Eigen::MatrixXd(M.asDiagonal())).cwiseAbs().maxCoeff(), 1e-13)
        << k;
    EXPECT_LT((data.forcing - f).cwiseAbs().maxCoeff(), 1e-12) << k;
  }
}

}  // namespace
}  // namespace unidyn
