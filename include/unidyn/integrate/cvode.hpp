// SUNDIALS CVODE's variable-order BDF method, for stiff models, behind the Stepper interface.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <exception>
#include <functional>
#include <memory>
#include <string_view>
#include <vector>

#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// Settings of CvodeBdf.
struct CvodeOptions {
  // CVODE's error test: the local error of each component below rtol |y_i| + atol.
  double rtol = 1e-6;
  double atol = 1e-9;
  // Failure after this many steps since initialize().
  std::size_t max_steps = 100000;
  // Highest BDF order (1..5).
  int max_order = 5;
  // Optional: put the state back on its constraint manifolds after each step. CVODE applies it
  // inside the step (CVodeSetProjFn), so its step history stays consistent — unlike replacing the
  // state from outside with reset_state(), which restarts the method at order 1.
  std::function<void(double t, Eigen::VectorXd& y)> projection;
};

// The BDF methods of orders 1–5 with Newton iterations on a dense difference-quotient Jacobian
// (Hindmarsh et al., "SUNDIALS: Suite of nonlinear and differential/algebraic equation solvers",
// ACM TOMS 31 (2005) 363–396). One step() is one internal CVODE step (CV_ONE_STEP) with the stop
// time at the limit. Dense output is CVODE's Nordsieck interpolating polynomial of the last step,
// kept as its Taylor coefficients at the end of the step, so that it survives a reset_state().
class CvodeBdf final : public Stepper {
 public:
  // Throws std::invalid_argument for inconsistent options.
  explicit CvodeBdf(OdeFunction rhs, CvodeOptions options = {});
  ~CvodeBdf() override;
  CvodeBdf(const CvodeBdf&) = delete;
  CvodeBdf& operator=(const CvodeBdf&) = delete;

  const CvodeOptions& options() const { return options_; }
  // The order and size of the last step.
  int last_order() const { return last_order_; }
  double last_step_size() const { return last_step_; }
  std::string_view name() const override { return "cvode"; }

  // CVODE's C callbacks (public for them; not part of the interface).
  struct Callbacks;

 private:
  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // Start CVODE at the current (t, y) with every option set.
  void start_solver();
  // Rethrow an exception caught in a callback, else throw IntegrationError for a failed step.
  [[noreturn]] void fail(int flag, double t_at);

  CvodeOptions options_;
  struct Solver;
  std::unique_ptr<Solver> solver_;
  // CVODE has to start again from the current point before the next step.
  bool start_pending_ = true;
  // An exception thrown by the right-hand side or the projection, rethrown after CVode returns.
  std::exception_ptr error_;
  // Dense output of the last step: y(t) = Σ_k taylor_[k] (t − t())^k / k!, k = 0..last_order_.
  std::vector<Eigen::VectorXd> taylor_;
  int last_order_ = 0;
  double last_step_ = 0.0;
};

}  // namespace unidyn
