// The alternative principles of book §4.11 on motions found by the balance laws: Hamilton's
// action is stationary on the double pendulum's true path (and not on another motion's path),
// Gauss's constraint is least at the solved q̈ — also with the rolling sphere's non-integrable
// constraints, where Hamilton's principle does not apply — and d'Alembert's virtual work vanishes
// for the displacements the constraints allow. Independently of the solver: Gauss's minimiser and
// d'Alembert's constraint force of the Cartesian spherical pendulum in closed form, and Z minimised
// numerically here for a Cartesian double pendulum (two constraints).
#include "unidyn/analysis/variational.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "support/oracles.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// The path of a run's first `samples` rows, moved by ε η with η(t) = sin(π (t − t0)/T) v: zero at
// both ends, so the perturbed path joins the same configurations.
SampledPath perturbed(const test::ModelRun& run, std::size_t samples, const Eigen::VectorXd& v,
                      double epsilon) {
  const std::size_t n = run.system.coordinates().size();
  SampledPath path;
  path.t0 = run.at(0, "t");
  path.step = run.at(1, "t") - path.t0;
  const double T = path.step * double(samples - 1);
  for (std::size_t k = 0; k < samples; ++k) {
    const double s = std::numbers::pi * double(k) * path.step / T;
    Eigen::VectorXd q(n), qdot(n);
    for (std::size_t i = 0; i < n; ++i) {
      q[Eigen::Index(i)] = run.rows[k][1 + i];
      qdot[Eigen::Index(i)] = run.rows[k][1 + n + i];
    }
    path.q.push_back(q + epsilon * std::sin(s) * v);
    path.qdot.push_back(qdot + epsilon * std::numbers::pi / T * std::cos(s) * v);
  }
  return path;
}

// (4.41): δI = (I(ε) − I(−ε))/(2ε) vanishes on the true path (to the quadrature's error) while
// the second variation does not (measured: |δI| below 1e-7 of it); on the path of another motion —
// the pendulum under a 10 % stronger gravity, scored with the true L — it does not vanish.
TEST(Variational, HamiltonsActionIsStationaryOnTheTruePath) {
  const test::ModelRun run = test::run_model("double-pendulum", {}, [](SimulationOptions& o) {
    o.t_end = 1;
    o.output_step = 0.0025;
  });
  const test::ModelRun other =
      test::run_model("double-pendulum", {{"g", 1.1 * 9.81}}, [](SimulationOptions& o) {
        o.t_end = 1;
        o.output_step = 0.0025;
      });
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  const std::vector<double> parameters{1.0, 1.0, 1.0, 1.0, 9.81};
  const std::size_t samples = run.rows.size();
  ASSERT_EQ(samples % 2, 1u);
  test::Random random;
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd v = Eigen::Vector2d(random.uniform(-1, 1), random.uniform(-1, 1));
    const double epsilon = 1e-3;
    const auto action = [&](const test::ModelRun& r, double e) {
      return action_integral(compiled, parameters, perturbed(r, samples, v, e));
    };
    const double I0 = action(run, 0);
    const double first = (action(run, epsilon) - action(run, -epsilon)) / (2 * epsilon);
    const double second =
        (action(run, epsilon) + action(run, -epsilon) - 2 * I0) / (epsilon * epsilon);
    EXPECT_LT(std::abs(first), 1e-6 * std::abs(second)) << trial;
    EXPECT_GT(std::abs(second), 1e-2);
    const double other_first = (action(other, epsilon) - action(other, -epsilon)) / (2 * epsilon);
    EXPECT_GT(std::abs(other_first), 1e-2 * std::abs(second)) << trial;
  }
}

// Gauss: with A δ = 0, Z(q̈ + δ) − Z(q̈) = ½ δᵀ M δ > 0 at the solved q̈ (the cross term is
// λᵀ A δ = 0), and d'Alembert's virtual work dᵀ (f − M q̈) is 0 for A d = 0, −λ · A d otherwise —
// at states of the rolling sphere (non-integrable constraints) and the Cartesian spherical
// pendulum.
TEST(Variational, GaussConstraintIsLeastAndVirtualWorkVanishes) {
  for (const char* name : {"sphere-incline", "spherical-pendulum-cartesian"}) {
    const test::ModelRun run = test::run_model(name);
    ASSERT_TRUE(run.summary.ok) << name;
    const CompiledSystem compiled(run.system, lagrange_equations(run.system));
    std::vector<double> parameters;
    for (const auto& p : run.system.parameters) parameters.push_back(p.value);
    const auto n = static_cast<Eigen::Index>(run.system.coordinates().size());
    test::Random random;
    for (const std::size_t row : {std::size_t(10), run.rows.size() / 2, run.rows.size() - 1}) {
      const double t = run.at(row, "t");
      Eigen::VectorXd q(n), qdot(n), qddot, lambda;
      for (Eigen::Index i = 0; i < n; ++i) {
        q[i] = run.rows[row][std::size_t(1 + i)];
        qdot[i] = run.rows[row][std::size_t(1 + n + i)];
      }
      CompiledSystemData data = compiled.make_data();
      compiled.solve(t, q, qdot, parameters, qddot, lambda, data);
      const Eigen::MatrixXd A = data.constraint_matrix, M = data.mass_matrix;
      const Eigen::MatrixXd kernel = A.fullPivLu().kernel();
      const double Z = gauss_constraint(compiled, parameters, t, q, qdot, qddot);
      for (int trial = 0; trial < 5; ++trial) {
        Eigen::VectorXd w(kernel.cols());
        for (Eigen::Index j = 0; j < w.size(); ++j) w[j] = random.uniform(-1, 1);
        const Eigen::VectorXd delta = 0.1 * kernel * w;
        const double raised = gauss_constraint(compiled, parameters, t, q, qdot, qddot + delta);
        EXPECT_NEAR(raised - Z, 0.5 * delta.dot(M * delta), 1e-10 * (1 + Z)) << name;
        EXPECT_GT(raised, Z) << name;
        const Eigen::VectorXd d = kernel * w;
        EXPECT_NEAR(virtual_work(compiled, parameters, t, q, qdot, qddot, d), 0, 1e-9) << name;
        Eigen::VectorXd any(n);
        for (Eigen::Index i = 0; i < n; ++i) any[i] = random.uniform(-1, 1);
        EXPECT_NEAR(virtual_work(compiled, parameters, t, q, qdot, qddot, any),
                    -lambda.dot(A * any), 1e-9 * (1 + lambda.norm()))
            << name;
      }
    }
  }
}

// q, q̇ of a run's row (the coordinates and their rates, in the file's order).
void row_state(const test::ModelRun& run, std::size_t row, Eigen::VectorXd& q,
               Eigen::VectorXd& qdot) {
  const auto n = static_cast<Eigen::Index>(run.system.coordinates().size());
  q.resize(n);
  qdot.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    q[i] = run.rows[row][std::size_t(1 + i)];
    qdot[i] = run.rows[row][std::size_t(1 + n + i)];
  }
}

std::vector<double> parameter_values(const System& system) {
  std::vector<double> values;
  for (const auto& p : system.parameters) values.push_back(p.value);
  return values;
}

// §4.11 on the spherical pendulum in Cartesian coordinates
// (models/spherical-pendulum-cartesian.yaml, Ψ = |r|² − L²), against closed forms derived here, not
// the solver's M, f, λ:
// - the admissible accelerations ((4.35), 2 r·v = 0, differentiated): r·a + |v|² = 0, a plane;
// - Gauss: Z(a) = ½ m |a − g|² is least on that plane at its foot point from g,
//     a* = g − ((r·g + |v|²)/|r|²) r,   Z(a*) = ½ m (r·g + |v|²)²/|r|²,
//   and Z(a* + δ) = Z(a*) + ½ m |δ|² for δ ⟂ r (Pythagoras);
// - d'Alembert (4.36)–(4.40): with F_c = m a* − m g = −m ((r·g + |v|²)/|r|²) r, F_c · δr = 0
//   for every δr ⟂ r (4.37), so (F + F_c − m a*)·δr = 0, and F_c = μ ∂Ψ/∂r with
//   μ = −m (r·g + |v|²)/(2|r|²) (4.40).
// Compared with: the solver's q̈ at the run's states, the run's velocities differentiated along
// the rows, the run's multiplier lambda(rod) and its constraint-force columns (m a − F and
// λ ∂Ψ/∂r), and unidyn's gauss_constraint and virtual_work evaluated at a*.
TEST(Variational, GaussMinimiserAndDalembertForceOfTheCartesianPendulumInClosedForm) {
  // rows every millisecond, so that differences of the velocity columns give the acceleration
  const test::ModelRun run = test::run_model("spherical-pendulum-cartesian", {},
                                             [](SimulationOptions& o) { o.output_step = 0.001; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  const std::vector<double> parameters = parameter_values(run.system);
  const double m = run.parameter("m"), g = run.parameter("g");
  const Eigen::Vector3d gravity(0, 0, -g);
  const double h = run.at(1, "t") - run.at(0, "t");
  test::Random random;
  double solver_error = 0, run_error = 0, lambda_error = 0, force_error = 0, z_error = 0,
         pythagoras_error = 0, work_error = 0, normal_work = 0, largest_Fc = 0;
  for (std::size_t row = 2; row + 2 < run.rows.size(); row += 67) {
    const double t = run.at(row, "t");
    Eigen::VectorXd q, qdot, qddot, lambda;
    row_state(run, row, q, qdot);
    const Eigen::Vector3d r = q, v = qdot;
    // the closed forms
    const double c = (r.dot(gravity) + v.squaredNorm()) / r.squaredNorm();
    const Eigen::Vector3d a_star = gravity - c * r;
    const Eigen::Vector3d Fc = m * a_star - m * gravity;
    const double mu = -m * c / 2;
    const double Z_star = 0.5 * m * c * c * r.squaredNorm();
    largest_Fc = std::max(largest_Fc, Fc.norm());
    // the solver's q̈ at the row's state
    CompiledSystemData data = compiled.make_data();
    compiled.solve(t, q, qdot, parameters, qddot, lambda, data);
    solver_error = std::max(solver_error, (qddot - a_star).norm() / a_star.norm());
    // the run's acceleration: its velocity columns differentiated (4th-order central differences)
    Eigen::Vector3d a_run;
    for (int i = 0; i < 3; ++i) {
      const std::string column = std::string("der(") + "xyz"[i] + ")";
      a_run[i] = (8 * (run.at(row + 1, column) - run.at(row - 1, column)) -
                  (run.at(row + 2, column) - run.at(row - 2, column))) /
                 (12 * h);
    }
    run_error = std::max(run_error, (a_run - a_star).norm());
    // the run's multiplier and its constraint-force columns
    lambda_error = std::max(lambda_error, std::abs(run.at(row, "lambda(rod)") - mu) / std::abs(mu));
    const Eigen::Vector3d R(run.at(row, "R_x"), run.at(row, "R_y"), run.at(row, "R_z"));
    const Eigen::Vector3d rod(run.at(row, "rod_x"), run.at(row, "rod_y"), run.at(row, "rod_z"));
    force_error =
        std::max({force_error, (R - Fc).norm() / Fc.norm(), (rod - Fc).norm() / Fc.norm()});
    // unidyn's Z at a* and at admissible a* + δ (δ ⟂ r)
    const double Z = gauss_constraint(compiled, parameters, t, q, qdot, a_star);
    z_error = std::max(z_error, std::abs(Z - Z_star) / Z_star);
    const Eigen::Vector3d e1 = r.unitOrthogonal(), e2 = r.cross(e1).normalized();
    for (int trial = 0; trial < 3; ++trial) {
      const Eigen::Vector3d delta = random.uniform(-1, 1) * e1 + random.uniform(-1, 1) * e2;
      const double raised = gauss_constraint(compiled, parameters, t, q, qdot, a_star + delta);
      pythagoras_error = std::max(
          pythagoras_error, std::abs(raised - Z_star - 0.5 * m * delta.squaredNorm()) / Z_star);
      EXPECT_GT(raised, Z_star);
      // d'Alembert with the closed-form force: F_c · δr = 0 and (F + F_c − m a*) · δr = 0 for
      // δr ⟂ r, and unidyn's virtual work δrᵀ (f − M a*) = −F_c · δr = 0
      const Eigen::Vector3d dr = delta;
      normal_work = std::max({normal_work, std::abs(Fc.dot(dr)) / Fc.norm(),
                              std::abs((m * gravity + Fc - m * a_star).dot(dr)) / Fc.norm()});
      work_error = std::max(
          work_error,
          std::abs(virtual_work(compiled, parameters, t, q, qdot, a_star, dr)) / Fc.norm());
    }
    // along r the virtual work of F − m a* is −F_c · r = m (r·g + |v|²): not zero
    EXPECT_NEAR(virtual_work(compiled, parameters, t, q, qdot, a_star, r), m * c * r.squaredNorm(),
                1e-12 * Fc.norm());
  }
  std::printf(
      "Cartesian pendulum against a* = g − ((r·g + |v|²)/|r|²) r: solver q̈ %.3g (relative), run "
      "(differences of der(), h = %g s) %.3g m/s², lambda %.3g, force columns %.3g, Z(a*) %.3g, "
      "Z(a* + δ) − Z(a*) − ½m|δ|² %.3g, virtual work for δr ⟂ r %.3g (unidyn) %.3g (closed form); "
      "largest |F_c| %.3g N\n",
      solver_error, h, run_error, lambda_error, force_error, z_error, pythagoras_error, work_error,
      normal_work, largest_Fc);
  EXPECT_LT(solver_error, 1e-12);
  // the difference formula's error h⁴/30 |a⁽⁴⁾| (1.3e-5 m/s² measured at h = 0.01 s, so ~1e-9 at
  // h = 1 ms) plus the run's global error at rtol 1e-12 and the round-off of 8 Δv/(12 h)
  EXPECT_LT(run_error, 1e-7);
  EXPECT_LT(lambda_error, 1e-12);
  EXPECT_LT(force_error, 1e-12);
  EXPECT_LT(z_error, 1e-12);
  EXPECT_LT(pythagoras_error, 1e-12);
  EXPECT_LT(work_error, 1e-12);
  EXPECT_LT(normal_work, 1e-12);
  EXPECT_GT(largest_Fc, 1.0);
}

// A spherical double pendulum in Cartesian coordinates: two particles, two rods (Ψ1 = |r1|² − L1²,
// Ψ2 = |r2 − r1|² − L2²), gravity; unequal masses so that Gauss's Z is not a plain distance.
constexpr const char* kCartesianDoublePendulum = R"yaml(unidyn: 1
name: Spherical double pendulum in Cartesian coordinates
parameters: {m1: 1.0, m2: 2.5, L1: 1.0, L2: 0.7, g: 9.81}
coordinates: [x1, y1, z1, x2, y2, z2]
particles:
  P1: {mass: m1, position: [x1, y1, z1]}
  P2: {mass: m2, position: [x2, y2, z2]}
forces:
  - gravity: -g*E3
constraints:
  - {name: rod1, position: x1^2 + y1^2 + z1^2 - L1^2}
  - {name: rod2, position: (x2 - x1)^2 + (y2 - y1)^2 + (z2 - z1)^2 - L2^2}
initial:
  x1: L1*sin(1.0)
  z1: -L1*cos(1.0)
  x2: L1*sin(1.0) + L2*sin(2.0)
  z2: -L1*cos(1.0) - L2*cos(2.0)
  der(y1): 1.5
  der(x2): 0.8*cos(2.0)
  der(y2): 0.5
  der(z2): -0.8*sin(2.0)
simulate: {t_end: 3, output_step: 0.01, rtol: 1e-12}
)yaml";

// Gauss's principle with two constraints, minimised numerically here: Z(a) = ½ Σ m_i |a_i − g|²
// over the admissible accelerations A a + b = 0 — rows r1·a1 + |v1|² = 0 and
// d·(a2 − a1) + |w|² = 0, d = r2 − r1, w = v2 − v1 (the rods twice differentiated) — by projected
// gradient descent from the least-norm admissible a (projector P = I − Aᵀ(AAᵀ)⁻¹A, step 1/max m):
// the minimiser is the solver's q̈ at the run's states, and its Lagrange multipliers ν (M(a − g)
// = Aᵀν, least squares) are 2 λ(rod1), 2 λ(rod2) of the run (∂Ψ/∂r doubles the rows of A).
TEST(Variational, GaussConstraintMinimisedNumericallyForTheCartesianDoublePendulum) {
  const test::ModelRun run =
      test::run_system(parse_model(kCartesianDoublePendulum, "cartesian-double-pendulum.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  const std::vector<double> parameters = parameter_values(run.system);
  const double m1 = run.parameter("m1"), m2 = run.parameter("m2"), g = run.parameter("g");
  Eigen::VectorXd masses(6), gravity(6);
  masses << m1, m1, m1, m2, m2, m2;
  gravity << 0, 0, -g, 0, 0, -g;
  const auto Z = [&](const Eigen::VectorXd& a) {
    return 0.5 * (a - gravity).dot(masses.asDiagonal() * (a - gravity));
  };
  double acceleration_error = 0, multiplier_error = 0, value_error = 0, largest_move = 0;
  int most_iterations = 0;
  for (std::size_t row = 0; row < run.rows.size(); row += 15) {
    const double t = run.at(row, "t");
    Eigen::VectorXd q, qdot;
    row_state(run, row, q, qdot);
    const Eigen::Vector3d r1 = q.head<3>(), r2 = q.tail<3>(), v1 = qdot.head<3>(),
                          v2 = qdot.tail<3>();
    const Eigen::Vector3d d = r2 - r1, w = v2 - v1;
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2, 6);
    A.block<1, 3>(0, 0) = r1.transpose();
    A.block<1, 3>(1, 0) = -d.transpose();
    A.block<1, 3>(1, 3) = d.transpose();
    const Eigen::Vector2d b(v1.squaredNorm(), w.squaredNorm());
    const Eigen::MatrixXd AAt = A * A.transpose();
    const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(6, 6) - A.transpose() * AAt.ldlt().solve(A);
    Eigen::VectorXd a = -A.transpose() * AAt.ldlt().solve(b);
    const Eigen::VectorXd start = a;
    const double step = 1 / std::max(m1, m2);
    int iterations = 0;
    for (; iterations < 1000; ++iterations) {
      const Eigen::VectorXd move = step * (P * (masses.asDiagonal() * (a - gravity)));
      a -= move;
      if (move.norm() < 1e-15 * (1 + a.norm())) break;
    }
    most_iterations = std::max(most_iterations, iterations);
    largest_move = std::max(largest_move, (a - start).norm());
    ASSERT_LT((A * a + b).norm(), 1e-12 * (1 + a.norm()));
    // the minimiser's multipliers
    const Eigen::VectorXd constraint_force = masses.asDiagonal() * (a - gravity);
    const Eigen::VectorXd nu = AAt.ldlt().solve(A * constraint_force);
    // the solver
    CompiledSystemData data = compiled.make_data();
    Eigen::VectorXd qddot, lambda;
    compiled.solve(t, q, qdot, parameters, qddot, lambda, data);
    acceleration_error = std::max(acceleration_error, (qddot - a).norm() / a.norm());
    const Eigen::Vector2d run_lambda(run.at(row, "lambda(rod1)"), run.at(row, "lambda(rod2)"));
    multiplier_error = std::max(multiplier_error, (2 * run_lambda - nu).norm() / nu.norm());
    // unidyn's Z at its q̈ is the least value found here
    value_error =
        std::max(value_error,
                 std::abs(gauss_constraint(compiled, parameters, t, q, qdot, qddot) - Z(a)) / Z(a));
  }
  std::printf(
      "Cartesian double pendulum, Gauss minimised by projected gradient (at most %d iterations, "
      "moved up to %.3g from the least-norm start): q̈ %.3g, multipliers %.3g, Z %.3g (relative)\n",
      most_iterations, largest_move, acceleration_error, multiplier_error, value_error);
  // the iteration converges to round-off (contraction 1 − m1/m2 per step)
  EXPECT_LT(acceleration_error, 1e-12);
  EXPECT_LT(multiplier_error, 1e-12);
  EXPECT_LT(value_error, 1e-12);
  EXPECT_GT(largest_move, 1.0);  // the minimum is not the starting point
}

}  // namespace
}  // namespace unidyn
