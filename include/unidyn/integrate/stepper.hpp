// The interface shared by the one-step integrators: advance one accepted step at a time, and give
// the solution anywhere inside the last step (dense output) for output rows and event location.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "unidyn/integrate/ode.hpp"

namespace unidyn {

// A one-step method for y' = f(t, y). Integration runs forward or backward, toward the t_limit of
// each step() call. Usage: initialize(t0, y0); while (t() != t_end) step(t_end);
class Stepper {
 public:
  explicit Stepper(OdeFunction rhs);
  virtual ~Stepper() = default;

  // Start a new solution at (t0, y0); forgets the previous one and zeroes the statistics.
  // Throws std::invalid_argument for a non-finite t0 or an empty or non-finite y0.
  void initialize(double t0, const Eigen::VectorXd& y0);

  // Take one accepted step toward t_limit that does not pass it; the step ends exactly on t_limit
  // when it reaches it. Throws IntegrationError on a non-finite derivative or state, a step-size
  // underflow, or an error test that cannot be met (the state then stays at the last accepted
  // step), and std::logic_error before initialize() or when t_limit equals t() or is not finite.
  void step(double t_limit);

  // The current time and state, and the time at which the last step began (= t() before any step).
  double t() const { return t_; }
  const Eigen::VectorXd& y() const { return y_; }
  double t_previous() const { return t_previous_; }

  // The solution anywhere in the last step [t_previous(), t()]; at t() exactly it is y(), also
  // after reset_state(). Throws std::out_of_range outside the last step. A method whose
  // continuous extension needs extra stages (dop853) evaluates them on the first call in a step.
  Eigen::VectorXd dense(double t);
  void dense(double t, Eigen::VectorXd& y_out);

  // Continue from a new point (t, y) — after an event changed the state or the equations —
  // as a new solution, keeping the statistics. Same checks as initialize().
  void restart_at(double t, const Eigen::VectorXd& y);

  // Replace the state at the current time, e.g. after a projection onto a constraint manifold. A
  // cached derivative at the old state (first-same-as-last) is dropped; the dense output of the
  // last step keeps describing the step as it was computed. Throws std::invalid_argument on a size
  // mismatch and IntegrationError on a non-finite state.
  void reset_state(const Eigen::VectorXd& y);

  const StepperStats& stats() const { return stats_; }

  // A short identifier of the method, e.g. "rk4", "dopri5".
  virtual std::string_view name() const = 0;

 protected:
  // Evaluate f(t, y) into dydt (sized here), counting the evaluation; returns whether every
  // component is finite. Throws std::logic_error when f resizes dydt.
  bool evaluate(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt);

  // As evaluate(), but a non-finite derivative throws IntegrationError at time t.
  void evaluate_finite(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt);

  // Make (t_new, y_new) the current point. y_new is swapped in: afterwards it holds the previous
  // state.
  void accept_step(double t_new, Eigen::VectorXd& y_new);

  StepperStats& mutable_stats() { return stats_; }

  // A fixed-step method's next step toward t_limit: a full step h (signed), or the rest of the way
  // when at most h (plus round-off) remains; and where it ends (t_limit exactly for the last).
  struct FixedStep {
    double h, t_end;
  };
  FixedStep fixed_step_toward(double t_limit, double step) const;

  // "<name>: " followed by the message, for error messages.
  std::string describe(std::string_view message) const;

 private:
  // A new solution begins at the current (t, y): drop everything cached from a previous one.
  virtual void restart() = 0;
  // The state at the current time is about to be replaced: drop the cached derivative (and keep
  // what the dense output of the last step still needs).
  virtual void before_reset_state() = 0;
  // One accepted step toward t_limit (t_limit ≠ t(), both finite), ending with accept_step().
  virtual void advance(double t_limit) = 0;
  // Whatever the continuous extension of the last step still needs, before interpolate().
  virtual void prepare_dense() {}
  // The solution at t strictly inside the last step, into y_out.
  virtual void interpolate(double t, Eigen::VectorXd& y_out) const = 0;

  OdeFunction rhs_;
  bool initialized_ = false;
  double t_ = 0.0;
  double t_previous_ = 0.0;
  Eigen::VectorXd y_;
  StepperStats stats_;
};

}  // namespace unidyn
