// Dormand–Prince 5(4): closed-form solutions, the fifth order of the fixed-step method and the
// order of its dense output, error control (tolerance proportionality, rejections, max_step), the
// Kepler orbit, failures located in time, and first-same-as-last bookkeeping.
#include "unidyn/integrate/dormand_prince.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "integrate/problems.hpp"

namespace unidyn {
namespace {

using test::vector;

DormandPrinceOptions tolerances(double rtol, double atol) {
  return test::tolerances<DormandPrinceOptions>(rtol, atol);
}

DormandPrinceOptions fixed(double h) {
  DormandPrinceOptions options;
  options.fixed_step = h;
  return options;
}

TEST(DormandPrince, ExponentialDecayMatchesClosedForm) {
  DormandPrince54 stepper(test::decay, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({2.0}), 3.0);
  EXPECT_NEAR(y[0], 2.0 * std::exp(-3.0), 1e-10);
}

TEST(DormandPrince, HarmonicOscillatorMatchesClosedForm) {
  const double omega = 3.0;
  DormandPrince54 stepper(test::oscillator(omega), tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0, 0.0}), 4.0);
  EXPECT_LT((y - test::oscillator_exact(omega, 4.0)).cwiseAbs().maxCoeff(), 1e-8);
}

// Without error control the global error at t = 20 of y' = y cos t falls 32-fold when h is halved.
TEST(DormandPrince, FixedStepConvergenceOrderIsFive) {
  std::vector<double> errors;
  for (double h : {0.25, 0.125, 0.0625, 0.03125}) {
    DormandPrince54 stepper(test::cosine_growth, fixed(h));
    const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0}), 20.0);
    errors.push_back(std::abs(y[0] - test::cosine_growth_exact(20.0)));
    EXPECT_EQ(stepper.stats().rejected_steps, 0u);
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "dopri5 observed order " << order << "\n";
    EXPECT_NEAR(order, 5.0, 0.3);
  }
}

// Dense output at interior points of every fixed step, against the closed form: the continuous
// extension is of order 4, so the interpolated values converge at least that fast.
TEST(DormandPrince, DenseOutputOrderIsAtLeastFour) {
  std::vector<double> errors;
  for (double h : {0.4, 0.2, 0.1, 0.05}) {
    DormandPrince54 stepper(test::cosine_growth, fixed(h));
    errors.push_back(test::cosine_growth_dense_error(stepper));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "dopri5 dense output observed order " << order << "\n";
    EXPECT_GT(order, 3.7);
  }
}

// The continuous extension has order 4, so it integrates y' = t^q exactly for q ≤ 3 anywhere inside
// a step (the quadrature conditions Σ b_i(θ) c_i^q = θ^(q+1)/(q+1)); the step itself up to q = 4.
TEST(DormandPrince, DenseOutputIsExactForCubicQuadrature) {
  for (int q = 0; q <= 4; ++q) {
    DormandPrince54 stepper(
        [q](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) { dydt[0] = std::pow(t, q); },
        fixed(1.0));
    stepper.initialize(0.0, vector({0.0}));
    stepper.step(1.0);
    EXPECT_NEAR(stepper.y()[0], 1.0 / (q + 1), 1e-15) << "q = " << q;
    if (q == 4) break;
    for (double theta : {0.1, 0.37, 0.5, 0.81}) {
      EXPECT_NEAR(stepper.dense(theta)[0], std::pow(theta, q + 1) / (q + 1), 1e-15)
          << "q = " << q << ", theta = " << theta;
    }
  }
}

// One step of y' = −y from the exact value: the interpolation error at the middle of the step falls
// like h^5 (the local error of a fourth-order continuous extension).
TEST(DormandPrince, DenseOutputLocalErrorIsFifthPower) {
  std::vector<double> errors;
  for (double h : {0.4, 0.2, 0.1, 0.05}) {
    DormandPrince54 stepper(test::decay, fixed(h));
    stepper.initialize(0.0, vector({1.0}));
    stepper.step(h);
    errors.push_back(std::abs(stepper.dense(0.5 * h)[0] - std::exp(-0.5 * h)));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "dopri5 dense output local order " << order << "\n";
    EXPECT_GT(order, 4.7);
  }
}

// Dense output reproduces the step's end points and, on a one-step problem started from the exact
// solution, is accurate to the local error.
TEST(DormandPrince, DenseOutputMatchesTheEndPoints) {
  DormandPrince54 stepper(test::cosine_growth, tolerances(1e-8, 1e-10));
  stepper.initialize(0.0, vector({1.0}));
  stepper.step(10.0);
  const Eigen::VectorXd y_start = stepper.y();
  stepper.step(10.0);
  EXPECT_NEAR(stepper.dense(stepper.t_previous())[0], y_start[0], 1e-14);
  const double t_near_end = stepper.t() - 1e-9 * (stepper.t() - stepper.t_previous());
  EXPECT_NEAR(stepper.dense(t_near_end)[0], stepper.y()[0], 1e-9);
}

// Kepler e = 0.5: back at periapsis after one period, energy and angular momentum conserved, and
// the position inside steps (dense output) following Kepler's equation.
TEST(DormandPrince, KeplerOrbitReturnsAfterOnePeriod) {
  const test::Kepler kepler{0.5};
  DormandPrince54 stepper(test::Kepler::rhs, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y0 = kepler.exact(0.0);
  stepper.initialize(0.0, y0);
  double energy_drift = 0.0, momentum_drift = 0.0, dense_error = 0.0;
  while (stepper.t() != test::Kepler::kPeriod) {
    stepper.step(test::Kepler::kPeriod);
    const Eigen::VectorXd& y = stepper.y();
    energy_drift = std::max(energy_drift, std::abs(test::Kepler::energy_of(y) - kepler.energy()));
    momentum_drift = std::max(
        momentum_drift, std::abs(test::Kepler::angular_momentum_of(y) - kepler.angular_momentum()));
    const double t_mid = 0.5 * (stepper.t_previous() + stepper.t());
    dense_error =
        std::max(dense_error, (stepper.dense(t_mid) - kepler.exact(t_mid)).cwiseAbs().maxCoeff());
  }
  EXPECT_LT((stepper.y() - y0).cwiseAbs().maxCoeff(), 5e-8);
  EXPECT_LT(energy_drift, 1e-9);
  EXPECT_LT(momentum_drift, 1e-9);
  EXPECT_LT(dense_error, 5e-8);
}

// Tolerance proportionality: rtol 100 times smaller gives a global error (the largest over two
// Kepler periods) at least 30 times smaller.
TEST(DormandPrince, GlobalErrorScalesWithTolerance) {
  const test::Kepler kepler{0.5};
  const double t_end = 2.0 * test::Kepler::kPeriod;
  std::vector<double> errors;
  for (double rtol : {1e-6, 1e-8, 1e-10}) {
    DormandPrince54 stepper(test::Kepler::rhs, tolerances(rtol, rtol * 1e-3));
    stepper.initialize(0.0, kepler.exact(0.0));
    double error = 0.0;
    while (stepper.t() != t_end) {
      stepper.step(t_end);
      error = std::max(error, (stepper.y() - kepler.exact(stepper.t())).cwiseAbs().maxCoeff());
    }
    errors.push_back(error);
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    std::cout << "dopri5 error ratio for rtol / 100: " << errors[i] / errors[i + 1] << "\n";
    EXPECT_GT(errors[i] / errors[i + 1], 30.0);
  }
}

// y' = cos t + A exp(−((t − 1)/w)²): the narrow pulse at t = 1 forces rejected steps; the solution
// sin t + A w √π/2 (erf((t − 1)/w) + erf(1/w)) is still met.
TEST(DormandPrince, RejectsStepsAtASharpFeature) {
  const double amplitude = 10.0, width = 0.02;
  const auto pulse = [=](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) {
    dydt[0] = std::cos(t) + amplitude * std::exp(-std::pow((t - 1.0) / width, 2));
  };
  const auto exact = [=](double t) {
    return std::sin(t) + amplitude * width * std::sqrt(std::numbers::pi) / 2.0 *
                             (std::erf((t - 1.0) / width) + std::erf(1.0 / width));
  };
  DormandPrince54 stepper(pulse, tolerances(1e-8, 1e-10));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({0.0}), 2.0);
  EXPECT_GT(stepper.stats().rejected_steps, 0u);
  EXPECT_NEAR(y[0], exact(2.0), 1e-7);
}

// With max_step = 0.01 no step is longer, although the controller alone takes much longer steps.
TEST(DormandPrince, HonoursMaxStep) {
  const auto longest_step = [](DormandPrinceOptions options) {
    DormandPrince54 stepper(test::decay, options);
    stepper.initialize(0.0, vector({1.0}));
    double longest = 0.0;
    while (stepper.t() != 1.0) {
      stepper.step(1.0);
      longest = std::max(longest, stepper.t() - stepper.t_previous());
    }
    return longest;
  };
  DormandPrinceOptions options = tolerances(1e-4, 1e-6);
  EXPECT_GT(longest_step(options), 0.05);
  options.max_step = 0.01;
  EXPECT_LE(longest_step(options), 0.01 * (1.0 + 1e-12));
}

// The first step has the requested initial size when it passes the error test.
TEST(DormandPrince, TakesTheRequestedInitialStep) {
  DormandPrinceOptions options = tolerances(1e-6, 1e-9);
  options.initial_step = 1e-3;
  DormandPrince54 stepper(test::decay, options);
  stepper.initialize(0.0, vector({1.0}));
  stepper.step(1.0);
  EXPECT_EQ(stepper.t(), 1e-3);
  EXPECT_EQ(stepper.stats().rhs_evaluations, 7u);
}

// A derivative that turns NaN after t = 0.5: the step is shrunk onto the bad time, then
// IntegrationError reports it; the state stays valid.
TEST(DormandPrince, NonFiniteDerivativeIsLocated) {
  DormandPrince54 stepper(
      [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        dydt = t > 0.5 ? Eigen::VectorXd::Constant(1, std::nan("")) : Eigen::VectorXd(-y);
      },
      tolerances(1e-8, 1e-10));
  stepper.initialize(0.0, vector({1.0}));
  try {
    while (stepper.t() != 1.0) stepper.step(1.0);
    FAIL() << "no IntegrationError";
  } catch (const IntegrationError& error) {
    EXPECT_NEAR(error.time(), 0.5, 1e-9);
    EXPECT_NE(std::string(error.what()).find("not finite"), std::string::npos) << error.what();
  }
  EXPECT_LE(stepper.t(), 0.5);
  EXPECT_NEAR(stepper.y()[0], std::exp(-stepper.t()), 1e-8);
}

// y' = y², y(0) = 1 blows up at t = 1 (y = 1/(1 − t)): the step size underflows at the pole of the
// numerical solution, which lies within the global error (~rtol) of t = 1, on either side.
TEST(DormandPrince, BlowUpFailsAtTheSingularity) {
  DormandPrince54 stepper(
      [](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) { dydt = y.cwiseProduct(y); },
      tolerances(1e-8, 1e-10));
  stepper.initialize(0.0, vector({1.0}));
  double error_time = 0.0;
  try {
    while (stepper.t() != 2.0) stepper.step(2.0);
    FAIL() << "no IntegrationError";
  } catch (const IntegrationError& error) {
    error_time = error.time();
    EXPECT_NEAR(error.time(), 1.0, 1e-6);
    EXPECT_NE(std::string(error.what()).find("step size"), std::string::npos) << error.what();
  }
  EXPECT_EQ(stepper.t(), error_time);
  EXPECT_GT(stepper.y()[0], 1e10);
  EXPECT_TRUE(std::isfinite(stepper.y()[0]));
}

TEST(DormandPrince, StopsAfterMaxSteps) {
  DormandPrinceOptions options = tolerances(1e-6, 1e-9);
  options.max_steps = 10;
  options.max_step = 0.01;
  DormandPrince54 stepper(test::decay, options);
  stepper.initialize(0.0, vector({1.0}));
  try {
    while (stepper.t() != 1.0) stepper.step(1.0);
    FAIL() << "no IntegrationError";
  } catch (const IntegrationError& error) {
    EXPECT_NE(std::string(error.what()).find("max_steps"), std::string::npos) << error.what();
  }
  EXPECT_EQ(stepper.stats().accepted_steps, 10u);
}

// First same as last: 6 evaluations per attempted step, plus f(t0, y0) and one for the automatic
// initial step.
TEST(DormandPrince, ReusesTheLastStageAsTheNextFirst) {
  DormandPrince54 stepper(test::cosine_growth, tolerances(1e-8, 1e-10));
  test::solve(stepper, 0.0, vector({1.0}), 10.0);
  const StepperStats& stats = stepper.stats();
  EXPECT_EQ(stats.rhs_evaluations, 2u + 6u * (stats.accepted_steps + stats.rejected_steps));
}

// reset_state drops the first-same-as-last derivative: after the state is tripled mid-run the
// solution is 3 e^(−t), which a stale derivative would spoil; the next step evaluates f once more.
TEST(DormandPrince, ResetStateDropsTheLastStage) {
  DormandPrince54 stepper(test::decay, tolerances(1e-10, 1e-12));
  stepper.initialize(0.0, vector({1.0}));
  while (stepper.t() < 0.3) stepper.step(1.0);
  stepper.reset_state(3.0 * stepper.y());
  const std::size_t evaluations = stepper.stats().rhs_evaluations;
  stepper.step(1.0);
  EXPECT_EQ(stepper.stats().rhs_evaluations, evaluations + 7u);
  while (stepper.t() != 1.0) stepper.step(1.0);
  EXPECT_NEAR(stepper.y()[0], 3.0 * std::exp(-1.0), 1e-9);
}

// Fixed steps after reset_state equal those of a stepper started afresh at the new state.
TEST(DormandPrince, ResetStateMatchesAFreshStart) {
  DormandPrince54 reset(test::cosine_growth, fixed(0.1)), fresh(test::cosine_growth, fixed(0.1));
  reset.initialize(0.0, vector({1.0}));
  reset.step(1.0);
  reset.reset_state(2.0 * reset.y());
  fresh.initialize(reset.t(), reset.y());
  reset.step(1.0);
  fresh.step(1.0);
  EXPECT_EQ(reset.y(), fresh.y());
}

TEST(DormandPrince, IntegratesBackward) {
  DormandPrince54 stepper(test::cosine_growth, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y =
      test::solve(stepper, 4.0, vector({test::cosine_growth_exact(4.0)}), -1.0);
  EXPECT_EQ(stepper.t(), -1.0);
  EXPECT_NEAR(y[0], test::cosine_growth_exact(-1.0), 1e-9);
}

TEST(DormandPrince, RejectsInvalidOptions) {
  const auto make = [](DormandPrinceOptions options) { DormandPrince54 s(test::decay, options); };
  DormandPrinceOptions options;
  options.rtol = -1.0;
  EXPECT_THROW(make(options), std::invalid_argument);
  options = {};
  options.atol = 0.0;
  EXPECT_THROW(make(options), std::invalid_argument);
  options = {};
  options.max_step = 0.0;
  EXPECT_THROW(make(options), std::invalid_argument);
  options = {};
  options.min_step = 1.0;
  options.max_step = 0.5;
  EXPECT_THROW(make(options), std::invalid_argument);
  options = {};
  options.safety = 1.5;
  EXPECT_THROW(make(options), std::invalid_argument);
  EXPECT_NO_THROW(make(DormandPrinceOptions{}));
}

}  // namespace
}  // namespace unidyn
