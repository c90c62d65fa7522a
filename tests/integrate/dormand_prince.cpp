// The Dormand–Prince pairs, 5(4) and 8(5,3): closed-form solutions, the order of the fixed-step
// method and of its dense output, error control (tolerance proportionality, rejections,
// max_step), the Kepler orbit, failures located in time, and first-same-as-last bookkeeping. Each
// test runs on both pairs; the traits hold what differs.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "integrate/problems.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/dormand_prince_853.hpp"

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

// The global error at t = 20 of y' = y cos t, y(0) = 1, in fixed steps h.
template <class Pair>
double cosine_growth_error(double h) {
  Pair stepper(test::cosine_growth, fixed(h));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0}), 20.0);
  EXPECT_EQ(stepper.stats().rejected_steps, 0u);
  return std::abs(y[0] - test::cosine_growth_exact(20.0));
}

// The distance from the start after two periods of the circular Kepler orbit, in fixed steps of
// the given fraction of a period. (y' = y cos t shows no clean eighth order before round-off: its
// leading error term is small.)
template <class Pair>
double circular_orbit_error(double fraction) {
  const test::Kepler circle{0.0};
  Pair stepper(test::Kepler::rhs, fixed(fraction * test::Kepler::kPeriod));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, circle.exact(0.0), 2 * test::Kepler::kPeriod);
  return (y - circle.exact(0.0)).cwiseAbs().maxCoeff();
}

// What a test expects of each pair: the order of the method and of its continuous extension, the
// evaluations of f per attempted step (first same as last) and the extra ones of the dense output;
// a fixed-step global error and the step parameters (each half the last) that show the order
// above round-off.
template <class Pair>
struct PairTraits;
template <>
struct PairTraits<DormandPrince54> {
  static constexpr int order = 5, dense_order = 4;
  static constexpr std::size_t evaluations = 6, dense_evaluations = 0;
  static double fixed_step_error(double h) { return cosine_growth_error<DormandPrince54>(h); }
  static constexpr std::array<double, 4> steps = {0.25, 0.125, 0.0625, 0.03125};
  static constexpr std::array<double, 4> dense_steps = {0.4, 0.2, 0.1, 0.05};
};
template <>
struct PairTraits<DormandPrince853> {
  static constexpr int order = 8, dense_order = 7;
  static constexpr std::size_t evaluations = 12, dense_evaluations = 3;
  static double fixed_step_error(double fraction) {
    return circular_orbit_error<DormandPrince853>(fraction);
  }
  static constexpr std::array<double, 3> steps = {1.0 / 16, 1.0 / 32, 1.0 / 64};
  static constexpr std::array<double, 4> dense_steps = {0.8, 0.4, 0.2, 0.1};
};

template <class Pair>
class DormandPrince : public ::testing::Test {};
using Pairs = ::testing::Types<DormandPrince54, DormandPrince853>;
TYPED_TEST_SUITE(DormandPrince, Pairs);

TYPED_TEST(DormandPrince, ExponentialDecayMatchesClosedForm) {
  TypeParam stepper(test::decay, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({2.0}), 3.0);
  EXPECT_NEAR(y[0], 2.0 * std::exp(-3.0), 1e-10);
}

TYPED_TEST(DormandPrince, HarmonicOscillatorMatchesClosedForm) {
  const double omega = 3.0;
  TypeParam stepper(test::oscillator(omega), tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({1.0, 0.0}), 4.0);
  EXPECT_LT((y - test::oscillator_exact(omega, 4.0)).cwiseAbs().maxCoeff(), 1e-8);
}

// Without error control the global error falls 2^p-fold when h is halved (32 for dopri5, 256 for
// dop853).
TYPED_TEST(DormandPrince, FixedStepConvergenceOrder) {
  using Traits = PairTraits<TypeParam>;
  std::vector<double> errors;
  for (double h : Traits::steps) errors.push_back(Traits::fixed_step_error(h));
  for (double order : test::observed_orders(errors)) {
    std::cout << "observed order " << order << "\n";
    EXPECT_NEAR(order, Traits::order, 0.3);
  }
}

// Dense output at interior points of every fixed step, against the closed form: the continuous
// extension is of order 4 (dopri5) or 7 (dop853), so the interpolated values converge at least that
// fast.
TYPED_TEST(DormandPrince, DenseOutputOrder) {
  using Traits = PairTraits<TypeParam>;
  std::vector<double> errors;
  for (double h : Traits::dense_steps) {
    TypeParam stepper(test::cosine_growth, fixed(h));
    errors.push_back(test::cosine_growth_dense_error(stepper));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "dense output observed order " << order << "\n";
    EXPECT_GT(order, Traits::dense_order - 0.3);
  }
}

// A continuous extension of order r integrates y' = t^q exactly for q < r anywhere inside a step
// (the quadrature conditions Σ b_i(θ) c_i^q = θ^(q+1)/(q+1)); the step itself up to q = p − 1.
TYPED_TEST(DormandPrince, DenseOutputIsExactForPolynomialQuadrature) {
  using Traits = PairTraits<TypeParam>;
  for (int q = 0; q < Traits::order; ++q) {
    TypeParam stepper(
        [q](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) { dydt[0] = std::pow(t, q); },
        fixed(1.0));
    stepper.initialize(0.0, vector({0.0}));
    stepper.step(1.0);
    EXPECT_NEAR(stepper.y()[0], 1.0 / (q + 1), 1e-15) << "q = " << q;
    if (q >= Traits::dense_order) continue;
    for (double theta : {0.1, 0.37, 0.5, 0.81}) {
      EXPECT_NEAR(stepper.dense(theta)[0], std::pow(theta, q + 1) / (q + 1), 1e-15)
          << "q = " << q << ", theta = " << theta;
    }
  }
}

// One step of y' = −y from the exact value: the interpolation error at the middle of the step falls
// like h^(r+1), the local error of a continuous extension of order r.
TYPED_TEST(DormandPrince, DenseOutputLocalError) {
  using Traits = PairTraits<TypeParam>;
  std::vector<double> errors;
  for (double h : Traits::dense_steps) {
    TypeParam stepper(test::decay, fixed(h));
    stepper.initialize(0.0, vector({1.0}));
    stepper.step(h);
    errors.push_back(std::abs(stepper.dense(0.5 * h)[0] - std::exp(-0.5 * h)));
  }
  for (double order : test::observed_orders(errors)) {
    std::cout << "dense output local order " << order << "\n";
    EXPECT_GT(order, Traits::dense_order + 0.7);
  }
}

// Dense output reproduces the step's end points and, on a one-step problem started from the exact
// solution, is accurate to the local error.
TYPED_TEST(DormandPrince, DenseOutputMatchesTheEndPoints) {
  TypeParam stepper(test::cosine_growth, tolerances(1e-8, 1e-10));
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
TYPED_TEST(DormandPrince, KeplerOrbitReturnsAfterOnePeriod) {
  const test::Kepler kepler{0.5};
  TypeParam stepper(test::Kepler::rhs, tolerances(1e-10, 1e-12));
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
TYPED_TEST(DormandPrince, GlobalErrorScalesWithTolerance) {
  const test::Kepler kepler{0.5};
  const double t_end = 2.0 * test::Kepler::kPeriod;
  std::vector<double> errors;
  for (double rtol : {1e-6, 1e-8, 1e-10}) {
    TypeParam stepper(test::Kepler::rhs, tolerances(rtol, rtol * 1e-3));
    stepper.initialize(0.0, kepler.exact(0.0));
    double error = 0.0;
    while (stepper.t() != t_end) {
      stepper.step(t_end);
      error = std::max(error, (stepper.y() - kepler.exact(stepper.t())).cwiseAbs().maxCoeff());
    }
    errors.push_back(error);
  }
  for (std::size_t i = 0; i + 1 < errors.size(); ++i) {
    std::cout << "error ratio for rtol / 100: " << errors[i] / errors[i + 1] << "\n";
    EXPECT_GT(errors[i] / errors[i + 1], 30.0);
  }
}

// y' = cos t + A exp(−((t − 1)/w)²): the narrow pulse at t = 1 forces rejected steps; the solution
// sin t + A w √π/2 (erf((t − 1)/w) + erf(1/w)) is still met.
TYPED_TEST(DormandPrince, RejectsStepsAtASharpFeature) {
  const double amplitude = 10.0, width = 0.02;
  const auto pulse = [=](double t, const Eigen::VectorXd&, Eigen::VectorXd& dydt) {
    dydt[0] = std::cos(t) + amplitude * std::exp(-std::pow((t - 1.0) / width, 2));
  };
  const auto exact = [=](double t) {
    return std::sin(t) + amplitude * width * std::sqrt(std::numbers::pi) / 2.0 *
                             (std::erf((t - 1.0) / width) + std::erf(1.0 / width));
  };
  TypeParam stepper(pulse, tolerances(1e-8, 1e-10));
  const Eigen::VectorXd y = test::solve(stepper, 0.0, vector({0.0}), 2.0);
  EXPECT_GT(stepper.stats().rejected_steps, 0u);
  EXPECT_NEAR(y[0], exact(2.0), 1e-7);
}

// With max_step = 0.01 no step is longer, although the controller alone takes much longer steps.
TYPED_TEST(DormandPrince, HonoursMaxStep) {
  const auto longest_step = [](DormandPrinceOptions options) {
    TypeParam stepper(test::decay, options);
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
TYPED_TEST(DormandPrince, TakesTheRequestedInitialStep) {
  DormandPrinceOptions options = tolerances(1e-6, 1e-9);
  options.initial_step = 1e-3;
  TypeParam stepper(test::decay, options);
  stepper.initialize(0.0, vector({1.0}));
  stepper.step(1.0);
  EXPECT_EQ(stepper.t(), 1e-3);
  EXPECT_EQ(stepper.stats().rhs_evaluations, 1 + PairTraits<TypeParam>::evaluations);
}

// A derivative that turns NaN after t = 0.5: the step is shrunk onto the bad time, then
// IntegrationError reports it; the state stays valid.
TYPED_TEST(DormandPrince, NonFiniteDerivativeIsLocated) {
  TypeParam stepper(
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
TYPED_TEST(DormandPrince, BlowUpFailsAtTheSingularity) {
  TypeParam stepper(
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

TYPED_TEST(DormandPrince, StopsAfterMaxSteps) {
  DormandPrinceOptions options = tolerances(1e-6, 1e-9);
  options.max_steps = 10;
  options.max_step = 0.01;
  TypeParam stepper(test::decay, options);
  stepper.initialize(0.0, vector({1.0}));
  try {
    while (stepper.t() != 1.0) stepper.step(1.0);
    FAIL() << "no IntegrationError";
  } catch (const IntegrationError& error) {
    EXPECT_NE(std::string(error.what()).find("max_steps"), std::string::npos) << error.what();
  }
  EXPECT_EQ(stepper.stats().accepted_steps, 10u);
}

// First same as last: 6 (dopri5) or 12 (dop853) evaluations per attempted step, plus f(t0, y0) and
// one for the automatic initial step; a dense output adds its extra stages once in a step however
// often it is called.
TYPED_TEST(DormandPrince, ReusesTheLastStageAsTheNextFirst) {
  using Traits = PairTraits<TypeParam>;
  TypeParam stepper(test::cosine_growth, tolerances(1e-8, 1e-10));
  test::solve(stepper, 0.0, vector({1.0}), 10.0);
  const StepperStats& stats = stepper.stats();
  EXPECT_EQ(stats.rhs_evaluations,
            2u + Traits::evaluations * (stats.accepted_steps + stats.rejected_steps));
  const std::size_t before = stats.rhs_evaluations;
  const double t_inside = 0.5 * (stepper.t_previous() + stepper.t());
  const Eigen::VectorXd first = stepper.dense(t_inside);
  EXPECT_EQ(stepper.dense(t_inside), first);
  stepper.dense(0.25 * stepper.t_previous() + 0.75 * stepper.t());
  EXPECT_EQ(stepper.stats().rhs_evaluations, before + Traits::dense_evaluations);
}

// reset_state drops the first-same-as-last derivative: after the state is tripled mid-run the
// solution is 3 e^(−t), which a stale derivative would spoil; the next step evaluates f once more.
TYPED_TEST(DormandPrince, ResetStateDropsTheLastStage) {
  TypeParam stepper(test::decay, tolerances(1e-10, 1e-12));
  stepper.initialize(0.0, vector({1.0}));
  while (stepper.t() < 0.3) stepper.step(1.0);
  stepper.reset_state(3.0 * stepper.y());
  const std::size_t evaluations = stepper.stats().rhs_evaluations;
  stepper.step(1.0);
  EXPECT_EQ(stepper.stats().rhs_evaluations, evaluations + 1 + PairTraits<TypeParam>::evaluations);
  while (stepper.t() != 1.0) stepper.step(1.0);
  EXPECT_NEAR(stepper.y()[0], 3.0 * std::exp(-1.0), 1e-9);
}

// Fixed steps after reset_state equal those of a stepper started afresh at the new state.
TYPED_TEST(DormandPrince, ResetStateMatchesAFreshStart) {
  TypeParam reset(test::cosine_growth, fixed(0.1)), fresh(test::cosine_growth, fixed(0.1));
  reset.initialize(0.0, vector({1.0}));
  reset.step(1.0);
  reset.reset_state(2.0 * reset.y());
  fresh.initialize(reset.t(), reset.y());
  reset.step(1.0);
  fresh.step(1.0);
  EXPECT_EQ(reset.y(), fresh.y());
}

TYPED_TEST(DormandPrince, IntegratesBackward) {
  TypeParam stepper(test::cosine_growth, tolerances(1e-10, 1e-12));
  const Eigen::VectorXd y =
      test::solve(stepper, 4.0, vector({test::cosine_growth_exact(4.0)}), -1.0);
  EXPECT_EQ(stepper.t(), -1.0);
  EXPECT_NEAR(y[0], test::cosine_growth_exact(-1.0), 1e-9);
}

TYPED_TEST(DormandPrince, RejectsInvalidOptions) {
  const auto make = [](DormandPrinceOptions options) { TypeParam s(test::decay, options); };
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

// The point of the eighth-order pair: one Kepler period (e = 0.5) at rtol 1e-12 with an error as
// small as dopri5's and far fewer evaluations (HNW I, §II.10, work–precision diagrams).
TEST(DormandPrince853, MeetsATightToleranceWithLessWork) {
  const test::Kepler kepler{0.5};
  const Eigen::VectorXd y0 = kepler.exact(0.0);
  const auto run = [&](Stepper& stepper) {
    const Eigen::VectorXd y = test::solve(stepper, 0.0, y0, test::Kepler::kPeriod);
    return std::pair((y - y0).cwiseAbs().maxCoeff(), stepper.stats().rhs_evaluations);
  };
  DormandPrince54 dopri5(test::Kepler::rhs, tolerances(1e-12, 1e-14));
  DormandPrince853 dop853(test::Kepler::rhs, tolerances(1e-12, 1e-14));
  const auto [error5, work5] = run(dopri5);
  const auto [error8, work8] = run(dop853);
  std::cout << "Kepler period at rtol 1e-12: dopri5 error " << error5 << " in " << work5
            << " evaluations, dop853 " << error8 << " in " << work8 << "\n";
  EXPECT_LT(error8, 1e-9);
  EXPECT_LT(error8, 3 * error5);
  EXPECT_LT(2 * work8, work5);
}

}  // namespace
}  // namespace unidyn
