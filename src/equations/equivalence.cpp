// Agreement of Newton's and Lagrange's equations.
#include "unidyn/equations/equivalence.hpp"

#include <cmath>
#include <random>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
EquivalenceReport check_equivalence(const System& system, const EquationsOfMotion& lagrange,
                                    const NewtonEquations& newton, int states, unsigned seed) {
  EquivalenceReport report;
  const std::vector<Expr> residual = equivalence_residual(system, newton, lagrange);
  report.symbolic_zero = true;
  for (const auto& r : residual) {
    // exact evaluation at random points decides at once; what it cannot decide, or the residual
    // it proves non-zero, is simplified (to be printed)
    const std::optional<bool> zero = vanishes_identically(r);
    report.symbolic_residual.push_back(zero.value_or(false) ? Expr(0) : simplify(r));
    report.symbolic_zero =
        report.symbolic_zero && zero != false && report.symbolic_residual.back().is_zero();
  }

  // Random states: each coordinate, rate and acceleration, and t, uniform in [−1, 1]
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const GiNaC::exmap parameters = system.parameter_values();
  const auto& q = system.coordinates();
  std::vector<Expr> potential_gradient;
  for (const auto& c : q)
    potential_gradient.push_back(derivative(lagrange.potential_energy, c.value));
  std::vector<GiNaC::exmap> points;
  for (int s = 0; s < states; ++s) {
    GiNaC::exmap state = parameters;
    state[system.time()] = uniform(engine);
    for (const auto& c : q) {
      state[c.value] = uniform(engine);
      state[c.rate] = uniform(engine);
      state[c.acceleration] = uniform(engine);
    }
    points.push_back(std::move(state));
  }
  // the residuals and the terms that scale them, in one evaluation (they share their nodes)
  std::vector<Expr> all = residual;
  all.insert(all.end(), lagrange.inertia_terms.begin(), lagrange.inertia_terms.end());
  all.insert(all.end(), potential_gradient.begin(), potential_gradient.end());
  all.insert(all.end(), lagrange.generalized_force.begin(), lagrange.generalized_force.end());
  // and each residual's terms: their sizes are the scale of the round-off in the sum
  const std::size_t n = q.size();
  std::vector<std::pair<std::size_t, std::size_t>> term_range;  // [first, end) in `all`
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t first = all.size();
    if (GiNaC::is_exactly_a<GiNaC::add>(residual[i])) {
      for (std::size_t k = 0; k < residual[i].nops(); ++k) all.push_back(residual[i].op(k));
    }
    term_range.emplace_back(first, all.size());
  }
  const std::vector<std::vector<std::optional<double>>> values = real_values(all, points);
  double worst = 0.0;
  int used = 0;
  for (std::size_t s = 0; s < points.size(); ++s) {
    const auto value = [&](std::size_t k) { return values[k][s].value_or(NAN); };
    // a state where Lagrange's own terms are not real lies outside the model's domain
    bool defined = true;
    for (std::size_t k = n; k < 4 * n; ++k) defined = defined && std::isfinite(value(k));
    if (!defined) continue;
    ++used;
    for (std::size_t i = 0; i < n; ++i) {
      const double r = value(i);
      double terms = 0;
      for (std::size_t k = term_range[i].first; k < term_range[i].second; ++k) {
        terms += std::abs(value(k));
      }
      const double scale = std::max(terms, std::abs(value(n + i)) + std::abs(value(2 * n + i)) +
                                               std::abs(value(3 * n + i))) +
                           1e-300;
      worst = std::max(worst, std::isfinite(r) ? std::abs(r) / scale : INFINITY);
    }
  }
  report.states = used;
  report.numeric_relative_residual = worst;
  return report;
}

}  // namespace unidyn
