// The Dormand–Prince 5(4) explicit Runge–Kutta pair with step-size control and dense output.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <string_view>

#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// Settings of DormandPrince54; the defaults are those of Hairer's DOPRI5 except the tolerances.
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
  // Step-size controller (HNW I, §II.4 and the PI control of DOPRI5): h_new = h / fac with
  // fac = err^(1/5 − 0.75 beta) / err_old^beta / safety, limited to [1/max_factor, 1/min_factor].
  double safety = 0.9;
  double min_factor = 0.2;
  double max_factor = 10.0;
  double beta = 0.04;
};

// The RK5(4)7M pair of Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae",
// J. Comput. Appl. Math. 6, 19–26, as in HNW I, §II.5, Table 5.2: fifth-order solution,
// fourth-order error estimate, first-same-as-last (6 evaluations per step). Dense output is the
// fourth-order continuous extension of Shampine (1986) used by Hairer's DOPRI5 (HNW I, §II.6).
class DormandPrince54 final : public Stepper {
 public:
  // Throws std::invalid_argument for inconsistent options.
  explicit DormandPrince54(OdeFunction rhs, DormandPrinceOptions options = {});

  const DormandPrinceOptions& options() const { return options_; }
  // The size the next step will try (0 before the first step).
  double next_step_size() const { return h_; }
  std::string_view name() const override { return "dopri5"; }

 private:
  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // The automatic first step size toward direction (±1) (HNW I, §II.4).
  double initial_step_size(double direction);
  // Stages 2–7 of a step of size h from the current point, into k_ and y_new_; false when a
  // derivative or the new state is not finite (t_bad_ then holds where).
  bool attempt(double h, double t_new);
  // The weighted RMS norm of the error estimate of the last attempt.
  double error_norm(double h);
  // Make the last attempt the current point and build its dense output.
  void commit(double h, double t_new);
  void take_fixed_step(double t_limit);
  void take_adaptive_step(double t_limit);

  DormandPrinceOptions options_;
  // Next step size (magnitude; 0: not chosen yet) and the previous error for the PI controller.
  double h_ = 0.0;
  double error_previous_ = 1e-4;
  // Stage derivatives; k_[0] = f(t, y) is valid when have_derivative_ (first same as last).
  std::array<Eigen::VectorXd, 7> k_;
  bool have_derivative_ = false;
  Eigen::VectorXd stage_, y_new_, error_;
  double t_bad_ = 0.0;
  // Dense output of the last step: y(t_prev + θh) = y_prev + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ) r4))).
  Eigen::VectorXd y_previous_;
  std::array<Eigen::VectorXd, 4> r_;
};

}  // namespace unidyn
