// Whether an operating point stays what it is.
#include "steadiness.hpp"

#include <cmath>

#include "motion.hpp"
#include "unidyn/analysis/linearization.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/numeric/tape_reads.hpp"

namespace unidyn::detail {

using Eigen::Index;
using Eigen::MatrixXd;

// F may change along a steady motion by this fraction of its largest entry (integration error).
constexpr double kSteady = 1e-6;

void expect_the_same_at_other_instants(const CompiledSystem& compiled, const OperatingPoint& point,
                                       const ReducedSystem& at, const std::vector<Index>& kept,
                                       double acceleration_tolerance,
                                       const std::vector<std::string>& names) {
  // equations that do not read t (its input, the tapes' first) are the same at every instant
  const auto reads_t = [](const Tape& tape) {
    const std::vector<bool> read = inputs_read(tape);
    return !read.empty() && read[0];
  };
  if (!reads_t(compiled.dynamics()) && !reads_t(compiled.constraint_tape())) return;
  const MatrixXd F = at.F(kept, kept);
  const double scale = std::max(largest(F), 1e-300);
  for (const double later : {0.7236067977499790, 2.6457513110645906, 9.8696044010893586}) {
    OperatingPoint then = point;
    then.t = point.t + later;
    CompiledSystemData data = compiled.make_data();
    data.active = point.active;
    compiled.solve(then.t, then.q, then.qdot, then.parameters, then.qddot, then.lambda, data);
    const ReducedSystem there = reduced_system(compiled, then, &at.choice);
    std::string what;
    for (const Index i : at.choice.independent_u) {
      if (std::abs(then.qddot[i] - point.qddot[i]) > acceleration_tolerance) {
        what = "the acceleration of " + names[static_cast<std::size_t>(i)];
      }
    }
    if (what.empty() && largest(there.F(kept, kept) - F) > kNegligible * scale) {
      what = "the linearised equations";
    }
    if (what.empty()) continue;
    throw NotAnOperatingPoint(
        "the equations of motion depend on t at the point (" + what + " at t = " +
        detail::to_short_text(then.t) + " differs from t = " + detail::to_short_text(point.t) +
        "): linearised at one instant, the motion would be frozen there. A driven system's point "
        "is analysed over a period of the drive (Floquet: `unidyn modes`, when the dependence on t "
        "is periodic)");
  }
}

namespace {

// Whether only ignorable coordinates move: each rate beyond rounding (relative to the fastest) is
// an independent coordinate's, dropped as ignorable.
bool only_ignorable_coordinates_move(const ReducedSystem& at, const OperatingPoint& point,
                                     const std::vector<Index>& dropped) {
  const double rate_tolerance = kNegligible * (1.0 + largest(point.qdot));
  std::vector<bool> ignorable(static_cast<std::size_t>(point.qdot.size()), false);
  for (const Index k : dropped) {
    if (k < at.P_q.cols()) {
      ignorable[static_cast<std::size_t>(at.choice.independent_q[static_cast<std::size_t>(k)])] =
          true;
    }
  }
  for (Index i = 0; i < point.qdot.size(); ++i) {
    if (std::abs(point.qdot[i]) > rate_tolerance && !ignorable[static_cast<std::size_t>(i)]) {
      return false;
    }
  }
  return true;
}

}  // namespace

void expect_steady_along_the_motion(const CompiledSystem& compiled, const OperatingPoint& point,
                                    const ReducedSystem& at, const std::vector<Index>& kept,
                                    const std::vector<Index>& dropped,
                                    const std::vector<std::string>& names) {
  Index fastest = 0;
  const double rate = point.qdot.size() == 0 ? 0.0 : point.qdot.cwiseAbs().maxCoeff(&fastest);
  if (rate == 0.0) return;  // nothing moves
  // a rolling bicycle's wheel angles and position: F does not depend on them
  if (only_ignorable_coordinates_move(at, point, dropped)) return;
  const MatrixXd F0 = at.F(kept, kept);
  const double scale = std::max(largest(F0), 1e-300);
  double change = 0.0, when = point.t;
  try {
    integrate_motion(compiled, point, at.choice, 0, 1.0 / rate, [&](double t, const MatrixXd& F) {
      const double d = largest(F(kept, kept) - F0);
      if (d > change) change = d, when = t;
    });
  } catch (const std::exception&) {
    return;  // the motion cannot be followed (it reaches a singular configuration): not judged
  }
  if (change <= kSteady * scale) return;
  throw NotAnOperatingPoint(
      "the point moves (" + rate_name(names[static_cast<std::size_t>(fastest)]) + " = " +
      to_short_text(point.qdot[fastest]) +
      " there) and the linearised equations change as it does (by " +
      to_short_text(change / scale, 3) + " of their size after " +
      to_short_text(when - point.t, 3) +
      " s of its motion): it is not an equilibrium or a steady motion. If the motion through it "
      "is periodic, analyse it over its period with --period T (Floquet)");
}

}  // namespace unidyn::detail
