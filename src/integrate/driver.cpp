// The integration driver: steps to t_end, emits rows on the output grid from dense output, applies
// the post-step hook, and turns failures into a result that keeps the data.
#include "unidyn/integrate/driver.hpp"

#include <cmath>
#include <exception>
#include <stdexcept>

#include "format.hpp"

namespace unidyn {
namespace {

// Output times t0 + k·(±h), then t_end exactly.
class OutputGrid {
 public:
  OutputGrid(double t0, double t_end, double step)
      : t0_(t0), t_end_(t_end), step_(t_end >= t0 ? step : -step) {}

  double next() const { return next_; }
  bool done() const { return done_; }

  void advance() {
    if (next_ == t_end_) {
      done_ = true;
      return;
    }
    ++index_;
    const double t = t0_ + double(index_) * step_;
    // Grid times within a whisker of t_end, or beyond it, become t_end.
    next_ = (t_end_ - t) / step_ <= 1e-9 ? t_end_ : t;
  }

  // Whether the next output time lies at or before t in the direction of integration.
  bool reached(double t) const { return !done_ && (step_ > 0.0 ? next_ <= t : next_ >= t); }

 private:
  double t0_, t_end_, step_;
  std::size_t index_ = 0;
  double next_ = t0_;
  bool done_ = false;
};

}  // namespace

IntegrationResult integrate(Stepper& stepper, double t0, const Eigen::VectorXd& y0, double t_end,
                            double output_step, const IntegrationCallbacks& callbacks) {
  if (!std::isfinite(t0) || !std::isfinite(t_end)) {
    throw std::invalid_argument("integrate: t0 and t_end must be finite");
  }
  if (!(output_step > 0.0) || !std::isfinite(output_step)) {
    throw std::invalid_argument("integrate: output_step must be positive and finite");
  }
  stepper.initialize(t0, y0);
  IntegrationResult result;
  OutputGrid grid(t0, t_end, output_step);
  Eigen::VectorXd row, hooked;
  // Exceptions from the output callback are the caller's, not a failure of the integration.
  bool in_output = false;
  const auto emit = [&](double t, const Eigen::VectorXd& y) {
    in_output = true;
    if (callbacks.output) callbacks.output(t, y);
    in_output = false;
    ++result.rows;
    grid.advance();
  };

  // The first row, then step by step: rows inside each step, the hook, the row at its end.
  emit(t0, y0);
  try {
    while (stepper.t() != t_end) {
      stepper.step(t_end);
      while (grid.reached(stepper.t()) && grid.next() != stepper.t()) {
        stepper.dense(grid.next(), row);
        emit(grid.next(), row);
      }
      if (callbacks.post_step) {
        hooked = stepper.y();
        callbacks.post_step(stepper.t(), hooked);
        if (hooked.size() != stepper.y().size() || hooked != stepper.y()) {
          stepper.reset_state(hooked);
        }
      }
      if (grid.reached(stepper.t())) emit(stepper.t(), stepper.y());
    }
  } catch (const IntegrationError& error) {
    if (in_output) throw;
    result.ok = false;
    result.message = error.what();
    result.t_failure = error.time();
  } catch (const std::exception& error) {
    if (in_output) throw;
    result.ok = false;
    result.message = std::string(stepper.name()) + ": at t = " + detail::to_text(stepper.t()) +
                     ": " + error.what();
    result.t_failure = stepper.t();
  }
  result.t = stepper.t();
  result.y = stepper.y();
  result.stats = stepper.stats();
  return result;
}

}  // namespace unidyn
