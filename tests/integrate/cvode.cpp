// CVODE's BDF behind the Stepper interface: closed-form solutions, a stiff linear system that an
// explicit method could not cross in the same number of steps, the dense output against the closed
// form inside steps, projection inside the step, reset_state(), and failures that say why.
#include "unidyn/integrate/cvode.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "integrate/problems.hpp"
#include "unidyn/integrate/driver.hpp"

namespace unidyn {
namespace {

using test::vector;

CvodeOptions tolerances(double rtol, double atol) {
  return test::tolerances<CvodeOptions>(rtol, atol);
}

TEST(Cvode, ExponentialDecayMatchesClosedForm) {
  CvodeBdf stepper(test::decay, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({2.0}), 3.0);
  EXPECT_EQ(stepper.t(), 3.0);
  EXPECT_NEAR(y[0], 2.0 * std::exp(-3.0), 1e-8);
  EXPECT_GT(stepper.stats().accepted_steps, 10u);
  EXPECT_GT(stepper.last_order(), 1);  // the variable-order method went above backward Euler
}

TEST(Cvode, NonAutonomousGrowthMatchesClosedForm) {
  CvodeBdf stepper(test::cosine_growth, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0}), 10.0);
  EXPECT_NEAR(y[0], test::cosine_growth_exact(10.0), 1e-7);
}

// y1' = −y1, y2' = −10⁶ (y2 − cos t) − sin t: y2 = cos t + (y2(0) − 1) e^(−10⁶ t). An explicit
// method needs |h| < ~3e-6 for stability, i.e. ~3·10⁶ steps to t = 10; BDF follows the slow
// solution with steps set by accuracy alone.
TEST(Cvode, StiffSystemWithFewSteps) {
  const double k = 1e6;
  const OdeFunction rhs = [k](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = -y[0];
    dydt[1] = -k * (y[1] - std::cos(t)) - std::sin(t);
  };
  CvodeOptions options = tolerances(1e-8, 1e-10);
  options.max_steps = 20000;
  CvodeBdf stepper(rhs, options);
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0, 2.0}), 10.0);
  EXPECT_NEAR(y[0], std::exp(-10.0), 1e-7);
  EXPECT_NEAR(y[1], std::cos(10.0), 1e-7);
  EXPECT_LT(stepper.stats().accepted_steps, 20000u);
}

// Inside every step the Nordsieck polynomial follows the closed form of the oscillator.
TEST(Cvode, DenseOutputInsideSteps) {
  const double omega = 2.0;
  CvodeBdf stepper(test::oscillator(omega), tolerances(1e-10, 1e-12));
  stepper.initialize(0.0, vector({1.0, 0.0}));
  double largest = 0;
  while (stepper.t() < 5.0) {
    stepper.step(5.0);
    for (const double theta : {0.1, 0.5, 0.9}) {
      const double t = stepper.t_previous() + theta * (stepper.t() - stepper.t_previous());
      largest = std::max(
          largest, (stepper.dense(t) - test::oscillator_exact(omega, t)).cwiseAbs().maxCoeff());
    }
    EXPECT_EQ(stepper.dense(stepper.t()), stepper.y());
  }
  EXPECT_LT(largest, 1e-7);
  EXPECT_THROW((void)stepper.dense(5.5), std::out_of_range);
}

// Inside steps after which the order goes up, too: a heavily damped spring (x'' = −x − 10⁴ x',
// λ ≈ −10⁻⁴ and −10⁴) against its closed form. The polynomial of a step used to be taken to the
// next step's order, whose extra coefficient CVodeGetDky refuses: a stale one stood in, and points
// inside those steps were off by 1e-5 at rtol 1e-8.
TEST(Cvode, DenseOutputInsideStepsBeforeAnOrderIncrease) {
  const double c = 1e4;
  const OdeFunction rhs = [c](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt[0] = y[1];
    dydt[1] = -y[0] - c * y[1];
  };
  const double root = std::sqrt(c * c - 4.0);
  const double slow = (-c + root) / 2, fast = (-c - root) / 2;
  const double b = slow / (slow - fast), a = 1 - b;  // x(0) = 1, x'(0) = 0
  CvodeBdf stepper(rhs, tolerances(1e-8, 1e-10));
  stepper.initialize(0.0, vector({1.0, 0.0}));
  double largest = 0;
  while (stepper.t() < 100.0) {
    stepper.step(100.0);
    for (const double theta : {0.1, 0.5, 0.9}) {
      const double t = stepper.t_previous() + theta * (stepper.t() - stepper.t_previous());
      largest = std::max(
          largest, std::abs(stepper.dense(t)[0] - a * std::exp(slow * t) - b * std::exp(fast * t)));
    }
  }
  EXPECT_LT(largest, 1e-7);
}

// The circle |y| = 1 held by a projection inside the step: the radius stays 1 to round-off while
// the phase follows the closed form.
TEST(Cvode, ProjectionInsideTheStep) {
  CvodeOptions options = tolerances(1e-6, 1e-9);
  int projections = 0;
  options.projection = [&projections](double, Eigen::VectorXd& y) {
    y /= y.norm();
    ++projections;
  };
  CvodeBdf stepper(test::oscillator(1.0), options);
  stepper.initialize(0.0, vector({1.0, 0.0}));
  double radius_error = 0;
  while (stepper.t() < 20.0) {
    stepper.step(20.0);
    radius_error = std::max(radius_error, std::abs(stepper.y().norm() - 1.0));
  }
  EXPECT_LT(radius_error, 1e-14);
  EXPECT_GT(projections, 10);
  EXPECT_LT((stepper.y() - test::oscillator_exact(1.0, 20.0)).cwiseAbs().maxCoeff(), 1e-3);
}

// A replaced state restarts CVODE from it: the decay goes on from the new value.
TEST(Cvode, ResetStateRestartsFromTheNewState) {
  CvodeBdf stepper(test::decay, tolerances(1e-10, 1e-12));
  stepper.initialize(0.0, vector({1.0}));
  while (stepper.t() < 1.0) stepper.step(1.0);
  const Eigen::VectorXd before = stepper.dense(0.5 * (stepper.t_previous() + 1.0));
  stepper.reset_state(vector({3.0}));
  // the last step's dense output is kept, except its end is the new state
  EXPECT_EQ(stepper.dense(0.5 * (stepper.t_previous() + 1.0)), before);
  EXPECT_EQ(stepper.dense(1.0)[0], 3.0);
  while (stepper.t() < 2.0) stepper.step(2.0);
  EXPECT_NEAR(stepper.y()[0], 3.0 * std::exp(-1.0), 1e-8);
}

// The driver's rows and events work through CVODE: the oscillator's zero crossings at
// t = π/2 + kπ located to 1e-10.
TEST(Cvode, DriverLocatesEvents) {
  CvodeBdf stepper(test::oscillator(1.0), tolerances(1e-12, 1e-14));
  IntegrationCallbacks callbacks;
  std::vector<double> crossings;
  callbacks.events = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& g) {
    g.resize(1);
    g[0] = y[0];
  };
  callbacks.on_event = [&crossings](double t, Eigen::VectorXd& y, std::size_t) -> AfterEvent {
    crossings.push_back(t);
    y[0] = -y[0];  // reflect: x stays ≥ 0 (an impact with restitution 1)
    y[1] = -y[1];
    return AfterEvent::restart;
  };
  const IntegrationResult result =
      integrate(stepper, 0.0, vector({1.0, 0.0}), 10.0, 0.1, callbacks);
  ASSERT_TRUE(result.ok) << result.message;
  ASSERT_GE(crossings.size(), 3u);
  // |x| = |cos t| with the reflections: crossings at π/2 + kπ
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    EXPECT_NEAR(crossings[k], std::numbers::pi * (0.5 + static_cast<double>(k)), 1e-9);
  }
}

TEST(Cvode, FailuresSayWhy) {
  // an exception in the right-hand side reaches the caller as it was thrown
  const OdeFunction throwing = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    if (t > 0.5) throw std::domain_error("no model beyond 0.5");
    dydt = -y;
  };
  CvodeBdf stepper(throwing);
  stepper.initialize(0.0, vector({1.0}));
  EXPECT_THROW(
      {
        while (stepper.t() < 1.0) stepper.step(1.0);
      },
      std::domain_error);
  EXPECT_LE(stepper.t(), 0.5);
  // a finite-time blow-up y' = y² ends in an IntegrationError near t = 1
  const OdeFunction blow_up = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt = y.cwiseProduct(y);
  };
  CvodeBdf blowing(blow_up, tolerances(1e-8, 1e-10));
  blowing.initialize(0.0, vector({1.0}));
  try {
    while (blowing.t() < 2.0) blowing.step(2.0);
    ADD_FAILURE() << "no failure";
  } catch (const IntegrationError& e) {
    EXPECT_NEAR(e.time(), 1.0, 1e-3) << e.what();
    EXPECT_NE(std::string(e.what()).find("cvode: "), std::string::npos) << e.what();
  }
  EXPECT_THROW(CvodeBdf(test::decay, tolerances(1e-6, 0.0)), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
