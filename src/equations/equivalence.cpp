// Agreement of Newton's and Lagrange's equations.
#include "unidyn/equations/equivalence.hpp"

#include <cmath>
#include <random>

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

double to_double(const Expr& e) {
  const Expr value = GiNaC::evalf(e);
  if (!GiNaC::is_a<GiNaC::numeric>(value)) return NAN;
  const GiNaC::numeric number = GiNaC::ex_to<GiNaC::numeric>(value);
  if (!number.is_real()) return NAN;
  return number.to_double();
}

}  // namespace

EquivalenceReport check_equivalence(const System& system, const EquationsOfMotion& lagrange,
                                    const NewtonEquations& newton, int states, unsigned seed) {
  EquivalenceReport report;
  const std::vector<Expr> residual = equivalence_residual(system, newton, lagrange);
  report.symbolic_zero = true;
  for (const auto& r : residual) {
    report.symbolic_residual.push_back(simplify(r));
    report.symbolic_zero = report.symbolic_zero && report.symbolic_residual.back().is_zero();
  }

  // Random states: each coordinate, rate and acceleration, and t, uniform in [−1, 1]
  std::mt19937_64 engine(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const GiNaC::exmap parameters = system.parameter_values();
  const auto& q = system.coordinates();
  double worst = 0.0;
  for (int s = 0; s < states; ++s) {
    GiNaC::exmap state = parameters;
    state[system.time()] = uniform(engine);
    for (const auto& c : q) {
      state[c.value] = uniform(engine);
      state[c.rate] = uniform(engine);
      state[c.acceleration] = uniform(engine);
    }
    for (std::size_t i = 0; i < q.size(); ++i) {
      const double r = to_double(residual[i].subs(state));
      const double scale =
          std::abs(to_double(lagrange.inertia_terms[i].subs(state))) +
          std::abs(to_double(lagrange.potential_energy.diff(q[i].value).subs(state))) +
          std::abs(to_double(lagrange.generalized_force[i].subs(state))) + 1e-300;
      worst = std::max(worst, std::isfinite(r) ? std::abs(r) / scale : INFINITY);
    }
  }
  report.states = states;
  report.numeric_relative_residual = worst;
  return report;
}

}  // namespace unidyn
