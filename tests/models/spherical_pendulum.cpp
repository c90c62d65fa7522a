// The spherical pendulum (book §3.3, Exercise 3.3; §2.6 and §4.4 for the Cartesian form with the
// rod constraint): models/spherical-pendulum.yaml against the closed-form rod tension, the book's
// spherical-coordinate equations integrated here by RK4, its conserved quantities, and
// models/spherical-pendulum-cartesian.yaml (the same pendulum, same parameters and initial state).
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

// The row at time t (rows are at exact multiples of the output step).
std::size_t row_at(const ModelRun& run, double t) {
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    if (std::abs(run.at(k, "t") - t) < 1e-12) return k;
  }
  ADD_FAILURE() << "no row at t = " << t;
  return 0;
}

// The book's spherical-coordinate equations (§3.3 with R = L, φ the polar angle from E3, gravity
// −g E3): φ̈ = sin φ cos φ θ̇² + (g/L) sin φ and d/dt(sin²φ θ̇) = 0, i.e. θ̇ = p/sin²φ with
// p = sin²φ0 θ̇0. State (φ, φ̇, θ).
using State = std::array<double, 3>;

State book_rates(const State& s, double g, double L, double p) {
  const double sphi = std::sin(s[0]);
  const double thetadot = p / (sphi * sphi);
  return {s[1], sphi * std::cos(s[0]) * thetadot * thetadot + g / L * sphi, thetadot};
}

// Classical RK4 with n equal steps from 0 to t: global error O(h⁴).
State rk4_book(State s, double t, int n, double g, double L, double p) {
  const double h = t / n;
  const auto axpy = [](const State& y, double a, const State& k) {
    return State{y[0] + a * k[0], y[1] + a * k[1], y[2] + a * k[2]};
  };
  for (int i = 0; i < n; ++i) {
    const State k1 = book_rates(s, g, L, p);
    const State k2 = book_rates(axpy(s, h / 2, k1), g, L, p);
    const State k3 = book_rates(axpy(s, h / 2, k2), g, L, p);
    const State k4 = book_rates(axpy(s, h, k3), g, L, p);
    for (int j = 0; j < 3; ++j) s[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return s;
}

// §3.3 / §4.5: gravity is conservative and the sphere is fixed, so E is conserved; θ is cyclic, so
// H_O·E3 is. The acceptance criterion: 100 s at rtol 1e-12 keeps E to 1e-9 relative.
TEST(SphericalPendulum, EnergyAndH3ConservedOver100Seconds) {
  const ModelRun run =
      run_model("spherical-pendulum", {}, [](SimulationOptions& o) { o.t_end = 100.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_EQ(run.rows.size(), 10001u);
  EXPECT_EQ(run.at(run.rows.size() - 1, "t"), 100.0);
  ASSERT_TRUE(run.summary.has_energy);
  EXPECT_LT(run.summary.energy_relative_drift, 1e-9);

  // H3 = m L² sin²φ θ̇, from the rows (not the model's own column) and from the summary.
  const double m = run.parameter("m"), L = run.parameter("L");
  const double h0 = m * L * L * std::pow(std::sin(run.at(0, "phi")), 2) * run.at(0, "der(theta)");
  double h_change = 0.0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double h = m * L * L * std::pow(std::sin(run.at(k, "phi")), 2) * run.at(k, "der(theta)");
    h_change = std::max(h_change, std::abs(h - h0));
    ASSERT_NEAR(run.at(k, "H3"), h, 1e-12 * std::abs(h0)) << "t = " << run.at(k, "t");
  }
  EXPECT_LT(h_change, 1e-9 * std::abs(h0));
  ASSERT_EQ(run.summary.conserved_drift.size(), 1u);
  EXPECT_EQ(run.summary.conserved_drift[0].name, "H3");
  EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-9 * std::abs(h0));
  std::printf("100 s: energy relative drift %.3g, H3 drift %.3g (H3 = %.6g)\n",
              run.summary.energy_relative_drift, h_change, h0);
}

// §2.6 / §4.4: the same pendulum in Cartesian coordinates with the rod constraint follows the same
// path; its rod force R = λ ∂Ψ/∂r = 2λ r gives the tension −2λL, which must equal the closed form
// m v²/L − m g cos φ from the radial component of F + R = m a (§3.3 with R̈ = 0).
TEST(SphericalPendulum, CartesianModelSamePathAndTension) {
  const ModelRun sph = run_model("spherical-pendulum");
  const ModelRun cart = run_model("spherical-pendulum-cartesian");
  ASSERT_TRUE(sph.summary.ok) << sph.summary.message;
  ASSERT_TRUE(cart.summary.ok) << cart.summary.message;
  ASSERT_EQ(sph.rows.size(), 1001u);
  ASSERT_EQ(cart.rows.size(), sph.rows.size());
  const double m = sph.parameter("m"), g = sph.parameter("g"), L = sph.parameter("L");
  ASSERT_EQ(cart.parameter("L"), L);
  ASSERT_EQ(cart.parameter("m"), m);
  ASSERT_EQ(cart.parameter("g"), g);

  double position_error = 0.0, closed_form_error = 0.0, tension_error = 0.0, tension_scale = 0.0;
  for (std::size_t k = 0; k < sph.rows.size(); ++k) {
    ASSERT_EQ(sph.at(k, "t"), cart.at(k, "t"));
    const double phi = sph.at(k, "phi"), theta = sph.at(k, "theta");
    const double phidot = sph.at(k, "der(phi)"), thetadot = sph.at(k, "der(theta)");
    // the position, computed here from the coordinates
    const double x = L * std::sin(phi) * std::cos(theta), y = L * std::sin(phi) * std::sin(theta),
                 z = L * std::cos(phi);
    EXPECT_NEAR(sph.at(k, "x"), x, 1e-14);
    EXPECT_NEAR(sph.at(k, "y"), y, 1e-14);
    EXPECT_NEAR(sph.at(k, "z"), z, 1e-14);
    position_error = std::max({position_error, std::abs(cart.at(k, "x") - x),
                               std::abs(cart.at(k, "y") - y), std::abs(cart.at(k, "z") - z)});

    const double v2 = L * L * (phidot * phidot + std::pow(std::sin(phi) * thetadot, 2));
    const double tension = m * v2 / L - m * g * std::cos(phi);
    tension_scale = std::max(tension_scale, m * v2 / L + m * g);
    closed_form_error = std::max(closed_form_error, std::abs(sph.at(k, "tension") - tension));
    tension_error = std::max(tension_error, std::abs(cart.at(k, "tension") - tension));
    // the Cartesian output is −2λL, as its model says
    EXPECT_NEAR(cart.at(k, "tension"), -2.0 * cart.at(k, "lambda(rod)") * L, 1e-12 * tension_scale);
  }
  // Both runs hold rtol 1e-12 over ~10 periods: path differences of 1e-10..1e-9.
  EXPECT_LT(position_error, 1e-8);
  // The spherical tension is evaluated at the same state: round-off only.
  EXPECT_LT(closed_form_error, 1e-11 * tension_scale);
  // The Cartesian tension differs by the path difference times O(m g/L, m v ω).
  EXPECT_LT(tension_error, 1e-8 * tension_scale);
  std::printf(
      "max |x_cart − x_sph| = %.3g, tension: closed form %.3g, Cartesian %.3g (scale %.3g)\n",
      position_error, closed_form_error, tension_error, tension_scale);
}

// §4.4: the rod constraint Ψ = x² + y² + z² − L² and its rate stay at zero (projection after
// every step), checked from the rows and in the summary.
TEST(SphericalPendulum, CartesianConstraintResiduals) {
  const ModelRun cart = run_model("spherical-pendulum-cartesian");
  ASSERT_TRUE(cart.summary.ok) << cart.summary.message;
  const double L = cart.parameter("L");
  double psi = 0.0, psidot = 0.0;
  for (std::size_t k = 0; k < cart.rows.size(); ++k) {
    const double x = cart.at(k, "x"), y = cart.at(k, "y"), z = cart.at(k, "z");
    psi = std::max(psi, std::abs(x * x + y * y + z * z - L * L));
    psidot = std::max(psidot, std::abs(2 * (x * cart.at(k, "der(x)") + y * cart.at(k, "der(y)") +
                                            z * cart.at(k, "der(z)"))));
  }
  EXPECT_LT(psi, 1e-10);
  EXPECT_LT(psidot, 1e-10);
  EXPECT_LT(cart.summary.max_position_residual, 1e-10);
  EXPECT_LT(cart.summary.max_velocity_residual, 1e-10);
  // the model's initial state is on the constraint already
  EXPECT_LT(cart.summary.initial_projection, 1e-14);
  std::printf("max |Psi| = %.3g, max |Psi'| = %.3g\n", psi, psidot);
}

// §3.3 (Exercise 3.3 with R = L): the book's φ̈ = sin φ cos φ θ̇² + (g/L) sin φ and
// d/dt(sin²φ θ̇) = 0, integrated by RK4 here, agree with the model at t = 5.
TEST(SphericalPendulum, AgreesWithBookEquationsByRk4) {
  const ModelRun run =
      run_model("spherical-pendulum", {}, [](SimulationOptions& o) { o.t_end = 5.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double g = run.parameter("g"), L = run.parameter("L");
  const double phi0 = run.at(0, "phi");
  const double p = std::pow(std::sin(phi0), 2) * run.at(0, "der(theta)");
  const State s0{phi0, run.at(0, "der(phi)"), run.at(0, "theta")};
  const std::size_t k = row_at(run, 5.0);
  // h = 1e-3 and h = 5e-4: the RK4 error (O(h⁴), ~1e-11 here) is far below the tolerance.
  const State fine = rk4_book(s0, 5.0, 10000, g, L, p);
  const State coarse = rk4_book(s0, 5.0, 5000, g, L, p);
  EXPECT_LT(std::abs(fine[0] - coarse[0]), 1e-9);
  const double errors[] = {std::abs(run.at(k, "phi") - fine[0]),
                           std::abs(run.at(k, "der(phi)") - fine[1]),
                           std::abs(run.at(k, "theta") - fine[2]),
                           std::abs(run.at(k, "der(theta)") - p / std::pow(std::sin(fine[0]), 2))};
  for (double e : errors) EXPECT_LT(e, 1e-7);
  std::printf("RK4 vs model at t = 5: phi %.3g, phi' %.3g, theta %.3g, theta' %.3g\n", errors[0],
              errors[1], errors[2], errors[3]);
}

// Exercise 4.3: the metric of the spherical coordinates, M = m L² diag(1, sin²φ), is not positive
// definite where sin φ = 0 (the poles): det M = m² L⁴ sin²φ, and there the solve refuses.
TEST(SphericalPendulum, MassMatrixSingularAtThePoles) {
  const System system = load_model(test::model_path("spherical-pendulum"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  Eigen::VectorXd qddot, lambda, qdot(2);
  qdot << 0.3, 0.7;
  for (const double phi : {0.4, 1.3, 2.9}) {
    Eigen::VectorXd q(2);
    q << phi, 0.2;
    compiled.solve(0, q, qdot, start.parameters, qddot, lambda, data);
    EXPECT_NEAR(data.mass_matrix.determinant(), std::pow(std::sin(phi), 2), 1e-12) << phi;
  }
  Eigen::VectorXd pole(2);
  pole << 0.0, 0.2;
  EXPECT_THROW(compiled.solve(0, pole, qdot, start.parameters, qddot, lambda, data),
               std::runtime_error);
  EXPECT_EQ(data.mass_matrix.determinant(), 0.0);
}

}  // namespace
}  // namespace unidyn
