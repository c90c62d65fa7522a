// Eigenvalues along a parameter, and where stability changes.
#include "unidyn/analysis/parameter_sweep.hpp"

#include "eigen_decomposition.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include "swept_value.hpp"
#include "unidyn/integrate/simulation.hpp"

namespace unidyn {
namespace {

// Singular values of A this small (relative to the largest) are zero: as many of the eigenvalues
// nearest 0 are the neighbouring steady motions', 0 at every value, and not counted in the growth.
// Counted at the values of the sweep, not between them: near a boundary where an eigenvalue
// passes through 0 (the bicycle's capsize speed) it would be counted too, and the boundary moved.
constexpr double kZero = 1e-12;

// A growth above this fraction of the largest |λ| (at least 1) is growth, not round-off; a boundary
// where a real part passes through 0 moves by it over the real part's slope (1e-13 · 16 / 0.18 for
// the bicycle's capsize), and one where a pair turns from real to imaginary by its square.
constexpr double kGrowing = 1e-13;

// The eigenvalues at one value of the parameter, or why there are none; the growth leaving out
// `zeros` eigenvalues nearest 0, or as many as A's zero singular values when not given.
SweepPoint point_at(const System& system, const CompiledSystem& compiled,
                    std::vector<GivenValue> given,
                    std::vector<std::pair<std::string, double>> parameters, const std::string& name,
                    double value, std::optional<std::size_t> given_zeros = std::nullopt) {
  SweepPoint out;
  out.value = value;
  std::size_t zeros = given_zeros.value_or(0);
  detail::put_swept_value(system, name, value, given, parameters);
  try {
    const OperatingPoint point =
        operating_point(system, compiled, given, initial_state(system, parameters).parameters);
    const Linearization L = linearize(system, compiled, point);
    const EigenDecomposition eigen = eigen_decomposition(L.A, true);
    if (!eigen.converged) throw std::runtime_error("the eigenvalue iteration did not converge");
    out.eigenvalues.assign(eigen.values.begin(), eigen.values.end());
    if (!given_zeros) {
      Eigen::JacobiSVD<Eigen::MatrixXd> svd(L.A);
      svd.setThreshold(kZero);
      zeros = static_cast<std::size_t>(L.A.rows() - svd.rank());
    }
    out.zeros = zeros;
  } catch (const std::exception& e) {
    out.failure = e.what();
    out.growth = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  // the growth: the largest real part but for the `zeros` eigenvalues nearest 0
  std::vector<std::complex<double>> rest = out.eigenvalues;
  std::sort(rest.begin(), rest.end(), [](auto a, auto b) { return std::abs(a) < std::abs(b); });
  out.growth = -std::numeric_limits<double>::infinity();
  for (std::size_t k = std::min(zeros, rest.size()); k < rest.size(); ++k) {
    out.growth = std::max(out.growth, rest[k].real());
  }
  // growing beyond round-off: an oscillation's real part is ±1e-16 of it when nothing damps it
  const double largest = rest.empty() ? 0.0 : std::abs(rest.back());
  out.growing = out.growth > kGrowing * std::max(1.0, largest);
  return out;
}

}  // namespace

ParameterSweep sweep_modes(const System& system, const CompiledSystem& compiled,
                           const std::vector<GivenValue>& given,
                           const std::vector<std::pair<std::string, double>>& parameters,
                           const std::string& name, double from, double to, std::size_t count) {
  detail::expect_sweepable(system, name, count);
  ParameterSweep out;
  out.parameter = name;
  for (std::size_t k = 0; k < count; ++k) {
    out.points.push_back(point_at(system, compiled, given, parameters, name,
                                  detail::swept_value(from, to, k, count)));
  }
  // Where the growth changes sign between neighbours: bisection on it.
  for (std::size_t k = 0; k + 1 < count; ++k) {
    const SweepPoint &a = out.points[k], &b = out.points[k + 1];
    if (!a.failure.empty() || !b.failure.empty() || a.growing == b.growing) continue;
    double lo = a.value, hi = b.value;
    const bool lo_growing = a.growing;
    bool failed = false;
    while (std::abs(hi - lo) > 1e-12 * (1.0 + std::abs(lo))) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      const SweepPoint m =
          point_at(system, compiled, given, parameters, name, mid, std::min(a.zeros, b.zeros));
      if (!m.failure.empty()) {
        failed = true;
        break;
      }
      (m.growing == lo_growing ? lo : hi) = mid;
    }
    if (!failed) out.boundaries.push_back({0.5 * (lo + hi), lo_growing});
  }
  return out;
}

}  // namespace unidyn
