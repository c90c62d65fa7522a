// Validation of models/pendulum-cart.yaml against §5.4 (pendulum and cart, (5.8)–(5.12)): unidyn's
// accelerations satisfy the book's equations of motion (5.11) typed here, the rail's normal force
// is the book's F_c1·E2, the out-of-plane forces vanish, and E and G·E1 are conserved.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::record;

struct Parameters {
  double m1, m2, g, K, L0;
};

// The planar state (x, r, θ) and its rates; y = z1 = z2 = 0.
struct PlanarState {
  double x, r, theta, dx, dr, dtheta;
};

// (5.11)–(5.12): M [ẍ, r̈, θ̈]ᵀ = −[f1, f2, f3]ᵀ with the mass matrix from T̃.
Eigen::Matrix3d book_mass_matrix(const Parameters& p, const PlanarState& s) {
  Eigen::Matrix3d M;
  M << p.m1 + p.m2, p.m2 * std::cos(s.theta), -p.m2 * s.r * std::sin(s.theta),  //
      p.m2 * std::cos(s.theta), p.m2, 0.0,                                      //
      -p.m2 * s.r * std::sin(s.theta), 0.0, p.m2 * s.r * s.r;
  return M;
}

Eigen::Vector3d book_f(const Parameters& p, const PlanarState& s) {
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  return {-2.0 * p.m2 * s.dr * s.dtheta * sn - p.m2 * s.r * s.dtheta * s.dtheta * c,
          -p.m2 * s.r * s.dtheta * s.dtheta + p.m2 * p.g * sn + p.K * (s.r - p.L0),
          2.0 * p.m2 * s.r * s.dr * s.dtheta + p.m2 * p.g * s.r * c};
}

// T̃ (5.9) with y = z1 = z2 = 0.
double book_kinetic_energy(const Parameters& p, const PlanarState& s) {
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  return 0.5 * (p.m1 + p.m2) * s.dx * s.dx +
         0.5 * p.m2 * (s.dr * s.dr + s.r * s.r * s.dtheta * s.dtheta) +
         p.m2 * (s.dx * s.dr * c - s.dx * s.r * s.dtheta * sn);
}

// Ũ = m2 g r sinθ + K/2 (r − L0)².
double book_potential_energy(const Parameters& p, const PlanarState& s) {
  return p.m2 * p.g * s.r * std::sin(s.theta) + 0.5 * p.K * (s.r - p.L0) * (s.r - p.L0);
}

// G·E1 = ∂T̃/∂ẋ = (m1 + m2) ẋ + m2 (ṙ cosθ − r θ̇ sinθ).
double book_momentum(const Parameters& p, const PlanarState& s) {
  return (p.m1 + p.m2) * s.dx +
         p.m2 * (s.dr * std::cos(s.theta) - s.r * s.dtheta * std::sin(s.theta));
}

// §5.4 F_c1·E2 = (m1 + m2) g + d/dt(m2 ṙ sinθ + m2 r θ̇ cosθ), the derivative written out.
double book_rail_force(const Parameters& p, const PlanarState& s, double ddr, double ddtheta) {
  const double c = std::cos(s.theta), sn = std::sin(s.theta);
  return (p.m1 + p.m2) * p.g + p.m2 * (ddr * sn + 2.0 * s.dr * s.dtheta * c + s.r * ddtheta * c -
                                       s.r * s.dtheta * s.dtheta * sn);
}

// The model's parameter vector (in its own order) with the given values.
std::vector<double> parameter_vector(const System& system, const Parameters& p) {
  std::vector<double> values(system.parameters.size(), 0.0);
  const std::pair<const char*, double> named[] = {
      {"m1", p.m1}, {"m2", p.m2}, {"g", p.g}, {"K", p.K}, {"L0", p.L0}};
  for (const auto& [name, value] : named) values.at(system.find_parameter(name).value()) = value;
  return values;
}

Parameters model_parameters(const System& system) {
  const auto value = [&](const char* name) {
    return system.parameters.at(system.find_parameter(name).value()).value;
  };
  return {value("m1"), value("m2"), value("g"), value("K"), value("L0")};
}

// The model's coordinate vectors for a planar state.
void coordinate_vectors(const System& system, const PlanarState& s, Eigen::VectorXd& q,
                        Eigen::VectorXd& qdot) {
  q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(system.coordinates().size()));
  qdot = q;
  const auto index = [&](const char* name) {
    return static_cast<Eigen::Index>(system.find_coordinate(name).value());
  };
  q[index("x")] = s.x;
  q[index("r")] = s.r;
  q[index("theta")] = s.theta;
  qdot[index("x")] = s.dx;
  qdot[index("r")] = s.dr;
  qdot[index("theta")] = s.dtheta;
}

PlanarState row_state(const test::ModelRun& run, std::size_t i) {
  return {run.at(i, "x"),      run.at(i, "r"),      run.at(i, "theta"),
          run.at(i, "der(x)"), run.at(i, "der(r)"), run.at(i, "der(theta)")};
}

const test::ModelRun& default_run() {
  static const test::ModelRun run = test::run_model("pendulum-cart", {}, [](SimulationOptions& o) {
    o.t_end = 2.0;          // four spring periods (2π√(m2/K) ≈ 0.44 s) and a swing (≈ 1.2 s)
    o.output_step = 0.005;  // for the difference quotient of the rail force
  });
  return run;
}

// (5.11)–(5.12) At random states and random parameters, unidyn's q̈ (with y = z1 = z2 = 0 and their
// rates zero) satisfies the book's M [ẍ, r̈, θ̈] = −[f1, f2, f3], and ÿ = z̈1 = z̈2 = 0.
TEST(PendulumCart, AccelerationsSatisfyTheBooksEquations) {
  const System system = load_model(test::model_path("pendulum-cart"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  test::Random random(511u);
  double worst = 0.0, worst_out_of_plane = 0.0;
  for (int trial = 0; trial < 200; ++trial) {
    const Parameters p{random.uniform(0.5, 3.0), random.uniform(0.5, 3.0),
                       random.uniform(1.0, 10.0), random.uniform(10.0, 300.0),
                       random.uniform(0.2, 1.0)};
    const PlanarState s{random.uniform(-1.0, 1.0),      random.uniform(0.2, 1.5),
                        random.uniform(0.0, 2.0 * kPi), random.uniform(-2.0, 2.0),
                        random.uniform(-2.0, 2.0),      random.uniform(-3.0, 3.0)};
    Eigen::VectorXd q, qdot, qddot, lambda;
    coordinate_vectors(system, s, q, qdot);
    const std::vector<double> values = parameter_vector(system, p);
    compiled.solve(random.uniform(-1.0, 1.0), q, qdot, values, qddot, lambda, data);
    const auto at = [&](const char* name) {
      return qddot[static_cast<Eigen::Index>(system.find_coordinate(name).value())];
    };
    const Eigen::Vector3d acceleration(at("x"), at("r"), at("theta"));
    const Eigen::Matrix3d M = book_mass_matrix(p, s);
    const Eigen::Vector3d f = book_f(p, s);
    const Eigen::Vector3d residual = M * acceleration + f;
    const double scale = (M.cwiseAbs() * acceleration.cwiseAbs() + f.cwiseAbs()).maxCoeff();
    worst = std::max(worst, residual.cwiseAbs().maxCoeff() / scale);
    worst_out_of_plane =
        std::max({worst_out_of_plane, std::abs(at("y")), std::abs(at("z1")), std::abs(at("z2"))});
  }
  // both sides are a few dozen floating-point operations: round-off only
  EXPECT_LT(worst, 1e-10);
  EXPECT_LT(worst_out_of_plane, 1e-12);
  record("max_relative_residual", worst);
  record("max_out_of_plane_acceleration", worst_out_of_plane);
}

// §5.4 E = T̃ + Ũ and the horizontal momentum G·E1 ((5.11)₁) are conserved; the energy and Gx
// columns are the book's expressions.
TEST(PendulumCart, EnergyAndHorizontalMomentumConserved) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Parameters p = model_parameters(run.system);
  // the model's initial state: x = 0, r = 0.55, θ = 4.2, ẋ = 0.1, ṙ = 0.2, θ̇ = 0.5
  const PlanarState start{0.0, 0.55, 4.2, 0.1, 0.2, 0.5};
  const PlanarState first = row_state(run, 0);
  ASSERT_EQ(first.r, start.r);
  ASSERT_EQ(first.theta, start.theta);
  ASSERT_EQ(first.dx, start.dx);
  const double E0 = book_kinetic_energy(p, start) + book_potential_energy(p, start);
  const double G0 = book_momentum(p, start);
  double energy_drift = 0.0, momentum_drift = 0.0, column_error = 0.0;
  double energy_scale = 0.0, momentum_scale = 0.0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const PlanarState s = row_state(run, i);
    const double T = book_kinetic_energy(p, s), U = book_potential_energy(p, s);
    const double E = T + U, G = book_momentum(p, s);
    energy_scale = std::max(energy_scale, T + std::abs(U));
    momentum_scale = std::max(momentum_scale,
                              std::abs((p.m1 + p.m2) * s.dx) + std::abs(G - (p.m1 + p.m2) * s.dx));
    energy_drift = std::max(energy_drift, std::abs(E - E0));
    momentum_drift = std::max(momentum_drift, std::abs(G - G0));
    column_error =
        std::max({column_error, std::abs(run.at(i, "energy") - E), std::abs(run.at(i, "Gx") - G)});
  }
  EXPECT_LT(column_error, 1e-12);
  // rtol 1e-12 per step over ~10³ steps (G·E1 is not linear in (q, q̇): it drifts like E)
  EXPECT_LT(energy_drift / energy_scale, 1e-10);
  EXPECT_LT(momentum_drift / momentum_scale, 1e-10);
  record("energy_relative_drift", energy_drift / energy_scale);
  record("momentum_relative_drift", momentum_drift / momentum_scale);
  record("accepted_steps", double(run.summary.stats.accepted_steps));
  record("column_error", column_error);
}

// §5.4, (5.12) The rail's normal force λ(rail) = F_c1·E2 = (m1 + m2) g + d/dt(m2 ṙ sinθ + m2 r θ̇
// cosθ) (R = λ ∂Ψ/∂r1 = λ E2), with the derivative written out and r̈, θ̈ from CompiledSystem::solve;
// the forces normal to the plane of motion vanish: λ(rail_side) = λ(plane) = 0.
TEST(PendulumCart, RailNormalForce) {
  const auto& run = default_run();
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Parameters p = model_parameters(run.system);
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> values = parameter_vector(run.system, p);
  const auto r_index = static_cast<Eigen::Index>(run.system.find_coordinate("r").value());
  const auto theta_index = static_cast<Eigen::Index>(run.system.find_coordinate("theta").value());
  const double scale = (p.m1 + p.m2) * p.g;
  double rail_error = 0.0, out_of_plane = 0.0, rail_min = INFINITY, rail_max = -INFINITY;
  for (std::size_t i = 0; i < run.rows.size(); i += 7) {
    const PlanarState s = row_state(run, i);
    Eigen::VectorXd q, qdot, qddot, lambda;
    coordinate_vectors(run.system, s, q, qdot);
    compiled.solve(run.at(i, "t"), q, qdot, values, qddot, lambda, data);
    const double expected = book_rail_force(p, s, qddot[r_index], qddot[theta_index]);
    rail_error = std::max(rail_error, std::abs(run.at(i, "lambda(rail)") - expected));
    out_of_plane = std::max({out_of_plane, std::abs(run.at(i, "lambda(rail_side)")),
                             std::abs(run.at(i, "lambda(plane)"))});
    rail_min = std::min(rail_min, expected);
    rail_max = std::max(rail_max, expected);
  }
  // the dynamic part varies by a good fraction of the weight: the check is not dominated by
  // (m1+m2)g
  EXPECT_GT(rail_max - rail_min, 0.1 * scale);
  // the same state solved twice, and the book's formula: round-off only
  EXPECT_LT(rail_error / scale, 1e-12);
  EXPECT_LT(out_of_plane / scale, 1e-12);
  record("rail_force_relative_error", rail_error / scale);
  record("out_of_plane_force", out_of_plane);

  // The same force without q̈ from unidyn: the vertical momentum balance of the whole system,
  // λ = (m1 + m2) g + dP/dt with P = m2 (ṙ sinθ + r θ̇ cosθ) from the rows and dP/dt by a
  // fourth-order central difference over the output step h = 0.005 (error h⁴/30 · P⁽⁵⁾).
  std::vector<double> P;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const PlanarState s = row_state(run, i);
    P.push_back(p.m2 * (s.dr * std::sin(s.theta) + s.r * s.dtheta * std::cos(s.theta)));
  }
  const double h = run.at(1, "t") - run.at(0, "t");
  double difference_error = 0.0;
  for (std::size_t i = 2; i + 2 < P.size(); ++i) {
    const double dP = (8.0 * (P[i + 1] - P[i - 1]) - (P[i + 2] - P[i - 2])) / (12.0 * h);
    difference_error = std::max(difference_error, std::abs(run.at(i, "lambda(rail)") - scale - dP));
  }
  // P oscillates at the spring frequency √(K/m2) ≈ 14 s⁻¹ with amplitude ≈ m2 ṙ ≈ 0.2 N·s:
  // h⁴/30 · 0.2 · 14⁵ ≈ 2e-6 N, below 1e-7 (m1 + m2) g (it falls 16-fold when h is halved)
  EXPECT_LT(difference_error / scale, 1e-6);
  record("rail_force_difference_error", difference_error / scale);
}

}  // namespace
}  // namespace unidyn
