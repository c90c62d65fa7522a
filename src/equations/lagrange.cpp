// Lagrange's equations, approach I.
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/symbolic/derivative.hpp"

namespace unidyn {

std::vector<Expr> element_generalized_forces(const System& system, const ForceElement& element,
                                             const std::vector<VectorExpr>& omega) {
  const auto& q = system.coordinates();
  std::vector<Expr> phi(q.size(), 0);
  // Φ_i = Σ F · ∂r/∂q^i + Σ M · ∂ω/∂q̇^i over the element's forces and moments (10.x)
  for (std::size_t i = 0; i < q.size(); ++i) {
    for (const auto& [p, F] : element.forces) {
      phi[i] += dot(F, diff(system.particles[p].position, q[i].value));
    }
    for (const auto& f : element.body_forces) phi[i] += dot(f.force, diff(f.point, q[i].value));
    for (const auto& moment : element.moments) {
      phi[i] += dot(moment.moment, diff(omega[moment.body], q[i].rate));
    }
  }
  return phi;
}

std::vector<VectorExpr> angular_velocities(const System& system) {
  std::vector<VectorExpr> omega;
  for (std::size_t b = 0; b < system.bodies.size(); ++b)
    omega.push_back(system.angular_velocity(b));
  return omega;
}

std::vector<Expr> generalized_forces(const System& system) {
  // Φ over the non-conservative elements (the others enter through −∂U/∂q)
  std::vector<Expr> phi(system.coordinates().size(), 0);
  const std::vector<VectorExpr> omega = angular_velocities(system);
  for (const auto& element : system.forces) {
    if (element.conservative) continue;
    const std::vector<Expr> own = element_generalized_forces(system, element, omega);
    for (std::size_t i = 0; i < phi.size(); ++i) phi[i] += own[i];
  }
  return phi;
}

void constraint_rows(const System& system, EquationsOfMotion& eq) {
  // Constraints: a_k · q̇ + e_k = 0 and its rate A q̈ + b = 0
  const Configuration& config = system.configuration;
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  const std::size_t m = system.constraints.size();
  eq.constraint_matrix = ExprMatrix(m, n);
  eq.constraint_velocity_term.assign(m, 0);
  eq.constraint_bias.assign(m, 0);
  eq.constraint_position.assign(m, 0);
  GiNaC::exmap no_rate;
  for (const auto& c : q) no_rate[c.rate] = 0;
  for (std::size_t k = 0; k < m; ++k) {
    const Constraint& c = system.constraints[k];
    Expr velocity_form;
    if (c.kind == Constraint::Kind::position) {
      eq.constraint_position[k] = c.expression;
      velocity_form = config.total_derivative(c.expression);  // Ψ̇ = ∂Ψ/∂q q̇ + ∂Ψ/∂t
    } else {
      velocity_form = c.expression;
    }
    for (std::size_t j = 0; j < n; ++j)
      eq.constraint_matrix(k, j) = derivative(velocity_form, q[j].rate);
    eq.constraint_velocity_term[k] = velocity_form.subs(no_rate);
    eq.constraint_bias[k] = config.convective_derivative(velocity_form);  // at q̈ = 0
  }
}

EquationsOfMotion energies_and_forces(const System& system) {
  const std::size_t n = system.coordinates().size();
  EquationsOfMotion eq;
  eq.kinetic_energy = system.kinetic_energy();
  eq.potential_energy = system.potential_energy();
  eq.generalized_force = generalized_forces(system);
  eq.mass_matrix = ExprMatrix(n, n);
  return eq;
}

void finish_equations(const System& system, const std::vector<Expr>& convective,
                      EquationsOfMotion& eq) {
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  // row i: Σ_j M_ij q̈^j + c_i + ∂U/∂q^i − Φ_i = 0, so f_i = Φ_i − ∂U/∂q^i − c_i
  eq.forcing.assign(n, 0);
  eq.applied_forcing.assign(n, 0);
  eq.inertia_terms.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    Expr inertia = convective[i];
    for (std::size_t j = 0; j < n; ++j) inertia += eq.mass_matrix(i, j) * q[j].acceleration;
    eq.inertia_terms[i] = inertia;
    eq.applied_forcing[i] = eq.generalized_force[i] - derivative(eq.potential_energy, q[i].value);
    eq.forcing[i] = eq.applied_forcing[i] - convective[i];
  }
  constraint_rows(system, eq);
}

EquationsOfMotion lagrange_equations(const System& system) {
  const Configuration& config = system.configuration;
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  EquationsOfMotion eq = energies_and_forces(system);
  // Row i: d/dt(∂T/∂q̇^i) − ∂T/∂q^i + ∂U/∂q^i − Φ_i, linear in q̈. With p_i = ∂T/∂q̇^i:
  // M_ij = ∂p_i/∂q̇^j (symmetric: each pair once), d/dt p_i = Σ_j M_ij q̈^j + ṗ_i⁰ with the
  // convective part ṗ_i⁰ = ∂p_i/∂t + Σ_j ∂p_i/∂q^j q̇^j, and c_i = ṗ_i⁰ − ∂T/∂q^i.
  // ∂T/∂q̇^i and ∂T/∂q^i in one walk through T, M_ij of each p_i in one walk through p_i
  std::vector<Expr> rates, x;
  for (const auto& c : q) rates.push_back(c.rate);
  for (const auto& c : q) x.push_back(c.value);
  x.insert(x.end(), rates.begin(), rates.end());
  const std::vector<Expr> dT = gradient(eq.kinetic_energy, x);
  std::vector<Expr> convective(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Expr& momentum = dT[n + i];
    const std::vector<Expr> dp = gradient(
        momentum, std::vector<Expr>(rates.begin() + static_cast<std::ptrdiff_t>(i), rates.end()));
    for (std::size_t j = i; j < n; ++j) {
      eq.mass_matrix(i, j) = dp[j - i];
      eq.mass_matrix(j, i) = eq.mass_matrix(i, j);
    }
    convective[i] = config.convective_derivative(momentum) - dT[i];
  }
  finish_equations(system, convective, eq);
  return eq;
}

}  // namespace unidyn
