// A particle on a smooth helix under gravity (book §3.8, (3.18)): models/helix.yaml against the
// book's closed-form θ(t) and its constraint multipliers λ_1 (cylinder) and λ_2 (helicoid).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::ModelRun;
using test::run_model;

struct HelixParameters {
  double m, g, R, alpha;
};

// The model's parameters with the overrides applied.
HelixParameters parameters(const ModelRun& run,
                           const std::vector<std::pair<std::string, double>>& overrides) {
  const auto value = [&](const std::string& name) {
    for (const auto& [n, v] : overrides) {
      if (n == name) return v;
    }
    return run.system.parameters.at(run.system.find_parameter(name).value()).value;
  };
  return {value("m"), value("g"), value("R"), value("alpha")};
}

struct Errors {
  double theta = 0, thetadot = 0, cylinder = 0, helicoid = 0, r = 0, eta = 0, rdot = 0, etadot = 0;
};

// Compares every row with (3.18): θ(t) = θ0 + ω0 t − gα t²/(2R(1 + α²)), and the book's
// multipliers λ_1 = mgαθ/(1 + α²) − mRθ̇², λ_2 = mg/(1 + α²) (§3.8; unidyn's R = λ ∂Ψ/∂r is the
// book's F_c = λ_1 ã² + λ_2 ã³ with Ψ_1 = r − R, Ψ_2 = η).
Errors compare_with_book(const std::vector<std::pair<std::string, double>>& overrides) {
  const ModelRun run = run_model("helix", overrides);
  EXPECT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_EQ(run.rows.size(), 501u);
  const auto [m, g, R, alpha] = parameters(run, overrides);
  const double theta0 = run.at(0, "theta"), omega0 = run.at(0, "der(theta)");
  const double thetaddot = -g * alpha / (R * (1 + alpha * alpha));
  Errors e;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double t = run.at(k, "t");
    const double theta = theta0 + omega0 * t + 0.5 * thetaddot * t * t;
    const double thetadot = omega0 + thetaddot * t;
    const double lambda1 =
        m * g * alpha * theta / (1 + alpha * alpha) - m * R * thetadot * thetadot;
    const double lambda2 = m * g / (1 + alpha * alpha);
    // relative to the size of λ_1's terms (λ_1 itself passes through zero)
    const double scale1 = std::abs(m * g * alpha * theta / (1 + alpha * alpha)) +
                          m * R * thetadot * thetadot + lambda2;
    e.theta =
        std::max(e.theta, std::abs(run.at(k, "theta") - theta) / std::max(1.0, std::abs(theta)));
    e.thetadot = std::max(e.thetadot, std::abs(run.at(k, "der(theta)") - thetadot) /
                                          std::max(1.0, std::abs(thetadot)));
    e.cylinder = std::max(e.cylinder, std::abs(run.at(k, "lambda(cylinder)") - lambda1) / scale1);
    e.helicoid = std::max(e.helicoid, std::abs(run.at(k, "lambda(helicoid)") - lambda2) / lambda2);
    e.r = std::max(e.r, std::abs(run.at(k, "r") - R));
    e.eta = std::max(e.eta, std::abs(run.at(k, "eta")));
    e.rdot = std::max(e.rdot, std::abs(run.at(k, "der(r)")));
    e.etadot = std::max(e.etadot, std::abs(run.at(k, "der(eta)")));
  }
  std::printf(
      "theta %.3g, theta' %.3g, lambda(cylinder) %.3g, lambda(helicoid) %.3g (relative); |r - R| "
      "%.3g, |eta| %.3g, |r'| %.3g, |eta'| %.3g; theta(5) = %.4g\n",
      e.theta, e.thetadot, e.cylinder, e.helicoid, e.r, e.eta, e.rdot, e.etadot,
      run.at(run.rows.size() - 1, "theta"));
  return e;
}

void expect_book_agreement(const Errors& e) {
  // θ is quadratic in t: dopri5 at rtol 1e-12 reproduces it to round-off (θ reaches ~30 rad).
  EXPECT_LT(e.theta, 1e-10);
  EXPECT_LT(e.thetadot, 1e-10);
  // λ follows from the state through the linear solve: the state's error, relative.
  EXPECT_LT(e.cylinder, 1e-8);
  EXPECT_LT(e.helicoid, 1e-8);
  // projection holds Ψ and Ψ̇ at round-off
  EXPECT_LT(e.r, 1e-12);
  EXPECT_LT(e.eta, 1e-12);
  EXPECT_LT(e.rdot, 1e-12);
  EXPECT_LT(e.etadot, 1e-12);
}

// §3.8, (3.18) and the constraint force after it, with the model's parameters.
TEST(Helix, ClosedFormMotionAndMultipliers) {
  expect_book_agreement(compare_with_book({}));
}

// §3.8, (3.18) with other parameters and initial state, so that the agreement is not an accident of
// the model's values.
TEST(Helix, ClosedFormWithOtherParameters) {
  expect_book_agreement(
      compare_with_book({{"alpha", 0.7}, {"R", 2.0}, {"m", 0.4}, {"der(theta)", -1.0}}));
}

// §3.8: the helix is fixed and smooth, so E = (m/2)(1 + α²)R²θ̇² + mgαRθ is conserved; the model's
// energy column is T + mgz with z = η + αrθ.
TEST(Helix, EnergyColumnIsTheBookEnergy) {
  const ModelRun run = run_model("helix");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto [m, g, R, alpha] = parameters(run, {});
  double worst = 0.0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double theta = run.at(k, "theta"), thetadot = run.at(k, "der(theta)");
    const double E =
        0.5 * m * (1 + alpha * alpha) * R * R * thetadot * thetadot + m * g * alpha * R * theta;
    worst = std::max(worst, std::abs(run.at(k, "energy") - E) / (std::abs(E) + m * g * R));
  }
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
}

}  // namespace
}  // namespace unidyn
