// Classic fourth-order Runge–Kutta with cubic Hermite dense output.
#include "unidyn/integrate/rk4.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "unidyn/numeric/number_text.hpp"

namespace unidyn {

Rk4::Rk4(OdeFunction rhs, double step_size) : Stepper(std::move(rhs)), h_(step_size) {
  if (!(h_ > 0.0) || !std::isfinite(h_)) {
    throw std::invalid_argument("rk4: the step size must be positive and finite");
  }
}

void Rk4::restart() {
  have_derivative_ = false;
  end_replaced_ = false;
}

void Rk4::before_reset_state() {
  have_derivative_ = false;
  if (!end_replaced_ && t() != t_previous()) {
    y_end_ = y();
    f_end_ = f_;
    end_replaced_ = true;
  }
}

void Rk4::advance(double t_limit) {
  const double t0 = t();
  const Eigen::VectorXd& y0 = y();
  // A full step h toward the limit, or the rest of the way when at most h (plus round-off) remains.
  const auto [h, t_new] = fixed_step_toward(t_limit, h_);

  // First stage: f(t, y), reused from the end of the previous step when still valid.
  if (!have_derivative_) {
    evaluate_finite(t0, y0, f_);
    have_derivative_ = true;
  }
  // (HNW I, Table 1.2) k2 = f(t + h/2, y + h/2 k1), k3 = f(t + h/2, y + h/2 k2), k4 = f(t + h, y +
  // h k3)
  stage_ = y0 + (0.5 * h) * f_;
  evaluate_finite(t0 + 0.5 * h, stage_, k2_);
  stage_ = y0 + (0.5 * h) * k2_;
  evaluate_finite(t0 + 0.5 * h, stage_, k3_);
  stage_ = y0 + h * k3_;
  evaluate_finite(t_new, stage_, k4_);
  // y1 = y + h/6 (k1 + 2 k2 + 2 k3 + k4)
  y_new_ = y0 + (h / 6.0) * (f_ + 2.0 * (k2_ + k3_) + k4_);
  if (!y_new_.allFinite()) {
    throw IntegrationError(describe("the state became non-finite at t = " + detail::to_text(t_new)),
                           t_new);
  }
  // The derivative at the new point: the Hermite end slope and the next step's first stage.
  evaluate_finite(t_new, y_new_, f_new_);

  // Commit: the current point becomes the start of the last step.
  f_previous_.swap(f_);
  f_.swap(f_new_);
  accept_step(t_new, y_new_);
  y_previous_.swap(y_new_);
  end_replaced_ = false;
}

void Rk4::interpolate(double t, Eigen::VectorXd& y_out) const {
  const double h = this->t() - t_previous();
  const double theta = (t - t_previous()) / h;
  const double one_minus = 1.0 - theta;
  // Cubic Hermite basis on [0, 1]: values h00, h01 and slopes h10, h11 (times h).
  const double h00 = (1.0 + 2.0 * theta) * one_minus * one_minus;
  const double h01 = theta * theta * (3.0 - 2.0 * theta);
  const double h10 = theta * one_minus * one_minus * h;
  const double h11 = -theta * theta * one_minus * h;
  const Eigen::VectorXd& y_end = end_replaced_ ? y_end_ : y();
  const Eigen::VectorXd& f_end = end_replaced_ ? f_end_ : f_;
  y_out = h00 * y_previous_ + h01 * y_end + h10 * f_previous_ + h11 * f_end;
}

}  // namespace unidyn
