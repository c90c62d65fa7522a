// The gravity-gradient satellite (§10.5, (10.11)) and MacCullagh's approximation (8.25).
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/model/forces.hpp"

namespace unidyn {
namespace {

// A circular orbit with e1 radial and e3 normal to the orbit, turning at the orbital rate, is a
// relative equilibrium of (10.11): F is along e_R (J e_R ∥ e_R), M = 0, and
// m R0 ω0² = G M m/R0² + 3 G M (tr J − 3 λ1)/(2 R0⁴). With λ1 < λ2 < λ3 (Lagrange's region) it
// stays so over five orbits.
TEST(GravityGradientSatellite, RelativeEquilibriumHolds) {
  const test::ModelRun run =
      test::run_model("gravity-gradient-satellite", {{"der(nu1)", 0.0}, {"der(nu2)", 0.0}},
                      [](SimulationOptions& o) { o.t_end = 5 * 2 * 3.14159; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double w0 = std::sqrt(1.0 + 1.5 * (0.002 + 0.0025 - 2 * 0.001));
  for (std::size_t i = 0; i < run.rows.size(); i += 100) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "R"), 1.0, 1e-10);
    EXPECT_NEAR(run.at(i, "theta"), w0 * t, 1e-9);
    EXPECT_NEAR(run.at(i, "pitch_error"), 0.0, 1e-9);
    EXPECT_NEAR(run.at(i, "nu1"), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "nu2"), 0.0, 1e-12);
  }
}

// Perturbed: the attitude librates and exchanges energy with the orbit; E = T + U and H_O stay.
TEST(GravityGradientSatellite, EnergyAndAngularMomentumAboutOConserved) {
  const test::ModelRun run = test::run_model("gravity-gradient-satellite");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-12);
  ASSERT_EQ(run.summary.conserved_drift.size(), 3u);
  for (const auto& c : run.summary.conserved_drift) EXPECT_LT(c.max_change, 1e-13) << c.name;
  double largest_roll = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    largest_roll = std::max(largest_roll, std::abs(run.at(i, "roll")));
  }
  EXPECT_GT(largest_roll, 1e-3);  // it does librate
  EXPECT_LT(largest_roll, 0.2);   // and stays near the stable equilibrium
}

// (8.25) against the exact attraction of a point-mass dumbbell satellite (Fig. 7.7: masses m_k at
// ±L_k E_k on the body basis, m = (1, 2, 1.5), L = (0.5, 0.3, 0.2)) by direct summation: the error
// of U and M falls as R⁻⁵ and that of F as R⁻⁶ (the next, hexadecapole, term). Measured: F errors
// 1.9e-7, 3.0e-9, 4.7e-11 at R = 10, 20, 40 (the notes: 2.2e-7, 3.5e-9, 5.4e-11 at another
// attitude).
TEST(GravityGradient, MacCullaghAgainstDirectSummation) {
  const System system = parse_model(R"(
unidyn: 1
parameters: {GM: 1.0}
coordinates: [x, y, z, a, b, c]
bodies:
  sat:
    mass: 9
    inertia: [2*(2*0.3^2 + 1.5*0.2^2), 2*(0.5^2 + 1.5*0.2^2), 2*(0.5^2 + 2*0.3^2)]
    rotation: {euler: 3-1-3, angles: [a, b, c]}
    center: [x, y, z]
)",
                                    "dumbbell.yaml");
  const ForceElement element = gravity_gradient(system, 0, Expr(1), VectorExpr{});
  const double mass[3] = {1, 2, 1.5}, arm[3] = {0.5, 0.3, 0.2};
  const auto& q = system.coordinates();
  double previous[3] = {0, 0, 0};
  for (const double R : {10.0, 20.0, 40.0}) {
    GiNaC::exmap state;
    const double direction[3] = {0.48, -0.6, 0.64};  // unit
    for (int i = 0; i < 3; ++i) state[q[static_cast<std::size_t>(i)].value] = R * direction[i];
    state[q[3].value] = 0.4;
    state[q[4].value] = 1.1;
    state[q[5].value] = -0.7;
    const auto number = [&](const Expr& e) {
      return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(state))).to_double();
    };
    // exact: Σ over the six masses at x̄ ± L_k e_k
    double U = 0, F[3] = {0, 0, 0}, M[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      const VectorExpr e = column(system.bodies[0].rotation, k);
      for (const double sign : {1.0, -1.0}) {
        double pi[3], x[3];
        for (int i = 0; i < 3; ++i) {
          pi[i] = sign * arm[k] * number(e[i]);
          x[i] = R * direction[i] + pi[i];
        }
        const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        U -= mass[k] / r;
        double f[3];
        for (int i = 0; i < 3; ++i) f[i] = -mass[k] * x[i] / (r * r * r);
        for (int i = 0; i < 3; ++i) F[i] += f[i];
        M[0] += pi[1] * f[2] - pi[2] * f[1];
        M[1] += pi[2] * f[0] - pi[0] * f[2];
        M[2] += pi[0] * f[1] - pi[1] * f[0];
      }
    }
    double error[3] = {std::abs(number(element.potential) - U), 0, 0};
    for (int i = 0; i < 3; ++i) {
      error[1] = std::max(error[1], std::abs(number(element.body_forces[0].force[i]) - F[i]));
      error[2] = std::max(error[2], std::abs(number(element.moments[0].moment[i]) - M[i]));
    }
    // the approximation keeps what the point-mass force −G M m c/R² misses
    EXPECT_LT(error[2], 1e-2 * std::abs(M[0]) + 1e-2 * std::abs(M[1]) + 1e-2 * std::abs(M[2]));
    if (previous[0] > 0) {
      EXPECT_GT(previous[0] / error[0], std::pow(2.0, 4.7)) << "U at R = " << R;
      EXPECT_GT(previous[1] / error[1], std::pow(2.0, 5.7)) << "F at R = " << R;
      EXPECT_GT(previous[2] / error[2], std::pow(2.0, 4.7)) << "M at R = " << R;
    }
    for (int i = 0; i < 3; ++i) previous[i] = error[i];
  }
}

}  // namespace
}  // namespace unidyn
