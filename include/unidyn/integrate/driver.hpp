// Integration over an interval with output rows on a regular grid, a post-step hook, and failures
// reported without losing the rows already computed.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <string>

#include "unidyn/integrate/ode.hpp"
#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// What the integration does after an event's handler.
enum class AfterEvent {
  restart,          // the event's row, then a new start from the state the handler left
  restart_quietly,  // a new start, without a row: only the event functions' arming changed
  stop,             // the event's row, and the run ends there (successfully)
};

struct IntegrationCallbacks {
  // One output row (t, y); called in order of t.
  std::function<void(double t, const Eigen::VectorXd& y)> output;
  // After each accepted step, with the new state; may modify y (e.g. project it onto a constraint
  // manifold), which then replaces the stepper's state by reset_state().
  std::function<void(double t, Eigen::VectorXd& y)> post_step;
  // Event functions g(t, y) (g sized by the callee). An event is some g_i going from > 0 to ≤ 0
  // within a step: it is located on the dense output to within kEventTimeTolerance (the time
  // returned is on the ≤ 0 side), rows up to it are emitted, and on_event gets the state there,
  // which it may change (a new phase, an impulse); the event's own row follows, at its time (on
  // the grid or between two grid times) with the state on_event left, unless on_event says it
  // changed nothing worth one (AfterEvent); integration then restarts from it, or stops there.
  // Just after its event a g_i counts as positive, so that any return to ≤ 0, however brief the
  // excursion, is the next event.
  std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& g)> events;
  std::function<AfterEvent(double t, Eigen::VectorXd& y, std::size_t which)> on_event;
};

// Events are located to this relative accuracy in time (of max(1, |t|)).
inline constexpr double kEventTimeTolerance = 1e-13;

struct IntegrationResult {
  // false: the integration stopped at t_failure, with the reason in message (both unset when ok).
  bool ok = true;
  std::string message;
  double t_failure = 0.0;
  // The last accepted point (t_end on success) and the stepper's work.
  double t = 0.0;
  Eigen::VectorXd y;
  StepperStats stats;
  std::size_t rows = 0;
  // Of the rows, those at events between two output times.
  std::size_t event_rows = 0;
  // on_event asked to stop: the run ended at t before t_end, successfully.
  bool stopped = false;
};

// Integrate y' = f(t, y) with stepper from (t0, y0) to t_end (forward or backward). Rows are
// emitted at t0, t0 ± output_step, t0 ± 2 output_step, … (each computed as t0 ± k output_step) and
// at t_end exactly; rows between step ends come from dense output, so outputs never shorten steps.
// A grid time within 1e-9 output_step of t_end is replaced by t_end. On an IntegrationError, or any
// other exception from the right-hand side or the post-step hook, returns ok = false after having
// emitted every row up to the last accepted step. Throws std::invalid_argument for a non-finite t0
// or t_end, an output_step that is not positive and finite, or an invalid y0; exceptions from the
// output callback propagate.
IntegrationResult integrate(Stepper& stepper, double t0, const Eigen::VectorXd& y0, double t_end,
                            double output_step, const IntegrationCallbacks& callbacks = {});

}  // namespace unidyn
