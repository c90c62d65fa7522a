// Validation of models/spring-chain.yaml against §5.2 (two masses and two springs on a smooth
// plane, (5.1)–(5.2)): the equations m1ẍ1 = −K1x1 − K2(x1 − x2), m2ẍ2 = −K2(x2 − x1) are linear, so
// the motion is exactly a superposition of the two normal modes of K v = ω² M v; the plane's normal
// forces are the weights; E = T̃ + Ũ is conserved.
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
  double m1, m2, K1, K2, g;
};

// The model's defaults.
constexpr Parameters kDefault{1.0, 2.0, 10.0, 5.0, 9.81};

// The normal modes: K v = ω² M v with K = [[K1+K2, −K2], [−K2, K2]], M = diag(m1, m2); ω²
// ascending, the modes in the columns.
Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d> normal_modes(const Parameters& p) {
  Eigen::Matrix2d K, M;
  K << p.K1 + p.K2, -p.K2, -p.K2, p.K2;
  M << p.m1, 0.0, 0.0, p.m2;
  return Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::Matrix2d>(K, M);
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

}  // namespace
}  // namespace unidyn
