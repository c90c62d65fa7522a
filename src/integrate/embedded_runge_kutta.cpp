// Step-size control, the automatic first step and first-same-as-last bookkeeping of the embedded
// Runge–Kutta pairs.
#include "unidyn/integrate/embedded_runge_kutta.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

using detail::to_text;

void require(bool condition, const char* message) {
  if (!condition) throw std::invalid_argument(std::string("Dormand–Prince options: ") + message);
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

EmbeddedRungeKutta::EmbeddedRungeKutta(OdeFunction rhs, DormandPrinceOptions options)
    : Stepper(std::move(rhs)), options_(options) {
  validate(options_);
}

void EmbeddedRungeKutta::exchange_first_stage(Eigen::VectorXd& f_new) {
  f0_.swap(f_new);
  have_f0_ = true;
}

const Eigen::ArrayXd& EmbeddedRungeKutta::error_scale(const Eigen::VectorXd& y_new) {
  scale_ = options_.atol + options_.rtol * y().array().abs().max(y_new.array().abs());
  return scale_;
}

void EmbeddedRungeKutta::restart() {
  h_ = 0.0;
  error_previous_ = 1e-4;
  have_f0_ = false;
}

void EmbeddedRungeKutta::before_reset_state() {
  have_f0_ = false;
}

void EmbeddedRungeKutta::advance(double t_limit) {
  // First stage: f(t, y), the last stage of the previous step unless the state was replaced.
  if (!have_f0_) {
    evaluate_finite(t(), y(), f0_);
    have_f0_ = true;
  }
  if (options_.fixed_step > 0.0) {
    take_fixed_step(t_limit);
  } else {
    take_adaptive_step(t_limit);
  }
}

void EmbeddedRungeKutta::take_fixed_step(double t_limit) {
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

void EmbeddedRungeKutta::take_adaptive_step(double t_limit) {
  const double direction = t_limit > t() ? 1.0 : -1.0;
  if (h_ == 0.0) {
    h_ = options_.initial_step > 0.0 ? options_.initial_step : initial_step_size(direction);
  }
  StepperStats& stats = mutable_stats();
  const double exponent = controller_exponent(options_.beta);
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
    // (HNW I, (4.13)) h_new = h (1/err)^(1/q) with safety and factor limits; PI stabilisation by
    // err_old^beta as in Hairer's codes. After a rejection the step may not grow.
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
      watch_stiffness(h);
      commit(h, t_new);
      return;
    }
    h_ = std::abs(h) / std::min(1.0 / options_.min_factor, factor_i / options_.safety);
    rejected = true;
    ++stats.rejected_steps;
  }
}

// (HNW II, §IV.2, as Hairer's DOPRI5 does) Every 1000th accepted step, and at every step once
// one was found stiff: h|λ| ≈ h ‖f(t1, y1) − f(t1, ŷ)‖ / ‖y1 − ŷ‖ from two stages at the step's
// end. Past the stability bound 15 times (six steps below it in a row start the count again),
// the steps are held by the method's stability, not by its accuracy: an implicit method takes the
// model in a fraction of the steps, and this one would creep to max_steps.
void EmbeddedRungeKutta::watch_stiffness(double h) {
  const std::size_t accepted = stats().accepted_steps + 1;
  if (stiff_steps_ == 0 && accepted % 1000 != 0) return;
  const double h_lambda = stiffness_estimate(h);
  if (h_lambda < 0.0) return;
  if (h_lambda > stability_bound()) {
    non_stiff_steps_ = 0;
    if (++stiff_steps_ == 15) {
      throw IntegrationError(
          describe("the model is stiff at t = " + to_text(t()) +
                   ": the steps are held by the method's stability (h|lambda| = " +
                   to_text(h_lambda) + " at the bound " + to_text(stability_bound()) +
                   " fifteen times), not its accuracy; --method cvode (BDF) is made for this"),
          t());
    }
  } else if (++non_stiff_steps_ == 6) {
    stiff_steps_ = 0;
  }
}

double EmbeddedRungeKutta::initial_step_size(double direction) {
  // (HNW I, §II.4, "Starting step size") with the RMS norm of the error test.
  const Eigen::VectorXd& y0 = y();
  const Eigen::ArrayXd scale = options_.atol + options_.rtol * y0.array().abs();
  // (a) d0 = ‖y0‖, d1 = ‖f(t0, y0)‖
  const double d0 = rms(y0.array() / scale);
  const double d1 = rms(f0_.array() / scale);
  // (b) h0 = 0.01 d0/d1, or 1e-6 when either is tiny
  double h0 = (d0 < 1e-5 || d1 < 1e-5) ? 1e-6 : 0.01 * d0 / d1;
  h0 = std::min(h0, options_.max_step);
  // (c) one explicit Euler step; a non-finite derivative there: keep h0, the step control shrinks
  // it
  probe_ = y0 + (direction * h0) * f0_;
  if (!evaluate(t() + direction * h0, probe_, f_probe_)) return h0;
  // (d) d2 = ‖f(t0 + h0, y1) − f(t0, y0)‖ / h0, an estimate of the second derivative
  const double d2 = rms((f_probe_ - f0_).array() / scale) / h0;
  // (e) h1 = (0.01 / max(d1, d2))^(1/q)
  const double d_max = std::max(d1, d2);
  const double h1 =
      d_max <= 1e-15 ? std::max(1e-6, h0 * 1e-3) : std::pow(0.01 / d_max, 1.0 / order());
  // (f) h = min(100 h0, h1)
  return std::min({100.0 * h0, h1, options_.max_step});
}

}  // namespace unidyn
