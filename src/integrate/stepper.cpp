// The state, statistics and argument checks shared by every one-step method.
#include "unidyn/integrate/stepper.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "unidyn/numeric/number_text.hpp"

namespace unidyn {

Stepper::Stepper(OdeFunction rhs) : rhs_(std::move(rhs)) {
  if (!rhs_) throw std::invalid_argument("stepper: the right-hand side is empty");
}

void Stepper::initialize(double t0, const Eigen::VectorXd& y0) {
  if (!std::isfinite(t0)) throw std::invalid_argument(describe("initial time is not finite"));
  if (y0.size() == 0) throw std::invalid_argument(describe("initial state is empty"));
  if (!y0.allFinite()) throw std::invalid_argument(describe("initial state is not finite"));
  t_ = t0;
  t_previous_ = t0;
  y_ = y0;
  stats_ = {};
  initialized_ = true;
  restart();
}

void Stepper::restart_at(double t, const Eigen::VectorXd& y) {
  const StepperStats kept = stats_;
  initialize(t, y);
  stats_ = kept;
}

void Stepper::step(double t_limit) {
  if (!initialized_) throw std::logic_error(describe("step() before initialize()"));
  if (!std::isfinite(t_limit)) throw std::logic_error(describe("step limit is not finite"));
  if (t_limit == t_) {
    throw std::logic_error(describe("step limit equals the current time " + detail::to_text(t_)));
  }
  advance(t_limit);
}

Eigen::VectorXd Stepper::dense(double t) {
  Eigen::VectorXd y_out;
  dense(t, y_out);
  return y_out;
}

void Stepper::dense(double t, Eigen::VectorXd& y_out) {
  // The end points exactly; inside, the method's continuous extension.
  if (t == t_) {
    y_out = y_;
    return;
  }
  const bool inside =
      t_previous_ < t_ ? (t_previous_ <= t && t < t_) : (t_ < t && t <= t_previous_);
  if (!inside) {
    throw std::out_of_range(describe("dense output at t = " + detail::to_text(t) +
                                     " outside the last step [" + detail::to_text(t_previous_) +
                                     ", " + detail::to_text(t_) + "]"));
  }
  prepare_dense();
  interpolate(t, y_out);
}

void Stepper::reset_state(const Eigen::VectorXd& y) {
  if (!initialized_) throw std::logic_error(describe("reset_state() before initialize()"));
  if (y.size() != y_.size()) {
    throw std::invalid_argument(describe("reset_state() with a state of size " +
                                         std::to_string(y.size()) + ", expected " +
                                         std::to_string(y_.size())));
  }
  if (!y.allFinite()) {
    throw IntegrationError(describe("non-finite state set at t = " + detail::to_text(t_)), t_);
  }
  before_reset_state();
  y_ = y;
}

bool Stepper::evaluate(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  dydt.resize(y.size());
  ++stats_.rhs_evaluations;
  rhs_(t, y, dydt);
  if (dydt.size() != y.size()) {
    throw std::logic_error(describe("the right-hand side resized its output to " +
                                    std::to_string(dydt.size()) + ", expected " +
                                    std::to_string(y.size())));
  }
  return dydt.allFinite();
}

void Stepper::evaluate_finite(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
  if (evaluate(t, y, dydt)) return;
  const std::string what = y.allFinite() ? "the right-hand side returned a non-finite derivative"
                                         : "the state became non-finite";
  throw IntegrationError(describe(what + " at t = " + detail::to_text(t)), t);
}

void Stepper::accept_step(double t_new, Eigen::VectorXd& y_new) {
  t_previous_ = t_;
  t_ = t_new;
  y_.swap(y_new);
  ++stats_.accepted_steps;
}

Stepper::FixedStep Stepper::fixed_step_toward(double t_limit, double step) const {
  const double remaining = t_limit - t_;
  const bool last = std::abs(remaining) <= step * (1.0 + 1e-8);
  return last ? FixedStep{remaining, t_limit}
              : FixedStep{std::copysign(step, remaining), t_ + std::copysign(step, remaining)};
}

std::string Stepper::describe(std::string_view message) const {
  return std::string(name()) + ": " + std::string(message);
}

}  // namespace unidyn
