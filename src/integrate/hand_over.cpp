// An index-1 method handing a run over to an index-3 one at a singular position (hand_over.hpp).
#include "unidyn/integrate/hand_over.hpp"

#include <stdexcept>
#include <utility>

namespace unidyn {

HandOver::HandOver(std::unique_ptr<Stepper> first, std::function<std::unique_ptr<Stepper>()> second,
                   Passed passed)
    : Stepper([](double, const Eigen::VectorXd&, Eigen::VectorXd&) {
        throw std::logic_error("hand-over: its methods evaluate their own right-hand sides");
      }),
      first_(std::move(first)),
      make_second_(std::move(second)),
      passed_(std::move(passed)),
      active_(first_.get()),
      last_(first_.get()) {}

void HandOver::synchronize() {
  if (pending_ == Pending::restart) {
    // a new solution from (t, y): the first start, or after an event
    if (started_) {
      active_->restart_at(t(), y());
    } else {
      active_->initialize(t(), y());
      started_ = true;
    }
  } else if (pending_ == Pending::reset) {
    active_->reset_state(y());
  }
  pending_ = Pending::none;
}

void HandOver::take_over(const SingularPosition& e) {
  if (hand_overs_++ == 0) {
    reason_ = e.situation();
    hand_over_time_ = t();
    second_ = make_second_();
    second_->initialize(t(), y());
  } else {
    second_->restart_at(t(), y());
  }
  active_ = second_.get();
  second_steps_ = 0;
}

void HandOver::advance(double t_limit) {
  synchronize();
  try {
    active_->step(t_limit);
  } catch (const SingularPosition& e) {
    if (active_ != first_.get()) throw;
    take_over(e);
    active_->step(t_limit);
  }
  last_ = active_;
  Eigen::VectorXd y1 = active_->y();
  accept_step(active_->t(), y1);
  // the first method again once the singular position is passed (from here, at the next step)
  if (active_ == second_.get() && passed_(t(), y(), ++second_steps_)) {
    active_ = first_.get();
    pending_ = Pending::restart;
    ++hand_backs_;
  }
  // the statistics of both methods
  StepperStats& stats = mutable_stats();
  stats = first_->stats();
  if (second_) {
    stats.rhs_evaluations += second_->stats().rhs_evaluations;
    stats.accepted_steps += second_->stats().accepted_steps;
    stats.rejected_steps += second_->stats().rejected_steps;
  }
}

}  // namespace unidyn
