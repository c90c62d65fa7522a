// The alternative principles of book §4.11 on motions found by the balance laws: Hamilton's
// action is stationary on the double pendulum's true path (and not on another motion's path),
// Gauss's constraint is least at the solved q̈ — also with the rolling sphere's non-integrable
// constraints, where Hamilton's principle does not apply — and d'Alembert's virtual work vanishes
// for the displacements the constraints allow.
#include "unidyn/analysis/variational.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/model_run.hpp"
#include "support/oracles.hpp"
#include "unidyn/equations/lagrange.hpp"

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

}  // namespace
}  // namespace unidyn
