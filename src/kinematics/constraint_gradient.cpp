// ∂Ψ/∂r_P from ∂Ψ/∂q.
#include "unidyn/kinematics/constraint_gradient.hpp"

#include <stdexcept>

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

std::vector<Expr> constraint_row(const System& system, std::size_t k) {
  const Constraint& c = system.constraints.at(k);
  std::vector<Expr> row;
  for (const auto& q : system.coordinates()) {
    row.push_back(c.kind == Constraint::Kind::position ? c.expression.diff(q.value)
                                                       : c.expression.diff(q.rate));
  }
  return row;
}

std::vector<VectorExpr> constraint_gradient(const System& system, const std::vector<Expr>& a) {
  const auto& q = system.coordinates();
  const auto n = static_cast<unsigned>(q.size());
  // the moving particles: those whose position depends on a coordinate
  std::vector<std::size_t> moving;
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    bool moves = false;
    for (const auto& c : q)
      moves = moves || system.particles[p].position.c[0].has(c.value) ||
              system.particles[p].position.c[1].has(c.value) ||
              system.particles[p].position.c[2].has(c.value);
    if (moves) moving.push_back(p);
  }
  if (3 * moving.size() != q.size()) {
    throw std::invalid_argument(
        "a constraint force on a particle needs three coordinates per moving particle (the "
        "positions then determine the coordinates); use P.constraint_force = m a - F instead");
  }
  // Jᵀ g = a with J_(3P+k),i = ∂(r_P · E_k)/∂q^i
  GiNaC::matrix Jt(n, n), rhs(n, 1);
  GiNaC::matrix unknowns(n, 1);
  for (unsigned i = 0; i < n; ++i) {
    rhs(i, 0) = a[i];
    unknowns(i, 0) = GiNaC::symbol();
    for (std::size_t m = 0; m < moving.size(); ++m) {
      for (unsigned k = 0; k < 3; ++k) {
        Jt(i, static_cast<unsigned>(3 * m) + k) =
            system.particles[moving[m]].position.c[k].diff(q[i].value);
      }
    }
  }
  GiNaC::matrix g;
  try {
    g = Jt.solve(unknowns, rhs);
  } catch (const std::runtime_error&) {
    throw std::invalid_argument("the coordinates do not determine the particles' positions here");
  }
  std::vector<VectorExpr> gradient(system.particles.size());
  for (std::size_t m = 0; m < moving.size(); ++m) {
    for (unsigned k = 0; k < 3; ++k) {
      gradient[moving[m]][static_cast<int>(k)] = simplify(g(static_cast<unsigned>(3 * m) + k, 0));
    }
  }
  return gradient;
}

}  // namespace unidyn
