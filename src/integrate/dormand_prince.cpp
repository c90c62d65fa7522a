// Dormand–Prince 5(4): stages, error control, automatic first step and dense output.
#include "unidyn/integrate/dormand_prince.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "dormand_prince_tableau.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

namespace dp = detail::dormand_prince;
using detail::to_text;

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(std::string("dopri5: ") + message);
}

void validate(const DormandPrinceOptions& o) {
  require(std::isfinite(o.rtol) && o.rtol >= 0.0, "rtol must be finite and non-negative");
  require(std::isfinite(o.atol) && o.atol > 0.0, "atol must be finite and positive");
  require(std::isfinite(o.initial_step) && o.initial_step >= 0.0,
          "initial_step must be finite and non-negative");
  require(o.max_step > 0.0, "max_step must be positive");
  require(std::isfinite(o.min_step) && o.min_step >= 0.0 && o.min_step <= o.max_step,
          "min_step must be finite, non-negative and at most max_step");
  require(o.max_steps > 0, "max_steps must be positive");
  require(std::isfinite(o.fixed_step) && o.fixed_step >= 0.0,
          "fixed_step must be finite and non-negative");
  require(o.safety > 0.0 && o.safety <= 1.0, "safety must be in (0, 1]");
  require(o.min_factor > 0.0 && o.min_factor < 1.0, "min_factor must be in (0, 1)");
  require(o.max_factor > 1.0 && std::isfinite(o.max_factor), "max_factor must be finite and > 1");
  require(o.beta >= 0.0 && o.beta < 0.2, "beta must be in [0, 0.2)");
}

// sqrt(mean(v²)), the norm of the error test.
double rms(const Eigen::ArrayXd& v) {
  return std::sqrt(v.square().sum() / double(v.size()));
}

}  // namespace

DormandPrince54::DormandPrince54(OdeFunction rhs, DormandPrinceOptions options)
    : Stepper(std::move(rhs)), options_(options) {
  validate(options_);
}

void DormandPrince54::restart() {
  h_ = 0.0;
  error_previous_ = 1e-4;
  have_derivative_ = false;
}

void DormandPrince54::before_reset_state() {
  have_derivative_ = false;
}

void DormandPrince54::advance(double t_limit) {
  // First stage: f(t, y), the last stage of the previous step unless the state was replaced.
  if (!have_derivative_) {
    evaluate_finite(t(), y(), k_[0]);
    have_derivative_ = true;
  }
  if (options_.fixed_step > 0.0) {
    take_fixed_step(t_limit);
  } else {
    take_adaptive_step(t_limit);
  }
}

void DormandPrince54::take_fixed_step(double t_limit) {
  // A full step toward the limit, or the rest of the way when at most one step (plus round-off)
  // remains.
  const double remaining = t_limit - t();
  const bool last = std::abs(remaining) <= options_.fixed_step * (1.0 + 1e-8);
  const double h = last ? remaining : std::copysign(options_.fixed_step, remaining);
  const double t_new = last ? t_limit : t() + h;
  h_ = options_.fixed_step;
  if (!attempt(h, t_new)) {
    throw IntegrationError(
        describe("the right-hand side or the state is not finite at t = " + to_text(t_bad_)),
        t_bad_);
  }
  commit(h, t_new);
}

void DormandPrince54::take_adaptive_step(double t_limit) {
  const double direction = t_limit > t() ? 1.0 : -1.0;
  if (h_ == 0.0) {
    h_ = options_.initial_step > 0.0 ? options_.initial_step : initial_step_size(direction);
  }
  StepperStats& stats = mutable_stats();
  const double exponent = 0.2 - 0.75 * options_.beta;
  bool rejected = false;
  bool saw_non_finite = false;
  double t_non_finite = 0.0;
  // Attempt, and on rejection shrink, until the error test passes (HNW I, §II.4).
  while (true) {
    if (stats.accepted_steps + stats.rejected_steps >= options_.max_steps) {
      throw IntegrationError(describe("reached max_steps = " + std::to_string(options_.max_steps) +
                                      " at t = " + to_text(t())),
                             t());
    }
    // Step-size underflow: below min_step, or too small to change t in floating point.
    const double h_abs = std::min(h_, options_.max_step);
    const double h_floor = 16.0 * std::numeric_limits<double>::epsilon() * std::abs(t());
    if (h_abs < options_.min_step || !(h_abs > h_floor) || t() + direction * h_abs == t()) {
      const std::string why =
          saw_non_finite ? "after the right-hand side or the state was not finite at t = " +
                               to_text(t_non_finite)
                         : "because the error test cannot be met";
      const std::string limit = h_abs < options_.min_step
                                    ? "step size " + to_text(h_abs) + " below min_step"
                                    : "step size underflow (h = " + to_text(h_abs) + ")";
      throw IntegrationError(describe(limit + " at t = " + to_text(t()) + " " + why), t());
    }
    // The rest of the way when at most 1% beyond this step (as DOPRI5) and within max_step.
    const double remaining = std::abs(t_limit - t());
    const bool last = remaining <= 1.01 * h_abs && remaining <= options_.max_step;
    const double h = last ? t_limit - t() : direction * h_abs;
    const double t_new = last ? t_limit : t() + h;

    // A non-finite stage or state: reject and shrink, so that the failure is located closely.
    if (!attempt(h, t_new)) {
      saw_non_finite = true;
      t_non_finite = t_bad_;
      h_ = std::abs(h) * options_.min_factor;
      rejected = true;
      ++stats.rejected_steps;
      continue;
    }
    // (HNW I, (4.13)) h_new = h (1/err)^(1/5) with safety and factor limits; PI stabilisation by
    // err_old^beta as in DOPRI5. After a rejection the step may not grow.
    const double error = error_norm(h);
    const double factor_i = std::pow(error, exponent);
    if (error <= 1.0) {
      const double factor =
          std::clamp(factor_i / std::pow(error_previous_, options_.beta) / options_.safety,
                     1.0 / options_.max_factor, 1.0 / options_.min_factor);
      double h_next = std::abs(h) / factor;
      if (rejected) h_next = std::min(h_next, std::abs(h));
      error_previous_ = std::max(error, 1e-4);
      h_ = std::min(h_next, options_.max_step);
      commit(h, t_new);
      return;
    }
    h_ = std::abs(h) / std::min(1.0 / options_.min_factor, factor_i / options_.safety);
    rejected = true;
    ++stats.rejected_steps;
  }
}

double DormandPrince54::initial_step_size(double direction) {
  // (HNW I, §II.4, "Starting step size") with the RMS norm of the error test.
  const Eigen::VectorXd& y0 = y();
  const Eigen::VectorXd& f0 = k_[0];
  const Eigen::ArrayXd scale = options_.atol + options_.rtol * y0.array().abs();
  // (a) d0 = ‖y0‖, d1 = ‖f(t0, y0)‖
  const double d0 = rms(y0.array() / scale);
  const double d1 = rms(f0.array() / scale);
  // (b) h0 = 0.01 d0/d1, or 1e-6 when either is tiny
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min(h0, options_.max_step);
  // (c) one explicit Euler step; a non-finite derivative there: keep h0, the step control shrinks
  // it
  stage_ = y0 + (direction * h0) * f0;
  if (!evaluate(t() + direction * h0, stage_, k_[1])) return h0;
  // (d) d2 = ‖f(t0 + h0, y1) − f(t0, y0)‖ / h0, an estimate of the second derivative
  const double d2 = rms((k_[1] - f0).array() / scale) / h0;
  // (e) h1 = (0.01 / max(d1, d2))^(1/(p+1)) with p + 1 = 5
  const double d_max = std::max(d1, d2);
  const double h1 = d_max <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d_max, 0.2);
  // (f) h = min(100 h0, h1)
  return std::min({100.0 * h0, h1, options_.max_step});
}

bool DormandPrince54::attempt(double h, double t_new) {
  const double t0 = t();
  const Eigen::VectorXd& y0 = y();
  auto& k = k_;
  // Stages 2–6 at t0 + c_i h; stage 6 at the step's end.
  stage_ = y0 + (h * dp::a21) * k[0];
  t_bad_ = t0 + dp::c2 * h;
  if (!evaluate(t_bad_, stage_, k[1])) return false;
  stage_ = y0 + h * (dp::a31 * k[0] + dp::a32 * k[1]);
  t_bad_ = t0 + dp::c3 * h;
  if (!evaluate(t_bad_, stage_, k[2])) return false;
  stage_ = y0 + h * (dp::a41 * k[0] + dp::a42 * k[1] + dp::a43 * k[2]);
  t_bad_ = t0 + dp::c4 * h;
  if (!evaluate(t_bad_, stage_, k[3])) return false;
  stage_ = y0 + h * (dp::a51 * k[0] + dp::a52 * k[1] + dp::a53 * k[2] + dp::a54 * k[3]);
  t_bad_ = t0 + dp::c5 * h;
  if (!evaluate(t_bad_, stage_, k[4])) return false;
  stage_ =
      y0 + h * (dp::a61 * k[0] + dp::a62 * k[1] + dp::a63 * k[2] + dp::a64 * k[3] + dp::a65 * k[4]);
  t_bad_ = t_new;
  if (!evaluate(t_new, stage_, k[5])) return false;
  // The fifth-order solution, and its derivative: stage 7, the next step's first (FSAL).
  y_new_ =
      y0 + h * (dp::a71 * k[0] + dp::a73 * k[2] + dp::a74 * k[3] + dp::a75 * k[4] + dp::a76 * k[5]);
  if (!y_new_.allFinite()) return false;
  return evaluate(t_new, y_new_, k[6]);
}

double DormandPrince54::error_norm(double h) {
  const auto& k = k_;
  // err = h Σ e_i k_i, weighted by atol + rtol max(|y|, |y_new|)
  error_ = h * (dp::e1 * k[0] + dp::e3 * k[2] + dp::e4 * k[3] + dp::e5 * k[4] + dp::e6 * k[5] +
                dp::e7 * k[6]);
  const Eigen::ArrayXd scale =
      options_.atol + options_.rtol * y().array().abs().max(y_new_.array().abs());
  return rms(error_.array() / scale);
}

void DormandPrince54::commit(double h, double t_new) {
  const auto& k = k_;
  const Eigen::VectorXd& y0 = y();
  // Dense output (DOPRI5 CONTD5): r1 = y1 − y0, r2 = h k1 − r1, r3 = r1 − h k7 − r2, r4 = h Σ d_i
  // k_i.
  r_[0] = y_new_ - y0;
  r_[1] = h * k[0] - r_[0];
  r_[2] = r_[0] - h * k[6] - r_[1];
  r_[3] = h * (dp::d1 * k[0] + dp::d3 * k[2] + dp::d4 * k[3] + dp::d5 * k[4] + dp::d6 * k[5] +
               dp::d7 * k[6]);
  // First same as last: f(t_new, y_new) is the next step's first stage.
  k_[0].swap(k_[6]);
  have_derivative_ = true;
  accept_step(t_new, y_new_);
  y_previous_.swap(y_new_);
}

void DormandPrince54::interpolate(double t, Eigen::VectorXd& y_out) const {
  const double theta = (t - t_previous()) / (this->t() - t_previous());
  const double one_minus = 1.0 - theta;
  // y(t_prev + θh) = y_prev + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ) r4)))
  y_out = y_previous_ + theta * (r_[0] + one_minus * (r_[1] + theta * (r_[2] + one_minus * r_[3])));
}

}  // namespace unidyn
