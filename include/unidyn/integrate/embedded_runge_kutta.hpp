// What the embedded explicit Runge–Kutta pairs share: the options, the step-size control with its
// rejections and failures, the automatic first step, and the first-same-as-last derivative.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <limits>

#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// Settings of the Dormand–Prince pairs (dopri5, dop853); the defaults are those of Hairer's DOPRI5
// except the tolerances, and dop853() gives those of his DOP853.
struct DormandPrinceOptions {
  // Error test: sqrt(mean((err_i / (atol + rtol max(|y_i|, |y_new_i|)))²)) ≤ 1. atol must be
  // positive.
  double rtol = 1e-6;
  double atol = 1e-9;
  // First step size; 0 chooses it automatically (HNW I, §II.4).
  double initial_step = 0.0;
  // Bounds on |h|: never larger than max_step; failure when the controller wants less than
  // min_step.
  double max_step = std::numeric_limits<double>::infinity();
  double min_step = 0.0;
  // Failure after this many attempted (accepted + rejected) steps since initialize().
  std::size_t max_steps = 100000;
  // > 0: steps of exactly this size without error control, e.g. to measure the order.
  double fixed_step = 0.0;
  // Step-size controller (HNW I, §II.4, with the PI control of Hairer's codes): h_new = h / fac
  // with fac = err^(exponent) / err_old^beta / safety, limited to [1/max_factor, 1/min_factor]; the
  // exponent is 1/5 − 0.75 beta for dopri5 and 1/8 − 0.2 beta for dop853.
  double safety = 0.9;
  double min_factor = 0.2;
  double max_factor = 10.0;
  double beta = 0.04;

  // Hairer's DOP853 controller: no PI term (beta 0), steps changed by factors in [1/3, 6].
  static DormandPrinceOptions dop853() {
    DormandPrinceOptions o;
    o.min_factor = 0.333;
    o.max_factor = 6.0;
    o.beta = 0.0;
    return o;
  }
};

// An explicit Runge–Kutta pair with an embedded error estimate and first same as last: the last
// stage of a step, f(t_new, y_new), is the first of the next. A method supplies its stages, error
// norm, order and continuous extension; the step control here is HNW I, §II.4.
class EmbeddedRungeKutta : public Stepper {
 public:
  // Throws std::invalid_argument for inconsistent options.
  EmbeddedRungeKutta(OdeFunction rhs, DormandPrinceOptions options);

  const DormandPrinceOptions& options() const { return options_; }
  // The size the next step will try (0 before the first step).
  double next_step_size() const { return h_; }

 protected:
  // f(t(), y()), the first stage of the next step (valid inside attempt()).
  const Eigen::VectorXd& first_stage() const { return f0_; }
  // In commit(): the derivative at the new point becomes the next first stage; `f_new` receives
  // the step's own first stage in exchange.
  void exchange_first_stage(Eigen::VectorXd& f_new);
  // The weights of the error test: atol + rtol max(|y_i|, |y_new_i|) (kept until the next call).
  const Eigen::ArrayXd& error_scale(const Eigen::VectorXd& y_new);
  // Where the last failed attempt found a non-finite stage or state.
  double t_bad_ = 0.0;

 private:
  // The order q of the error estimate's leading term, for the first step (h ~ tol^(1/q)).
  virtual int order() const = 0;
  // The exponent of err in the step-size controller, given beta.
  virtual double controller_exponent(double beta) const = 0;
  // The stages of a step of size h from the current point, ending at t_new; false when a
  // derivative or the new state is not finite (t_bad_ then holds where).
  virtual bool attempt(double h, double t_new) = 0;
  // The weighted RMS norm of the error estimate of the last attempt (≤ 1: accept).
  virtual double error_norm(double h) = 0;
  // Make the last attempt the current point (accept_step) and keep what its dense output needs.
  virtual void commit(double h, double t_new) = 0;
  // h|λ| of the last attempt, an estimate of where the step is in the stability region, and the
  // bound of that region along the negative axis; a negative estimate: the method has none.
  virtual double stiffness_estimate(double /*h*/) const { return -1.0; }
  virtual double stability_bound() const { return 0.0; }
  // Throws IntegrationError when the accepted steps are held by stability, not accuracy.
  void watch_stiffness(double h);

  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  // The automatic first step size toward direction (±1) (HNW I, §II.4).
  double initial_step_size(double direction);
  void take_fixed_step(double t_limit);
  void take_adaptive_step(double t_limit);

  DormandPrinceOptions options_;
  // Next step size (magnitude; 0: not chosen yet) and the previous error for the PI controller.
  double h_ = 0.0;
  double error_previous_ = 1e-4;
  // f(t, y) at the current point when have_f0_ (first same as last); scratch of the first step.
  Eigen::VectorXd f0_, probe_, f_probe_;
  Eigen::ArrayXd scale_;
  bool have_f0_ = false;
  // The stiffness test's counters (Hairer's DOPRI5: IASTI, NONSTI).
  int stiff_steps_ = 0, non_stiff_steps_ = 0;
};

}  // namespace unidyn
