// Ordinary differential equations y' = f(t, y): the right-hand side, the error an integration can
// end with, and the work counters every stepper keeps.
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

namespace unidyn {

// Right-hand side of y' = f(t, y). dydt arrives sized like y and must be filled; it must not be
// resized.
using OdeFunction = std::function<void(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt)>;

// An integration that cannot go on: a non-finite derivative or state, a step size that underflowed,
// an error test that cannot be met, too many steps. time() is where it happened.
class IntegrationError : public std::runtime_error {
 public:
  IntegrationError(const std::string& message, double time)
      : std::runtime_error(message), time_(time) {}

  double time() const noexcept { return time_; }

 private:
  double time_;
};

// Work done since the last initialize().
struct StepperStats {
  std::size_t rhs_evaluations = 0;
  std::size_t accepted_steps = 0;
  std::size_t rejected_steps = 0;
};

}  // namespace unidyn
