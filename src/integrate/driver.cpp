// The integration driver: steps to t_end, emits rows on the output grid from dense output, applies
// the post-step hook, and turns failures into a result that keeps the data.
#include "unidyn/integrate/driver.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "unidyn/numeric/number_text.hpp"

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

// The earliest event in the last step [t_previous, t] of the stepper: the index of a g_i that went
// from > 0 to ≤ 0, and where (the ≤ 0 end of a bracket narrowed by the Illinois method on the dense
// output), or none.
struct Crossing {
  std::size_t which;
  double t;
};
std::optional<Crossing> earliest_crossing(Stepper& stepper, const IntegrationCallbacks& cb,
                                          const Eigen::VectorXd& g_before,
                                          const Eigen::VectorXd& g_after) {
  std::optional<Crossing> first;
  Eigen::VectorXd y, g;
  const double tolerance = kEventTimeTolerance * std::max(1.0, std::abs(stepper.t()));
  for (Eigen::Index i = 0; i < g_after.size(); ++i) {
    if (!(g_before[i] > 0.0 && g_after[i] <= 0.0)) continue;
    double ta = stepper.t_previous(), tb = stepper.t(), ga = g_before[i], gb = g_after[i];
    int kept_side = 0;  // Illinois: halve the value at an end kept twice in a row
    for (int iteration = 0; iteration < 200 && std::abs(tb - ta) > tolerance; ++iteration) {
      double tm = std::isfinite(ga) ? tb - gb * (tb - ta) / (gb - ga) : (ta + tb) / 2;
      if (!(tm > std::min(ta, tb) && tm < std::max(ta, tb))) tm = (ta + tb) / 2;
      stepper.dense(tm, y);
      cb.events(tm, y, g);
      if (g[i] > 0.0) {
        ta = tm;
        ga = g[i];
        if (kept_side == 1) gb /= 2;
        kept_side = 1;
      } else {
        tb = tm;
        gb = g[i];
        if (kept_side == -1) ga /= 2;
        kept_side = -1;
      }
    }
    const bool forward = stepper.t() > stepper.t_previous();
    if (!first || (forward ? tb < first->t : tb > first->t)) {
      first = Crossing{static_cast<std::size_t>(i), tb};
    }
  }
  return first;
}

// Events that do not settle: a handler that re-arms an event which fires again at once (a
// Zeno-like loop) would keep the run at one instant for ever. More than kMaxEventsAtAnInstant
// events within 1e-9 (relative) of the first of them stop the run with the reason.
constexpr int kMaxEventsAtAnInstant = 1000;
class EventStreak {
 public:
  void record(double t) {
    if (count_ == 0 || std::abs(t - first_) > 1e-9 * std::max(1.0, std::abs(first_))) {
      first_ = t;
      count_ = 0;
    }
    if (++count_ > kMaxEventsAtAnInstant) {
      throw IntegrationError(
          std::to_string(kMaxEventsAtAnInstant) +
              " events within 1e-9 of t = " + detail::to_text(first_) +
              ": the events there do not settle (each one's handling sets off the next)",
          t);
    }
  }

 private:
  double first_ = 0.0;
  int count_ = 0;
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
  // A row at t: the grid's next time (then the grid moves on), or an event's time between two.
  const auto emit = [&](double t, const Eigen::VectorXd& y) {
    in_output = true;
    if (callbacks.output) callbacks.output(t, y);
    in_output = false;
    ++result.rows;
    if (grid.reached(t)) {
      grid.advance();
    } else {
      ++result.event_rows;
    }
  };

  // The first row, then step by step: rows inside each step, the hook, the row at its end.
  emit(t0, y0);
  const bool with_events = callbacks.events && callbacks.on_event;
  Eigen::VectorXd g_before, g_after;
  EventStreak streak;
  try {
    if (with_events) callbacks.events(t0, y0, g_before);
    while (stepper.t() != t_end) {
      stepper.step(t_end);
      if (with_events) {
        callbacks.events(stepper.t(), stepper.y(), g_after);
        if (const auto event = earliest_crossing(stepper, callbacks, g_before, g_after)) {
          streak.record(event->t);
          // rows before the event, the state there, the handler, and a new start (or the end)
          while (grid.reached(event->t) && grid.next() != event->t) {
            stepper.dense(grid.next(), row);
            emit(grid.next(), row);
          }
          hooked = stepper.dense(event->t);
          if (callbacks.post_step) callbacks.post_step(event->t, hooked);
          const AfterEvent after = callbacks.on_event(event->t, hooked, event->which);
          // the event's own row, with the state the integration goes on from
          if (after != AfterEvent::restart_quietly) emit(event->t, hooked);
          stepper.restart_at(event->t, hooked);
          if (after == AfterEvent::stop) {
            result.stopped = true;
            break;
          }
          callbacks.events(event->t, hooked, g_before);
          // The handled g_i starts at ≈ 0, on either side: it counts as positive, so that its
          // next return to ≤ 0 is an event however short the excursion (the search probes
          // toward the step's start until it finds g_i > 0, or ends there).
          if (g_before[static_cast<Eigen::Index>(event->which)] <= 0.0) {
            g_before[static_cast<Eigen::Index>(event->which)] =
                std::numeric_limits<double>::infinity();
          }
          continue;
        }
      }
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
      if (with_events) callbacks.events(stepper.t(), stepper.y(), g_before);
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
