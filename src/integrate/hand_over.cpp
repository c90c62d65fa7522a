// An index-1 method handing a run over to an index-3 one at a singular position (hand_over.hpp).
#include "unidyn/integrate/hand_over.hpp"

#include <stdexcept>
#include <utility>

namespace unidyn {

HandOver::HandOver(std::unique_ptr<Stepper> first, std::function<std::unique_ptr<Stepper>()> second)
    : Stepper([](double, const Eigen::VectorXd&, Eigen::VectorXd&) {
        throw std::logic_error("hand-over: its methods evaluate their own right-hand sides");
      }),
      first_(std::move(first)),
      make_second_(std::move(second)),
      active_(first_.get()) {}

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

void HandOver::advance(double t_limit) {
  synchronize();
  try {
    active_->step(t_limit);
  } catch (const SingularPosition& e) {
    if (second_) throw;
    // the second method from the first one's last accepted step (this stepper's point)
    reason_ = e.situation();
    hand_over_time_ = t();
    second_ = make_second_();
    second_->initialize(t(), y());
    active_ = second_.get();
    active_->step(t_limit);
  }
  Eigen::VectorXd y1 = active_->y();
  accept_step(active_->t(), y1);
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
