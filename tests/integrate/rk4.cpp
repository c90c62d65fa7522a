// Classic Runge–Kutta: closed-form solutions, the fourth order of the steps and of the dense
// output, the Kepler orbit, and the stepper contract (landing on the limit, failures, reset_state).
#include "unidyn/integrate/rk4.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "integrate/problems.hpp"

namespace unidyn {
namespace {

using test::vector;

TEST(Rk4, ExponentialDecayMatchesClosedForm) {
  Rk4 stepper(test::decay, 0.01);
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({2.0}), 1.0);
  EXPECT_NEAR(y[0], 2.0 * std::exp(-1.0), 1e-10);
}

TEST(Rk4, HarmonicOscillatorMatchesClosedForm) {
  const double omega = 2.0;
  Rk4 stepper(test::oscillator(omega), 0.01);
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0, 0.0}), 3.0);
  EXPECT_LT((y - test::oscillator_exact(omega, 3.0)).cwiseAbs().maxCoeff(), 1e-7);
}

// The global error at t = 5 of y' = y cos t falls 16-fold when h is halved.
TEST(Rk4, ConvergenceOrderIsFour) {
  std::vector<double> errors;
  for (double h : {0.1, 0.05, 0.025, 0.0125}) {
    Rk4 stepper(test::cosine_growth, h);
    const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0}), 5.0);
    errors.push_back(std::abs(y[0] - test::cosine_growth_exact(5.0)));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "rk4 observed order " << order << "\n";
    EXPECT_NEAR(order, 4.0, 0.3);
  }
}

// Dense output at interior points of every step, against the closed form: the cubic Hermite
// interpolant keeps the fourth order.
TEST(Rk4, DenseOutputIsFourthOrder) {
  std::vector<double> errors;
  for (double h : {0.2, 0.1, 0.05, 0.025}) {
    Rk4 stepper(test::cosine_growth, h);
    errors.push_back(test::cosine_growth_dense_error(stepper));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "rk4 dense output observed order " << order << "\n";
    EXPECT_GT(order, 3.7);
  }
}

// Simpson's rule makes a step exact for y' = t^q, q ≤ 3, and the cubic Hermite interpolant with
// exact end data is exact inside the step for q ≤ 2.
TEST(Rk4, ExactForLowDegreeQuadrature) {
  for (int q = 0; q <= 3; ++q) {
    Rk4 stepper(
        [q](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) { dydt[0] = std::pow(t, q); },
        1.0);
    stepper.initialize(0.0, vector({0.0}));
    stepper.step(1.0);
    EXPECT_NEAR(stepper.y()[0], 1.0 / (q + 1), 1e-15) << "q = " << q;
    if (q == 3) break;
    for (double theta : {0.1, 0.37, 0.5, 0.81}) {
      EXPECT_NEAR(stepper.dense(theta)[0], std::pow(theta, q + 1) / (q + 1), 1e-15)
          << "q = " << q << ", theta = " << theta;
    }
  }
}

// After one period of the e = 0.5 orbit the body is back at periapsis; energy and angular momentum
// stay at their closed-form values, and the position follows Kepler's equation.
TEST(Rk4, KeplerOrbitReturnsAfterOnePeriod) {
  const test::Kepler kepler{0.5};
  Rk4 stepper(test::Kepler::rhs, test::Kepler::kPeriod / 1000.0);
  const Eigen::VectorXd y0 = kepler.exact(0.0);
  stepper.initialize(0.0, y0);
  double energy_drift = 0.0, momentum_drift = 0.0, position_error = 0.0;
  while (stepper.t() != test::Kepler::kPeriod) {
    stepper.step(test::Kepler::kPeriod);
    const Eigen::VectorXd& y = stepper.y();
    energy_drift = std::max(energy_drift, std::abs(test::Kepler::energy_of(y) - kepler.energy()));
    momentum_drift = std::max(
        momentum_drift, std::abs(test::Kepler::angular_momentum_of(y) - kepler.angular_momentum()));
    position_error =
        std::max(position_error, (y - kepler.exact(stepper.t())).head<2>().cwiseAbs().maxCoeff());
  }
  EXPECT_LT((stepper.y() - y0).cwiseAbs().maxCoeff(), 5e-7);
  EXPECT_LT(energy_drift, 5e-9);
  EXPECT_LT(momentum_drift, 5e-10);
  EXPECT_LT(position_error, 3e-7);
}

// Steps of h, the last one shortened to end exactly on the limit; 4 evaluations per step plus the
// first derivative.
TEST(Rk4, LandsExactlyOnTheLimitAndReusesTheEndDerivative) {
  Rk4 stepper(test::decay, 0.3);
  stepper.initialize(0.0, vector({1.0}));
  std::vector<double> times;
  while (stepper.t() != 1.0) {
    stepper.step(1.0);
    times.push_back(stepper.t());
  }
  ASSERT_EQ(times.size(), 4u);
  EXPECT_DOUBLE_EQ(times[0], 0.3);
  EXPECT_DOUBLE_EQ(times[2], 0.9);
  EXPECT_EQ(times[3], 1.0);
  EXPECT_DOUBLE_EQ(stepper.t_previous(), 0.9);
  EXPECT_EQ(stepper.stats().accepted_steps, 4u);
  EXPECT_EQ(stepper.stats().rejected_steps, 0u);
  EXPECT_EQ(stepper.stats().rhs_evaluations, 4u * 4u + 1u);
}

TEST(Rk4, IntegratesBackward) {
  Rk4 stepper(test::decay, 0.01);
  const Eigen::VectorXd y = test::solve(stepper, 1.0, vector({std::exp(-1.0)}), 0.0);
  EXPECT_EQ(stepper.t(), 0.0);
  EXPECT_NEAR(y[0], 1.0, 1e-10);
}

// A derivative that turns NaN after t = 0.5 stops the integration within a step of 0.5; the state
// stays at the last good step.
TEST(Rk4, NonFiniteDerivativeThrowsNearItsTime) {
  const double h = 0.01;
  Rk4 stepper(
      [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        dydt = t > 0.5 ? Eigen::VectorXd::Constant(1, std::nan("")) : Eigen::VectorXd(-y);
      },
      h);
  stepper.initialize(0.0, vector({1.0}));
  try {
    while (stepper.t() != 1.0) stepper.step(1.0);
    FAIL() << "no IntegrationError";
  } catch (const IntegrationError& error) {
    EXPECT_GT(error.time(), 0.5);
    EXPECT_LE(error.time(), 0.5 + h + 1e-12);
    EXPECT_NE(std::string(error.what()).find("non-finite"), std::string::npos) << error.what();
  }
  EXPECT_LE(stepper.t(), 0.5);
  EXPECT_GT(stepper.t(), 0.5 - h - 1e-12);
  EXPECT_NEAR(stepper.y()[0], std::exp(-stepper.t()), 1e-10);
}

// reset_state drops the derivative cached from the old state: the next step equals that of a
// stepper started afresh at the new state.
TEST(Rk4, ResetStateDropsTheCachedDerivative) {
  Rk4 reset(test::cosine_growth, 0.1), fresh(test::cosine_growth, 0.1);
  reset.initialize(0.0, vector({1.0}));
  reset.step(1.0);
  const Eigen::VectorXd replaced = 3.0 * reset.y();
  reset.reset_state(replaced);
  EXPECT_EQ(reset.y(), replaced);
  fresh.initialize(reset.t(), replaced);
  reset.step(1.0);
  fresh.step(1.0);
  EXPECT_EQ(reset.t(), fresh.t());
  EXPECT_EQ(reset.y(), fresh.y());
}

// Dense output inside the last step still describes the step as computed after reset_state, and is
// the new state at its end.
TEST(Rk4, DenseOutputSurvivesResetState) {
  Rk4 stepper(test::cosine_growth, 0.1);
  stepper.initialize(0.0, vector({1.0}));
  stepper.step(1.0);
  const Eigen::VectorXd before = stepper.dense(0.05);
  stepper.reset_state(vector({7.0}));
  EXPECT_EQ(stepper.dense(0.05), before);
  EXPECT_EQ(stepper.dense(stepper.t())[0], 7.0);
  EXPECT_NEAR(stepper.dense(0.0)[0], 1.0, 1e-15);
  EXPECT_THROW(stepper.dense(0.2), std::out_of_range);
}

TEST(Rk4, RejectsInvalidArguments) {
  EXPECT_THROW(Rk4(test::decay, 0.0), std::invalid_argument);
  EXPECT_THROW(Rk4(test::decay, std::nan("")), std::invalid_argument);
  Rk4 stepper(test::decay, 0.1);
  EXPECT_THROW(stepper.step(1.0), std::logic_error);
  EXPECT_THROW(stepper.initialize(0.0, Eigen::VectorXd()), std::invalid_argument);
  stepper.initialize(0.0, vector({1.0}));
  EXPECT_THROW(stepper.step(0.0), std::logic_error);
  EXPECT_THROW(stepper.reset_state(vector({1.0, 2.0})), std::invalid_argument);
  EXPECT_THROW(stepper.reset_state(vector({std::nan("")})), IntegrationError);
}

}  // namespace
}  // namespace unidyn
