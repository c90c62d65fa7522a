// Eigenvalues, mode shapes and the stability verdict of a linearisation.
#include "unidyn/analysis/modes.hpp"

#include "eigen_decomposition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "semisimple.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

using Eigen::Index;
using Eigen::MatrixXcd;
using Eigen::MatrixXd;
using Eigen::VectorXcd;
using complex = std::complex<double>;

// Eigenvalues this close (relative to the largest) are one; those this close to the imaginary
// axis are on it. Wider than round-off: a Jordan block of size 2 splits by the square root of the
// error in A (1e-12 of it splits it by 1e-6).
constexpr double kClose = 1e-6;

// v carried to every coordinate: the dropped (ignorable) states from δẋ_k = F_k · w, last dropped
// first, then δq = to_coordinates · w; scaled so that its largest entry is 1. A mode that moves
// no coordinate (λ = 0 along a rate) is given by its rates instead.
std::vector<complex> mode_shape(const Linearization& L, const VectorXcd& v, complex lambda,
                                double tolerance, bool& of_rates) {
  const Index full = L.full_A.rows();
  VectorXcd w = VectorXcd::Zero(full);
  for (std::size_t i = 0; i < L.kept.size(); ++i) w[L.kept[i]] = v[static_cast<Index>(i)];
  for (auto k = L.dropped.rbegin(); k != L.dropped.rend(); ++k) {
    const complex divisor = lambda - L.full_A(*k, *k);
    if (std::abs(divisor) <= tolerance) continue;  // grows like t: no shape of its own
    complex sum = 0.0;
    for (Index j = 0; j < full; ++j) {
      if (j != *k) sum += L.full_A(*k, j) * w[j];
    }
    w[*k] = sum / divisor;
  }
  const Index n = static_cast<Index>(L.coordinates.size());
  const VectorXcd all = L.to_coordinates.cast<complex>() * w;
  VectorXcd shape = all.head(n);
  of_rates = shape.cwiseAbs().maxCoeff() <= tolerance * all.cwiseAbs().maxCoeff();
  if (of_rates) shape = all.tail(n);
  Index largest = 0;
  shape.cwiseAbs().maxCoeff(&largest);
  if (std::abs(shape[largest]) > 0.0) shape /= shape[largest];
  return {shape.begin(), shape.end()};
}

std::string eigenvalue_text(complex lambda) {
  if (lambda.imag() == 0.0) return detail::to_short_text(lambda.real());
  if (lambda.real() == 0.0) return "±" + detail::to_short_text(std::abs(lambda.imag())) + "i";
  return detail::to_short_text(lambda.real()) + (lambda.imag() < 0 ? " - " : " + ") +
         detail::to_short_text(std::abs(lambda.imag())) + "i";
}

}  // namespace

std::string to_string(Stability s) {
  switch (s) {
    case Stability::asymptotically_stable:
      return "asymptotically stable";
    case Stability::linearly_stable:
      return "linearly stable";
    case Stability::unstable:
      return "unstable";
    case Stability::inconclusive:
      return "inconclusive";
  }
  return "inconclusive";
}

ModeAnalysis analyse_modes(const Linearization& L) {
  ModeAnalysis out;
  const Index s = L.A.rows();
  if (s == 0) {
    out.verdict = Stability::linearly_stable;
    out.reason = "no state is left to perturb: every coordinate is ignorable";
    return out;
  }
  const EigenDecomposition solver = eigen_decomposition(L.A, true);
  if (!solver.converged) {
    out.reason = "the eigenvalue iteration did not converge";
    return out;
  }
  const VectorXcd& lambda = solver.values;
  const MatrixXcd& vectors = solver.vectors;
  const double largest = lambda.cwiseAbs().maxCoeff();
  const double tolerance = kClose * std::max(largest, 1.0);
  out.tolerance = tolerance;

  // The modes: real eigenvalues, then one of each complex pair, each by Re λ from the largest.
  std::vector<Index> order;
  for (Index k = 0; k < s; ++k) {
    if (lambda[k].imag() >= -tolerance) order.push_back(k);
  }
  const auto is_real = [&](Index k) { return std::abs(lambda[k].imag()) <= tolerance; };
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    if (is_real(a) != is_real(b)) return is_real(a);
    if (std::abs(lambda[a].real() - lambda[b].real()) > tolerance) {
      return lambda[a].real() > lambda[b].real();
    }
    return lambda[a].imag() < lambda[b].imag();  // equal decay: the slower oscillation first
  });
  for (const Index k : order) {
    Mode mode;
    mode.eigenvalue = is_real(k) ? complex(lambda[k].real(), 0.0) : lambda[k];
    mode.natural_frequency = std::abs(mode.eigenvalue);
    mode.damped_frequency = std::abs(mode.eigenvalue.imag());
    mode.damping_ratio = mode.natural_frequency > 0.0
                             ? -mode.eigenvalue.real() / mode.natural_frequency
                             : std::numeric_limits<double>::quiet_NaN();
    mode.shape = mode_shape(L, vectors.col(k), lambda[k], tolerance, mode.of_rates);
    out.modes.push_back(std::move(mode));
  }

  // The verdict.
  std::string growing, on_axis, defective;
  for (Index k = 0; k < s; ++k) {
    if (lambda[k].real() > tolerance)
      growing += (growing.empty() ? "" : ", ") + eigenvalue_text(lambda[k]);
  }
  if (!growing.empty()) {
    out.verdict = Stability::unstable;
    out.reason = "eigenvalues with a positive real part: " + growing;
    return out;
  }
  // the eigenvalues on the imaginary axis, grouped by value, and their eigenvectors
  std::vector<bool> seen(static_cast<std::size_t>(s), false);
  Index zeros = 0;
  for (Index k = 0; k < s; ++k) {
    if (seen[static_cast<std::size_t>(k)] || std::abs(lambda[k].real()) > tolerance) continue;
    Index multiplicity = 0;
    for (Index j = k; j < s; ++j) {
      if (!seen[static_cast<std::size_t>(j)] && std::abs(lambda[j] - lambda[k]) <= tolerance) {
        seen[static_cast<std::size_t>(j)] = true;
        ++multiplicity;
      }
    }
    const complex mu(0.0, is_real(k) ? 0.0 : lambda[k].imag());
    if (mu == complex(0.0, 0.0)) zeros = multiplicity;
    if (lambda[k].imag() < -tolerance) continue;  // its conjugate speaks for it
    on_axis += (on_axis.empty() ? "" : ", ") + eigenvalue_text(mu) +
               (multiplicity > 1 ? " (" + std::to_string(multiplicity) + " times)" : "");
    if (!detail::semisimple(L.A, mu, multiplicity, kClose * std::max(largest, 1.0))) {
      defective += (defective.empty() ? "" : ", ") + eigenvalue_text(mu);
    }
  }
  if (!defective.empty()) {
    out.verdict = Stability::inconclusive;
    out.reason = "eigenvalues on the imaginary axis without enough eigenvectors (" + defective +
                 "): the linear motion grows like t, and the nonlinear terms decide";
    return out;
  }
  if (on_axis.empty()) {
    out.verdict = Stability::asymptotically_stable;
    out.reason = "every eigenvalue has a negative real part";
    return out;
  }
  out.verdict = Stability::linearly_stable;
  Index on_axis_count = 0;
  for (Index k = 0; k < s; ++k) on_axis_count += std::abs(lambda[k].real()) <= tolerance ? 1 : 0;
  if (on_axis_count == zeros) {
    out.reason = "every eigenvalue but " +
                 std::string(zeros > 1 ? "the zero ones" : "the zero one") +
                 " (neighbouring steady motions) has a negative real part: a perturbation decays "
                 "to a neighbouring steady motion";
    return out;
  }
  out.reason = "no eigenvalue has a positive real part; on the imaginary axis: " + on_axis +
               (zeros > 0 ? " (zero: a neighbouring steady motion, neutral)" : "") +
               "; whether the nonlinear terms keep the motion bounded is not decided here";
  return out;
}

std::string eigenvalue_text(const Mode& mode, double tolerance) {
  const double re = std::abs(mode.eigenvalue.real()) <= tolerance ? 0.0 : mode.eigenvalue.real();
  const double im = std::abs(mode.eigenvalue.imag());
  const auto six_digits = [](double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.6g", x);
    return std::string(text);
  };
  return im == 0.0 ? six_digits(re) : six_digits(re) + "\u00b1" + six_digits(im) + "i";
}

}  // namespace unidyn
