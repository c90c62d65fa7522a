// Floquet multipliers of a periodic motion: the variational equations over one period.
#include "unidyn/analysis/floquet.hpp"

#include "eigen_decomposition.hpp"

#include <algorithm>
#include <cmath>

#include "motion.hpp"
#include "semisimple.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;
using complex = std::complex<double>;
using namespace detail;

namespace {

// The motion must come back to the point to this fraction of its size, times Φ's growth.
constexpr double kReturn = 1e-8;

// The kept states' values (independent coordinates, then independent rates) at (q, q̇).
VectorXd kept_values(const Linearization& L, const Choice& choice, const VectorXd& q,
                     const VectorXd& qdot) {
  const auto s1 = static_cast<Index>(choice.independent_q.size());
  VectorXd out(static_cast<Index>(L.kept.size()));
  for (std::size_t k = 0; k < L.kept.size(); ++k) {
    const Index j = L.kept[k];
    out[static_cast<Index>(k)] = j < s1
                                     ? q[choice.independent_q[static_cast<std::size_t>(j)]]
                                     : qdot[choice.independent_u[static_cast<std::size_t>(j - s1)]];
  }
  return out;
}

std::string multiplier_text(complex mu) {
  const std::string re = detail::to_short_text(mu.real(), 6);
  if (std::abs(mu.imag()) <= kFloquetOnCircle * std::max(1.0, std::abs(mu))) return re;
  return re + (mu.imag() < 0 ? "-" : "+") + detail::to_short_text(std::abs(mu.imag()), 6) + "i";
}

}  // namespace

PeriodicLinearization linearize_periodic(const System& system, const CompiledSystem& compiled,
                                         const OperatingPoint& point, const DrivePeriod& period) {
  PeriodicLinearization out;
  out.period = period;
  out.t0 = point.t;
  const ReducedSystem at = reduced_system(compiled, point, nullptr);
  const Index states = at.F.rows();
  // The motion and Φ over one period, and the influence of each state on each other along it:
  // max |F(i, k)| / max |F| over every evaluation.
  MatrixXd influence = MatrixXd::Zero(states, states);
  const MotionSolution motion = integrate_motion(
      compiled, point, at.choice, states, period.period, [&](double, const MatrixXd& F) {
        const double scale = largest(F);
        if (scale > 0.0) influence = influence.cwiseMax(F.cwiseAbs() / scale);
      });
  out.steps = motion.steps;

  // The ignorable coordinates: nothing along the period depends on them, nor near the point.
  std::vector<MatrixXd> samples{influence};
  if (const auto near = nearby_state(system, compiled, point, at)) {
    samples.push_back(reduced_system(compiled, *near, &at.choice).F);
  } else {
    samples.clear();
  }
  out.at_start = reduced_linearization(system, at, samples);
  const Linearization& L = out.at_start;
  out.monodromy = motion.monodromy(L.kept, L.kept);

  // The motion must come back: the kept states after one period where they were.
  const VectorXd start = kept_values(L, at.choice, point.q, point.qdot);
  const VectorXd end = kept_values(L, at.choice, motion.q, motion.qdot);
  out.return_gap = largest(end - start);
  const double allowed =
      kReturn * (1.0 + largest(start)) * std::max(1.0, largest(motion.monodromy));
  if (out.return_gap > allowed) {
    Index worst = 0;
    (end - start).cwiseAbs().maxCoeff(&worst);
    throw NotAnOperatingPoint(
        "the motion from the point does not come back to it after one period of the drive (T = " +
        detail::to_short_text(period.period) + "): " + L.state[static_cast<std::size_t>(worst)] +
        " goes from " + detail::to_short_text(start[worst]) + " to " +
        detail::to_short_text(end[worst]) +
        "; Floquet analysis is of periodic motions: give a state the drive keeps at rest, or "
        "one on a periodic response");
  }
  return out;
}

double largest_multiplier(const MatrixXd& monodromy) {
  if (monodromy.size() == 0) return 0.0;
  return eigen_decomposition(monodromy, false).values.cwiseAbs().maxCoeff();
}

FloquetAnalysis analyse_floquet(const PeriodicLinearization& P) {
  FloquetAnalysis out;
  out.tolerance = kFloquetOnCircle;
  const MatrixXd& Phi = P.monodromy;
  const Index s = Phi.rows();
  if (s == 0) {
    out.verdict = Stability::linearly_stable;
    out.reason = "no state is left to perturb: every coordinate is ignorable";
    return out;
  }
  const EigenDecomposition solver = eigen_decomposition(Phi, false);
  if (!solver.converged) {
    out.reason = "the eigenvalue iteration did not converge";
    return out;
  }
  const Eigen::VectorXcd& mu = solver.values;
  // |μ| from the largest; equal ones by arg μ from the smallest
  std::vector<Index> order(static_cast<std::size_t>(s));
  for (Index k = 0; k < s; ++k) order[static_cast<std::size_t>(k)] = k;
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    if (std::abs(std::abs(mu[a]) - std::abs(mu[b])) > kFloquetOnCircle) {
      return std::abs(mu[a]) > std::abs(mu[b]);
    }
    return std::arg(mu[a]) < std::arg(mu[b]);
  });
  for (const Index k : order) {
    out.multipliers.push_back({mu[k], std::log(mu[k]) / P.period.period});
  }

  // The verdict.
  std::string outside, on_circle, defective;
  double most = 0.0;
  for (const Index k : order) {
    most = std::max(most, std::abs(mu[k]));
    if (std::abs(mu[k]) > 1.0 + kFloquetOnCircle) {
      outside += (outside.empty() ? "" : ", ") + multiplier_text(mu[k]);
    }
  }
  if (!outside.empty()) {
    out.verdict = Stability::unstable;
    out.reason = "multipliers outside the unit circle: " + outside +
                 " (a perturbation grows by |mu| = " + detail::to_short_text(most, 6) +
                 " each period)";
    return out;
  }
  std::vector<bool> seen(static_cast<std::size_t>(s), false);
  for (const Index k : order) {
    if (seen[static_cast<std::size_t>(k)] || std::abs(std::abs(mu[k]) - 1.0) > kFloquetOnCircle)
      continue;
    Index multiplicity = 0;
    for (Index j = 0; j < s; ++j) {
      if (!seen[static_cast<std::size_t>(j)] && std::abs(mu[j] - mu[k]) <= kFloquetOnCircle) {
        seen[static_cast<std::size_t>(j)] = true;
        ++multiplicity;
      }
    }
    if (mu[k].imag() < -kFloquetOnCircle) continue;  // its conjugate speaks for it
    on_circle += (on_circle.empty() ? "" : ", ") + multiplier_text(mu[k]) +
                 (multiplicity > 1 ? " (" + std::to_string(multiplicity) + " times)" : "");
    if (!semisimple(Phi, mu[k], multiplicity, kFloquetOnCircle * std::max(1.0, largest(Phi)))) {
      defective += (defective.empty() ? "" : ", ") + multiplier_text(mu[k]);
    }
  }
  if (!defective.empty()) {
    out.verdict = Stability::inconclusive;
    out.reason = "multipliers on the unit circle without enough eigenvectors (" + defective +
                 "): on a transition curve, the linear motion grows like t, and the nonlinear "
                 "terms decide";
    return out;
  }
  if (on_circle.empty()) {
    out.verdict = Stability::asymptotically_stable;
    out.reason = "every multiplier is inside the unit circle: a perturbation shrinks by |mu| = " +
                 detail::to_short_text(most, 6) + " each period";
    return out;
  }
  out.verdict = Stability::linearly_stable;
  out.reason = "no multiplier is outside the unit circle; on it: " + on_circle +
               ". The linear motion stays bounded; on the unit circle linear theory is "
               "inconclusive about the motion itself (the nonlinear terms decide)";
  return out;
}

}  // namespace unidyn
