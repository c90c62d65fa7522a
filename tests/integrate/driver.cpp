// The integration driver: the output grid (exact multiples, t_end exactly), rows from dense output
// without shortened steps, the post-step hook with reset_state, and failures that keep the rows.
#include "unidyn/integrate/driver.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "integrate/problems.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/dormand_prince_853.hpp"
#include "unidyn/integrate/rk4.hpp"

namespace unidyn {
namespace {

using test::vector;

struct Row {
  double t;
  Eigen::VectorXd y;
};

// Callbacks that collect the rows.
IntegrationCallbacks recorder(std::vector<Row>& rows) {
  IntegrationCallbacks callbacks;
  callbacks.output = [&rows](double t, const Eigen::VectorXd& y) { rows.push_back({t, y}); };
  return callbacks;
}

DormandPrinceOptions tolerances(double rtol, double atol) {
  return test::tolerances<DormandPrinceOptions>(rtol, atol);
}

// Rows at t0 + k h, each computed as such, then t_end exactly, with no near-duplicate before it.
TEST(Driver, RowsAtExactMultiplesAndAtTheEnd) {
  for (double t_end : {0.3, 0.6, 0.7, 1.0, 1.05, 2.9}) {
    Rk4 stepper(test::decay, 0.07);
    std::vector<Row> rows;
    const IntegrationResult result =
        integrate(stepper, 0.0, vector({1.0}), t_end, 0.1, recorder(rows));
    ASSERT_TRUE(result.ok) << result.message;
    const auto expected_rows = static_cast<std::size_t>(std::ceil(t_end / 0.1 - 1e-6)) + 1;
    ASSERT_EQ(rows.size(), expected_rows) << "t_end = " << t_end;
    EXPECT_EQ(result.rows, rows.size());
    for (std::size_t k = 0; k + 1 < rows.size(); ++k) EXPECT_EQ(rows[k].t, double(k) * 0.1);
    EXPECT_EQ(rows.back().t, t_end);
    EXPECT_GT(rows.back().t - rows[rows.size() - 2].t, 0.01);
    EXPECT_EQ(result.t, t_end);
    EXPECT_EQ(result.y, rows.back().y);
  }
}

TEST(Driver, RowsRunBackward) {
  DormandPrince54 stepper(test::decay, tolerances(1e-10, 1e-12));
  std::vector<Row> rows;
  const IntegrationResult result =
      integrate(stepper, 1.0, vector({1.0}), 0.0, 0.25, recorder(rows));
  ASSERT_TRUE(result.ok) << result.message;
  ASSERT_EQ(rows.size(), 5u);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_EQ(rows[k].t, 1.0 - double(k) * 0.25);
    EXPECT_NEAR(rows[k].y[0], std::exp(1.0 - rows[k].t), 1e-9);
  }
}

// Rows 10 times denser than the steps come from dense output and match e^(−t); the steps are the
// same as with a single output at the end.
TEST(Driver, RowsComeFromDenseOutputWithoutShorteningSteps) {
  DormandPrince54 dense_rows(test::decay, tolerances(1e-9, 1e-12));
  std::vector<Row> rows;
  const IntegrationResult result =
      integrate(dense_rows, 0.0, vector({1.0}), 4.0, 0.01, recorder(rows));
  ASSERT_TRUE(result.ok) << result.message;
  ASSERT_EQ(rows.size(), 401u);
  for (const Row& row : rows) EXPECT_NEAR(row.y[0], std::exp(-row.t), 1e-8) << "t = " << row.t;

  DormandPrince54 end_only(test::decay, tolerances(1e-9, 1e-12));
  const IntegrationResult reference = integrate(end_only, 0.0, vector({1.0}), 4.0, 10.0);
  EXPECT_EQ(reference.rows, 2u);
  EXPECT_EQ(result.stats.accepted_steps, reference.stats.accepted_steps);
  EXPECT_EQ(result.stats.rhs_evaluations, reference.stats.rhs_evaluations);
  EXPECT_LT(result.stats.accepted_steps, rows.size() / 4);
  EXPECT_EQ(result.y, reference.y);
}

// y' = ω × y + 0.1 y grows like e^(0.1 t) while rotating; a hook that renormalises after every step
// keeps |y| = 1 at the step ends (rows inside a step grow by at most e^(0.1 h) − 1), and the
// direction follows the rotation about ω = (0, 0, 2).
TEST(Driver, PostStepHookRenormalises) {
  const auto rhs = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt << -2.0 * y[1] + 0.1 * y[0], 2.0 * y[0] + 0.1 * y[1], 0.1 * y[2];
  };
  const Eigen::VectorXd y0 = Eigen::Vector3d(0.6, 0.0, 0.8);
  const auto direction = [&](double t) {
    return Eigen::Vector3d(0.6 * std::cos(2.0 * t), 0.6 * std::sin(2.0 * t), 0.8);
  };
  std::size_t hook_calls = 0;
  for (int method = 0; method < 2; ++method) {
    DormandPrince54 dopri5(rhs, tolerances(1e-10, 1e-12));
    Rk4 rk4(rhs, 0.005);
    Stepper& stepper = method == 0 ? static_cast<Stepper&>(dopri5) : rk4;
    std::vector<Row> rows;
    IntegrationCallbacks callbacks = recorder(rows);
    callbacks.post_step = [&hook_calls](double, Eigen::VectorXd& y) {
      y.normalize();
      ++hook_calls;
    };
    const IntegrationResult result = integrate(stepper, 0.0, y0, 5.0, 0.1, callbacks);
    ASSERT_TRUE(result.ok) << result.message;
    EXPECT_NEAR(result.y.norm(), 1.0, 1e-14) << stepper.name();
    for (const Row& row : rows) {
      EXPECT_NEAR(row.y.norm(), 1.0, 5e-3) << stepper.name() << " t = " << row.t;
      EXPECT_LT((row.y.normalized() - direction(row.t)).norm(), 1e-8)
          << stepper.name() << " t = " << row.t;
    }
    EXPECT_NEAR(rows.back().y.norm(), 1.0, 1e-14);
  }
  EXPECT_GT(hook_calls, 1000u);

  // Without the hook the norm grows to e^(0.5).
  DormandPrince54 free(rhs, tolerances(1e-10, 1e-12));
  EXPECT_NEAR(integrate(free, 0.0, y0, 5.0, 0.1).y.norm(), std::exp(0.5), 1e-8);
}

// A derivative that turns NaN after t = 0.5: ok = false with the time and a message; every row
// before is kept and correct, none after.
TEST(Driver, NonFiniteDerivativeKeepsTheRows) {
  const auto rhs = [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt = t > 0.5 ? Eigen::VectorXd::Constant(1, std::nan("")) : Eigen::VectorXd(-y);
  };
  for (int method = 0; method < 2; ++method) {
    DormandPrince54 dopri5(rhs, tolerances(1e-8, 1e-10));
    Rk4 rk4(rhs, 0.03);
    Stepper& stepper = method == 0 ? static_cast<Stepper&>(dopri5) : rk4;
    std::vector<Row> rows;
    const IntegrationResult result =
        integrate(stepper, 0.0, vector({1.0}), 1.0, 0.1, recorder(rows));
    EXPECT_FALSE(result.ok);
    EXPECT_NE(result.message.find("finite"), std::string::npos) << result.message;
    EXPECT_NEAR(result.t_failure, 0.5, 0.03) << stepper.name();
    EXPECT_LE(result.t, 0.5);
    ASSERT_GE(rows.size(), 5u) << stepper.name();
    EXPECT_EQ(result.rows, rows.size());
    for (std::size_t k = 0; k < rows.size(); ++k) {
      EXPECT_EQ(rows[k].t, double(k) * 0.1);
      EXPECT_LE(rows[k].t, result.t);
      EXPECT_NEAR(rows[k].y[0], std::exp(-rows[k].t), 1e-6);
    }
  }
}

// y' = y² from y(0) = 1 blows up at t = 1: failure with a message near t = 1, the rows before kept.
TEST(Driver, BlowUpReportsFailureAndKeepsTheRows) {
  DormandPrince54 stepper(
      [](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) { dydt = y.cwiseProduct(y); },
      tolerances(1e-8, 1e-10));
  std::vector<Row> rows;
  const IntegrationResult result = integrate(stepper, 0.0, vector({1.0}), 2.0, 0.1, recorder(rows));
  EXPECT_FALSE(result.ok);
  EXPECT_FALSE(result.message.empty());
  EXPECT_NEAR(result.t_failure, 1.0, 1e-6);
  ASSERT_GE(rows.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) {
    EXPECT_NEAR(rows[k].y[0] * (1.0 - rows[k].t), 1.0, 1e-6) << "t = " << rows[k].t;
  }
  EXPECT_GT(result.stats.accepted_steps, 0u);
}

// An exception from the right-hand side (e.g. a singular configuration) is a failure too.
TEST(Driver, ExceptionFromTheRightHandSideKeepsTheRows) {
  Rk4 stepper(
      [](double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        if (t > 0.35) throw std::domain_error("gimbal lock");
        dydt = -y;
      },
      0.01);
  std::vector<Row> rows;
  const IntegrationResult result = integrate(stepper, 0.0, vector({1.0}), 1.0, 0.1, recorder(rows));
  EXPECT_FALSE(result.ok);
  EXPECT_NE(result.message.find("gimbal lock"), std::string::npos) << result.message;
  EXPECT_EQ(rows.size(), 4u);
  EXPECT_NEAR(result.t_failure, 0.35, 0.01 + 1e-12);
}

TEST(Driver, ExceptionFromTheOutputPropagates) {
  Rk4 stepper(test::decay, 0.01);
  IntegrationCallbacks callbacks;
  callbacks.output = [](double t, const Eigen::VectorXd&) {
    if (t > 0.25) throw std::runtime_error("disk full");
  };
  EXPECT_THROW(integrate(stepper, 0.0, vector({1.0}), 1.0, 0.1, callbacks), std::runtime_error);
}

TEST(Driver, EqualEndsGiveOneRow) {
  Rk4 stepper(test::decay, 0.01);
  std::vector<Row> rows;
  const IntegrationResult result = integrate(stepper, 2.0, vector({1.0}), 2.0, 0.1, recorder(rows));
  EXPECT_TRUE(result.ok);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].t, 2.0);
}

TEST(Driver, RejectsInvalidArguments) {
  Rk4 stepper(test::decay, 0.01);
  EXPECT_THROW(integrate(stepper, 0.0, vector({1.0}), 1.0, 0.0), std::invalid_argument);
  EXPECT_THROW(integrate(stepper, 0.0, vector({1.0}), 1.0, -0.1), std::invalid_argument);
  EXPECT_THROW(integrate(stepper, 0.0, vector({1.0}), std::nan(""), 0.1), std::invalid_argument);
  EXPECT_THROW(integrate(stepper, 0.0, vector({std::nan("")}), 1.0, 0.1), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// A ball dropped from h bounces with restitution e: impacts at t1 = √(2h/g), then every
// 2 e^k v1/g later (v1 = g t1). Events y ≤ 0 located on the dense output, which is exact for a
// parabola: each impact lies 2 v⁺/g after the last one (v⁺ the speed the handler set) to
// kEventTimeTolerance (plus the dense output's round-off), and the chain of impacts follows the
// closed form to within those errors, each grown (1 + 2e)-fold by every later flight.
constexpr double kGravity = 9.81;
void expect_bouncing_ball_impact_times(Stepper& stepper) {
  const double g = kGravity, h = 1.0, e = 0.8;
  std::vector<double> impacts, speeds_after;
  std::vector<Row> rows;
  IntegrationCallbacks callbacks = recorder(rows);
  callbacks.events = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& values) {
    values.resize(1);
    values[0] = y[0];
  };
  callbacks.on_event = [&](double t, Eigen::VectorXd& y, std::size_t which) -> AfterEvent {
    EXPECT_EQ(which, 0u);
    impacts.push_back(t);
    y[0] = 0.0;
    y[1] = -e * y[1];
    speeds_after.push_back(y[1]);
    return AfterEvent::restart;
  };
  const IntegrationResult result = integrate(stepper, 0.0, vector({h, 0.0}), 3.0, 0.01, callbacks);
  ASSERT_TRUE(result.ok) << result.message;
  EXPECT_FALSE(result.stopped);
  const double v1 = std::sqrt(2 * g * h);
  double expected = v1 / g, speed = v1;
  ASSERT_GE(impacts.size(), 4u);
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const double t = impacts[i];
    if (i > 0) {
      EXPECT_NEAR(t, impacts[i - 1] + 2 * speeds_after[i - 1] / g, kEventTimeTolerance * t + 1e-14)
          << "impact " << i << " of " << stepper.name();
    }
    EXPECT_NEAR(t, expected, 1e-11) << "impact at " << expected << " of " << stepper.name();
    speed *= e;
    expected += 2 * speed / g;
  }
  // each impact has its own row, with the velocity after it; the grid rows are still k · 0.01
  std::size_t on_grid = 0, k = 0;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    if (r > 0) {
      EXPECT_GT(rows[r].t, rows[r - 1].t) << r;
    }
    if (k < impacts.size() && rows[r].t == impacts[k]) {
      EXPECT_EQ(rows[r].y[0], 0.0);
      EXPECT_GT(rows[r].y[1], 0.0);
      ++k;
    } else {
      EXPECT_NEAR(rows[r].t, 0.01 * double(on_grid++), 1e-12) << r;
    }
  }
  EXPECT_EQ(k, impacts.size());
  EXPECT_EQ(on_grid, 301u);
  EXPECT_EQ(result.rows, rows.size());
}

// The ball with both Dormand–Prince pairs (dop853's dense output evaluates its extra stages
// inside the event search).
TEST(DriverEvents, BouncingBallImpactTimes) {
  const OdeFunction ball = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
    dydt << y[1], -kGravity;
  };
  DormandPrince54 dopri5(ball, tolerances(1e-12, 1e-14));
  expect_bouncing_ball_impact_times(dopri5);
  DormandPrince853 dop853(ball, tolerances(1e-12, 1e-14));
  expect_bouncing_ball_impact_times(dop853);
}

// An event that stops the run: x = cos t reaches 0 at π/2; the rows stop there.
TEST(DriverEvents, StopEventEndsTheRunWhereItIsLocated) {
  DormandPrince54 stepper(test::oscillator(1.0), tolerances(1e-12, 1e-14));
  std::vector<Row> rows;
  IntegrationCallbacks callbacks = recorder(rows);
  callbacks.events = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& values) {
    values.resize(2);
    values << y[0], 2.0 + y[1];  // the second never reaches 0
  };
  double when = 0;
  callbacks.on_event = [&](double t, Eigen::VectorXd&, std::size_t which) -> AfterEvent {
    EXPECT_EQ(which, 0u);
    when = t;
    return AfterEvent::stop;
  };
  const IntegrationResult result =
      integrate(stepper, 0.0, vector({1.0, 0.0}), 10.0, 0.1, callbacks);
  ASSERT_TRUE(result.ok) << result.message;
  EXPECT_TRUE(result.stopped);
  EXPECT_NEAR(when, std::acos(0.0), 1e-10);
  EXPECT_EQ(result.t, when);
  EXPECT_EQ(rows.size(), 17u);  // 0, 0.1, …, 1.5, then the stop's own row
  EXPECT_EQ(rows.back().t, when);
  EXPECT_NEAR(rows.back().y[0], 0.0, 1e-12);
}

// A quiet event re-arms without a row: x = cos t, the event x · s ≤ 0 with s flipped at each
// crossing (π/2 + kπ) — five of them before t = 15 — and only the grid's rows come out.
TEST(DriverEvents, QuietEventsRestartWithoutARow) {
  DormandPrince54 stepper(test::oscillator(1.0), tolerances(1e-12, 1e-14));
  std::vector<Row> rows;
  IntegrationCallbacks callbacks = recorder(rows);
  double sign = 1.0;
  callbacks.events = [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& values) {
    values.resize(1);
    values[0] = sign * y[0];
  };
  std::vector<double> crossings;
  callbacks.on_event = [&](double t, Eigen::VectorXd&, std::size_t) -> AfterEvent {
    crossings.push_back(t);
    sign = -sign;
    return AfterEvent::restart_quietly;
  };
  const IntegrationResult result =
      integrate(stepper, 0.0, vector({1.0, 0.0}), 15.0, 0.5, callbacks);
  ASSERT_TRUE(result.ok) << result.message;
  ASSERT_EQ(crossings.size(), 5u);
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    EXPECT_NEAR(crossings[k], std::acos(0.0) * double(2 * k + 1), 1e-10);
  }
  EXPECT_EQ(result.event_rows, 0u);
  ASSERT_EQ(rows.size(), 31u);  // 0, 0.5, …, 15
  for (const Row& r : rows) EXPECT_NEAR(r.y[0], std::cos(r.t), 1e-9) << r.t;
}

// A handler that never lets its event settle — x = cos t, the event x ≤ 0, each handling puts x
// back to +1e-15 so that it fires again at once — is stopped after 1000 events at that instant
// with the reason, keeping the rows, instead of holding the run there for ever.
TEST(DriverEvents, EventsThatDoNotSettleStopTheRun) {
  DormandPrince54 stepper(test::oscillator(1.0), tolerances(1e-12, 1e-14));
  std::vector<Row> rows;
  IntegrationCallbacks callbacks = recorder(rows);
  callbacks.events = [](double, const Eigen::VectorXd& y, Eigen::VectorXd& values) {
    values.resize(1);
    values[0] = y[0];
  };
  std::size_t handled = 0;
  callbacks.on_event = [&](double, Eigen::VectorXd& y, std::size_t) -> AfterEvent {
    ++handled;
    y[0] = 1e-15;
    return AfterEvent::restart_quietly;
  };
  const IntegrationResult result =
      integrate(stepper, 0.0, vector({1.0, 0.0}), 15.0, 0.5, callbacks);
  ASSERT_FALSE(result.ok);
  EXPECT_EQ(handled, 1000u);
  EXPECT_NE(result.message.find("do not settle"), std::string::npos) << result.message;
  EXPECT_NEAR(result.t_failure, std::acos(0.0), 1e-6);
  EXPECT_EQ(rows.size(), 4u);  // 0, 0.5, 1, 1.5
}

}  // namespace
}  // namespace unidyn
