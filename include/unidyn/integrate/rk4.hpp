// The classic fourth-order Runge–Kutta method with a fixed step.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// Classic RK4 (Hairer, Nørsett & Wanner, Solving ODEs I, §II.1, Table 1.2, left) with step h; the
// last step toward a limit is shortened to land on it. Dense output is the cubic Hermite
// interpolant of the values and derivatives at both ends of the step, whose error h⁴/384 max|y⁗|
// keeps the global fourth order. The derivative at the end of a step is reused as the first stage
// of the next (4 evaluations per step).
class Rk4 final : public Stepper {
 public:
  // Throws std::invalid_argument unless step_size is positive and finite.
  Rk4(OdeFunction rhs, double step_size);

  double step_size() const { return h_; }
  std::string_view name() const override { return "rk4"; }

 private:
  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  double h_;
  // f at the current point, valid when have_derivative_; f at the start of the last step.
  bool have_derivative_ = false;
  Eigen::VectorXd f_;
  Eigen::VectorXd f_previous_;
  // The state at the start of the last step, and at its end when reset_state() has replaced it.
  Eigen::VectorXd y_previous_;
  bool end_replaced_ = false;
  Eigen::VectorXd y_end_, f_end_;
  // Stage workspace.
  Eigen::VectorXd k2_, k3_, k4_, stage_, y_new_, f_new_;
};

}  // namespace unidyn
