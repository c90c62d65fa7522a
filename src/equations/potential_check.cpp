// Whether a force element's generalised forces derive from a potential, and the potential.
#include "unidyn/equations/potential_check.hpp"

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// The first symbol of `symbols` that e depends on, if any.
std::optional<std::size_t> depends_on(const std::vector<Expr>& phi,
                                      const std::vector<GiNaC::realsymbol>& symbols) {
  for (std::size_t k = 0; k < symbols.size(); ++k) {
    for (const Expr& e : phi) {
      if (e.has(symbols[k])) return k;
    }
  }
  return std::nullopt;
}

// U = −∫_0^1 Φ(s q) · q ds for a polynomial Φ (after simplification: a moment's Φ is often one
// once its trigonometric factors cancel); none otherwise.
std::optional<Expr> line_integral(std::vector<Expr> phi, const std::vector<Expr>& q) {
  for (Expr& e : phi) e = simplify(e);
  const GiNaC::realsymbol s("s");
  GiNaC::exmap scaled;
  Expr integrand = 0;
  for (const Expr& c : q) scaled[c] = s * c;
  for (std::size_t i = 0; i < q.size(); ++i) {
    for (const Expr& c : q) {
      if (!phi[i].is_polynomial(c)) return std::nullopt;
    }
    integrand += phi[i].subs(scaled) * q[i];
  }
  integrand = integrand.expand();
  Expr U = 0;
  for (int k = integrand.ldegree(s); k <= integrand.degree(s); ++k) {
    U -= integrand.coeff(s, k) / (k + 1);
  }
  return U;
}

}  // namespace

PotentialCheck potential_check(const System& system, std::size_t element) {
  const auto& coordinates = system.coordinates();
  const std::vector<Expr> phi =
      element_generalized_forces(system, system.forces.at(element), angular_velocities(system));
  PotentialCheck check;
  // U(q): Φ may depend on neither time nor the rates
  if (depends_on(phi, {system.time()})) {
    check.witness = "depends on t";
    return check;
  }
  std::vector<GiNaC::realsymbol> rates;
  for (const auto& c : coordinates) rates.push_back(c.rate);
  if (const auto k = depends_on(phi, rates)) {
    check.witness = "depends on der(" + coordinates[*k].name + ")";
    return check;
  }
  // (2.5): the curl of Φ in the coordinates vanishes
  for (std::size_t i = 0; i < phi.size(); ++i) {
    for (std::size_t j = i + 1; j < phi.size(); ++j) {
      const Expr curl = simplify(derivative(phi[i], coordinates[j].value) -
                                 derivative(phi[j], coordinates[i].value));
      if (curl.is_zero()) continue;
      check.witness = "dPhi_" + coordinates[i].name + "/d" + coordinates[j].name + " - dPhi_" +
                      coordinates[j].name + "/d" + coordinates[i].name;
      check.value = curl;
      return check;
    }
  }
  check.conservative = true;
  std::vector<Expr> q;
  for (const auto& c : coordinates) q.push_back(c.value);
  check.potential = line_integral(phi, q);
  return check;
}

void adopt_proven_potentials(System& system) {
  for (std::size_t k = 0; k < system.forces.size(); ++k) {
    ForceElement& element = system.forces[k];
    const bool given_without_potential =
        element.kind == ForceElement::Kind::force || element.kind == ForceElement::Kind::moment;
    if (!given_without_potential || element.conservative) continue;
    const PotentialCheck check = potential_check(system, k);
    if (!check.conservative || !check.potential) continue;
    element.conservative = true;
    element.potential_proven = true;
    element.potential = *check.potential;
  }
}

}  // namespace unidyn
