// The equations of motion through partial velocities (Kane; Lagrange's second form (10.16)).
#include "unidyn/equations/kane.hpp"

namespace unidyn {
namespace {

// The rows of M and the convective parts c_i = Σ m ∂v/∂q̇^i · a⁰ (+ the bodies' rotation), summed
// into mass and convective.
struct Accumulator {
  const System& system;
  ExprMatrix& mass;
  std::vector<Expr>& convective;
  // the same sums, term by term, for their numeric evaluation
  std::vector<PartialVelocityTerm>& terms;

  // A point mass m moving with position r(q, t): ∂v/∂q̇^i = ∂r/∂q^i, a⁰ = d/dt(v) at q̈ = 0.
  void point(const Expr& m, const VectorExpr& r) {
    const Configuration& config = system.configuration;
    const auto& q = system.coordinates();
    const std::size_t n = q.size();
    std::vector<VectorExpr> partial(n);
    VectorExpr v = diff(r, system.time());
    for (std::size_t i = 0; i < n; ++i) {
      partial[i] = diff(r, q[i].value);
      v = v + partial[i] * q[i].rate;
    }
    const VectorExpr a0{config.convective_derivative(v[0]), config.convective_derivative(v[1]),
                        config.convective_derivative(v[2])};
    PartialVelocityTerm term{m, std::nullopt, {}, {}, a0 * m};
    for (std::size_t i = 0; i < n; ++i) {
      if (is_zero(partial[i])) continue;
      for (std::size_t j = i; j < n; ++j) mass(i, j) += m * dot(partial[i], partial[j]);
      convective[i] += m * dot(partial[i], a0);
      term.columns.push_back(i);
      term.partial_velocity.push_back(partial[i]);
    }
    if (!term.columns.empty()) terms.push_back(std::move(term));
  }

  // Body b's rotation on its own basis e1, e2, e3 (Euler's equations): with ω0 = Qᵀ ω,
  // ∂ω/∂q̇^i · J ∂ω/∂q̇^j = ∂ω0/∂q̇^i · J0 ∂ω0/∂q̇^j (J = Q J0 Qᵀ) and ∂ω/∂q̇^i · Ḣ⁰ =
  // ∂ω0/∂q̇^i · (J0 ω̇0⁰ + ω0 × J0 ω0) (Qᵀ ω̇ = ω̇0): no products Q Qᵀ to reduce by sin² + cos² = 1.
  void rotation(std::size_t b) {
    const Configuration& config = system.configuration;
    const auto& q = system.coordinates();
    const std::size_t n = q.size();
    const GiNaC::matrix& J0 = system.bodies[b].inertia;
    const VectorExpr omega0 = system.body_angular_velocity(b);
    const VectorExpr omega0_dot0{config.convective_derivative(omega0[0]),
                                 config.convective_derivative(omega0[1]),
                                 config.convective_derivative(omega0[2])};
    const VectorExpr H0_dot0 = times(J0, omega0_dot0) + cross(omega0, times(J0, omega0));
    std::vector<VectorExpr> partial(n), J_partial(n);
    for (std::size_t i = 0; i < n; ++i) {
      partial[i] = diff(omega0, q[i].rate);
      J_partial[i] = times(J0, partial[i]);
    }
    PartialVelocityTerm term{0, J0, {}, {}, H0_dot0};
    for (std::size_t i = 0; i < n; ++i) {
      if (is_zero(partial[i])) continue;
      for (std::size_t j = i; j < n; ++j) mass(i, j) += dot(partial[i], J_partial[j]);
      convective[i] += dot(partial[i], H0_dot0);
      term.columns.push_back(i);
      term.partial_velocity.push_back(partial[i]);
    }
    if (!term.columns.empty()) terms.push_back(std::move(term));
  }

  static bool is_zero(const VectorExpr& v) {
    return v[0].is_zero() && v[1].is_zero() && v[2].is_zero();
  }
};

}  // namespace

EquationsOfMotion kane_equations(const System& system) {
  const std::size_t n = system.coordinates().size();
  EquationsOfMotion eq = energies_and_forces(system);
  // M and c from every particle and body: Σ m a · ∂v/∂q̇^i = Σ_j M_ij q̈^j + c_i
  std::vector<Expr> convective(n, 0);
  Accumulator sum{system, eq.mass_matrix, convective, eq.partial_velocity_terms};
  for (const Particle& p : system.particles) sum.point(p.mass, p.position);
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    sum.point(system.bodies[b].mass, system.bodies[b].center);
    sum.rotation(b);
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < i; ++j) eq.mass_matrix(i, j) = eq.mass_matrix(j, i);
  }
  finish_equations(system, convective, eq);
  return eq;
}

}  // namespace unidyn
