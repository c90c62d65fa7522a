// Floquet multipliers along a parameter, and where the largest crosses the unit circle.
#include "unidyn/analysis/floquet_sweep.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "swept_value.hpp"
#include "unidyn/integrate/simulation.hpp"

namespace unidyn {
namespace {

using Eigen::MatrixXd;

// The monodromy matrix at one value, or why there is none.
struct Evaluated {
  FloquetSweepPoint point;
  MatrixXd monodromy;
};

struct SweepSetting {
  const System& system;
  const CompiledSystem& compiled;
  const TimeDependence& dependence;
  const std::vector<GivenValue>& given;
  const std::vector<std::pair<std::string, double>>& parameters;
  const std::string& name;
  std::optional<double> period;
};

Evaluated evaluate_at(const SweepSetting& s, double value) {
  Evaluated out;
  out.point.value = value;
  std::vector<GivenValue> given = s.given;
  std::vector<std::pair<std::string, double>> parameters = s.parameters;
  detail::put_swept_value(s.system, s.name, value, given, parameters);
  try {
    const std::vector<double> p = initial_state(s.system, parameters).parameters;
    const std::optional<DrivePeriod> period =
        drive_period(s.system, s.compiled, s.dependence, p, s.period);
    if (!period) {
      throw NotPeriodic(
          "every frequency of the drive is 0 here: the equations do not change "
          "with t, and there is no period");
    }
    const OperatingPoint point = operating_point(s.system, s.compiled, given, p);
    const PeriodicLinearization L = linearize_periodic(s.system, s.compiled, point, *period);
    out.monodromy = L.monodromy;
    out.point.period = period->period;
    for (const FloquetMultiplier& m : analyse_floquet(L).multipliers) {
      out.point.multipliers.push_back(m.multiplier);
    }
  } catch (const std::exception& e) {
    out.point.failure = e.what();
    out.point.growth = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const double most = out.point.multipliers.empty() ? 0.0 : std::abs(out.point.multipliers[0]);
  out.point.growth =
      most > 0.0 ? std::log(most) / out.point.period : -std::numeric_limits<double>::infinity();
  out.point.growing = most > 1.0 + kFloquetOnCircle;
  return out;
}

// det(Φ − I), det(Φ + I) and the largest |μ| − 1 − kFloquetOnCircle at an evaluated value.
double indicator(const Evaluated& e, int which) {
  const MatrixXd I = MatrixXd::Identity(e.monodromy.rows(), e.monodromy.cols());
  if (which == 0) return (e.monodromy - I).determinant();
  if (which == 1) return (e.monodromy + I).determinant();
  return largest_multiplier(e.monodromy) - 1.0 - kFloquetOnCircle;
}

// Which indicator changes sign, beyond round-off, between a and b: det(Φ − I), det(Φ + I), or
// the largest |μ| itself.
int changing_indicator(const Evaluated& a, const Evaluated& b) {
  for (const int which : {0, 1}) {
    const double x = indicator(a, which), y = indicator(b, which);
    if (std::min(std::abs(x), std::abs(y)) > 1e-9 && (x < 0) != (y < 0)) return which;
  }
  return 2;
}

}  // namespace

FloquetSweep sweep_floquet(const System& system, const CompiledSystem& compiled,
                           const TimeDependence& dependence, const std::vector<GivenValue>& given,
                           const std::vector<std::pair<std::string, double>>& parameters,
                           const std::string& name, double from, double to, std::size_t count,
                           std::optional<double> period) {
  detail::expect_sweepable(system, name, count);
  const SweepSetting setting{system, compiled, dependence, given, parameters, name, period};
  FloquetSweep out;
  out.parameter = name;
  std::vector<Evaluated> evaluated;
  for (std::size_t k = 0; k < count; ++k) {
    evaluated.push_back(evaluate_at(setting, detail::swept_value(from, to, k, count)));
    out.points.push_back(evaluated.back().point);
  }
  // Where the largest |μ| crosses 1 between neighbours: bisection on the indicator that changes
  // sign there.
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const Evaluated &a = evaluated[k], &b = evaluated[k + 1];
    if (!a.point.failure.empty() || !b.point.failure.empty() ||
        a.point.growing == b.point.growing) {
      continue;
    }
    const int which = changing_indicator(a, b);
    const bool lo_sign = indicator(a, which) < 0;
    double lo = a.point.value, hi = b.point.value;
    bool failed = false;
    while (std::abs(hi - lo) > 1e-12 * (1.0 + std::abs(lo))) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      const Evaluated m = evaluate_at(setting, mid);
      if (!m.point.failure.empty()) {
        failed = true;
        break;
      }
      ((indicator(m, which) < 0) == lo_sign ? lo : hi) = mid;
    }
    if (!failed) out.boundaries.push_back({0.5 * (lo + hi), a.point.growing});
  }
  return out;
}

}  // namespace unidyn
