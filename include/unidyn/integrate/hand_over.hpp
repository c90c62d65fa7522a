// The default integration of a model with position constraints: an index-1 method (dopri5, with
// error control) until its right-hand side meets a singular position — the constraints' rows lose
// rank, and the index-1 equations, which hold the positions only through their second derivatives,
// cannot say which branch the motion takes — then the index-3 augmented Lagrangian method
// (integrate/augmented_lagrangian.hpp), which holds the positions themselves, from the last
// accepted step through it; and the first method again once the caller finds the position passed
// (the second method is of second order with a fixed step: the first keeps the run's tolerance
// between singular positions).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <string_view>

#include "unidyn/integrate/stepper.hpp"

namespace unidyn {

// A singular position met by an index-1 method: thrown by its right-hand side. what() is the
// situation followed by the consequence.
class SingularPosition : public IntegrationError {
 public:
  SingularPosition(const std::string& situation, const std::string& consequence, double t)
      : IntegrationError(situation + consequence, t), situation_(situation) {}
  // "the constraints lose rank at t = ... (...)"
  const std::string& situation() const { return situation_; }

 private:
  std::string situation_;
};

class HandOver final : public Stepper {
 public:
  // `second` makes the method that takes over (at the first SingularPosition; it is restarted at
  // the later ones); `passed(t, y, steps)`, asked after each of its steps (the steps it took since
  // it took over), says when the first method may go on.
  using Passed = std::function<bool(double, const Eigen::VectorXd&, int)>;
  HandOver(std::unique_ptr<Stepper> first, std::function<std::unique_ptr<Stepper>()> second,
           Passed passed);

  // How many times the second method took over; where first (the last step the first one
  // accepted) and why (the situation of the first one's SingularPosition).
  int hand_overs() const { return hand_overs_; }
  // How many times the first method took the run back.
  int hand_backs() const { return hand_backs_; }
  double hand_over_time() const { return hand_over_time_; }
  const std::string& reason() const { return reason_; }
  // The method that takes the steps now.
  std::string_view name() const override { return active_->name(); }

 private:
  void restart() override { pending_ = Pending::restart; }
  // (a restart pending takes the new state with it)
  void before_reset_state() override {
    if (pending_ != Pending::restart) pending_ = Pending::reset;
  }
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override { last_->dense(t, y_out); }
  // The active method at this stepper's (t, y) after a restart or a reset here.
  void synchronize();
  // The second method from this stepper's point (the first one's last accepted step).
  void take_over(const SingularPosition& e);

  enum class Pending { none, restart, reset };
  std::unique_ptr<Stepper> first_, second_;
  std::function<std::unique_ptr<Stepper>()> make_second_;
  Passed passed_;
  // the method taking the steps, and the one that took the last step (the dense output's)
  Stepper* active_;
  Stepper* last_;
  Pending pending_ = Pending::none;
  bool started_ = false;
  int hand_overs_ = 0, hand_backs_ = 0, second_steps_ = 0;
  double hand_over_time_ = 0.0;
  std::string reason_;
};

}  // namespace unidyn
