// The motion from an operating point with its variational equations.
#include "motion.hpp"

#include "unidyn/integrate/dormand_prince_853.hpp"

namespace unidyn::detail {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// The motion and Φ are integrated to this relative and absolute error per step.
constexpr double kTolerance = 1e-12;

MotionSolution integrate_motion(const CompiledSystem& compiled, const OperatingPoint& point,
                                const Choice& choice, Index states, double duration,
                                const MotionVisitor& visit) {
  const auto n = static_cast<Index>(compiled.coordinate_count());
  CompiledSystemData data = compiled.make_data();
  data.active = point.active;
  OperatingPoint here = point;
  // F at (t, y): the accelerations there, then the reduced system's matrix
  const auto F_at = [&](double t, const VectorXd& y) {
    here.t = t;
    here.q = y.head(n);
    here.qdot = y.segment(n, n);
    compiled.solve(t, here.q, here.qdot, here.parameters, here.qddot, here.lambda, data);
    return reduced_system(compiled, here, &choice).F;
  };
  // y = (q, q̇, Φ column by column)
  const auto rhs = [&](double t, const VectorXd& y, VectorXd& dydt) {
    if (states > 0) {
      // Φ' = F Φ: F at every stage, looked at there too
      const MatrixXd F = F_at(t, y);
      if (visit) visit(t, F);
      Eigen::Map<MatrixXd>(dydt.data() + 2 * n, states, states) =
          F * Eigen::Map<const MatrixXd>(y.data() + 2 * n, states, states);
    } else {
      here.t = t;
      here.q = y.head(n);
      here.qdot = y.segment(n, n);
      compiled.solve(t, here.q, here.qdot, here.parameters, here.qddot, here.lambda, data);
    }
    dydt.head(n) = here.qdot;
    dydt.segment(n, n) = here.qddot;
  };
  DormandPrinceOptions options = DormandPrinceOptions::dop853();
  options.rtol = kTolerance;
  options.atol = kTolerance;
  options.max_steps = 1000000;
  DormandPrince853 stepper(rhs, options);
  VectorXd y0(2 * n + states * states);
  y0 << point.q, point.qdot, MatrixXd::Identity(states, states).reshaped();
  const double t_end = point.t + duration;
  stepper.initialize(point.t, y0);
  while (stepper.t() != t_end) {
    stepper.step(t_end);
    // without Φ, F is only looked at: at the end of each step (on the motion)
    if (states == 0 && visit) visit(stepper.t(), F_at(stepper.t(), stepper.y()));
  }
  const VectorXd& y = stepper.y();
  MotionSolution out;
  out.q = y.head(n);
  out.qdot = y.segment(n, n);
  out.monodromy = Eigen::Map<const MatrixXd>(y.data() + 2 * n, states, states);
  out.steps = stepper.stats().accepted_steps;
  return out;
}

}  // namespace unidyn::detail
