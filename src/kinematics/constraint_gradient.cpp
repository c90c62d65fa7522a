// The loads of a constraint on particles and bodies from its row in the coordinates.
#include "unidyn/kinematics/constraint_gradient.hpp"

#include <stdexcept>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// What moves with the coordinates and what a constraint load on it pairs with: a particle's
// position (∂r/∂q^i), a body's centre (∂x̄/∂q^i) or a body's orientation (∂ω/∂q̇^i).
struct Slot {
  enum class Kind { particle, center, orientation } kind;
  std::size_t index;
  std::vector<VectorExpr> partial;  // per coordinate
};

bool moves(const std::vector<VectorExpr>& partial) {
  for (const auto& v : partial) {
    for (int k = 0; k < 3; ++k) {
      if (!expand_within_budget(v[k], "a constraint's gradient").is_zero()) return true;
    }
  }
  return false;
}

std::vector<Slot> moving_slots(const System& system) {
  const auto& q = system.coordinates();
  std::vector<Slot> slots;
  const auto add = [&](Slot::Kind kind, std::size_t index, const auto& partial_of) {
    Slot slot{kind, index, {}};
    for (const auto& c : q) slot.partial.push_back(partial_of(c));
    if (moves(slot.partial)) slots.push_back(std::move(slot));
  };
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    add(Slot::Kind::particle, p,
        [&](const CoordinateSymbols& c) { return diff(system.particles[p].position, c.value); });
  }
  for (std::size_t b = 0; b < system.bodies.size(); ++b) {
    add(Slot::Kind::center, b,
        [&](const CoordinateSymbols& c) { return diff(system.bodies[b].center, c.value); });
    const VectorExpr omega = system.angular_velocity(b);
    add(Slot::Kind::orientation, b,
        [&](const CoordinateSymbols& c) { return diff(omega, c.rate); });
  }
  return slots;
}

// Whether each coordinate moves at most one slot.
bool coordinates_separate(const std::vector<Slot>& slots) {
  if (slots.empty()) return true;
  for (std::size_t i = 0; i < slots[0].partial.size(); ++i) {
    int moved = 0;
    for (const Slot& slot : slots) moved += moves({slot.partial[i]}) ? 1 : 0;
    if (moved > 1) return false;
  }
  return true;
}

}  // namespace

std::vector<Expr> constraint_row(const System& system, std::size_t k) {
  const Constraint& c = system.constraints.at(k);
  std::vector<Expr> row;
  for (const auto& q : system.coordinates()) {
    row.push_back(c.kind == Constraint::Kind::position ? derivative(c.expression, q.value)
                                                       : derivative(c.expression, q.rate));
  }
  return row;
}

ConstraintLoads solve_constraint_loads(const System& system, const std::vector<Expr>& a) {
  const auto n = static_cast<unsigned>(system.coordinates().size());
  const std::vector<Slot> slots = moving_slots(system);
  // A parametrisation constraint (Euler parameters' unit norm) takes the coordinate the
  // orientation does not: its multiplier ν closes the square system and comes out 0 for a Ψ that
  // depends on the parameters only through Q.
  std::vector<std::vector<Expr>> extra;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    if (system.constraints[k].parametrisation) extra.push_back(constraint_row(system, k));
  }
  const auto columns = static_cast<unsigned>(3 * slots.size() + extra.size());
  // fewer coordinates than that is fine when each coordinate moves one thing alone (a particle
  // kept in a plane, say): the least-norm x, each load along the directions its coordinates move
  // it. (A coordinate that moves several — a pendulum's angle moving both bobs — leaves the split
  // of the load between them undetermined.)
  if (columns != n && !(extra.empty() && columns > n && coordinates_separate(slots))) {
    throw std::invalid_argument(
        "a constraint's force on a particle or body needs the coordinates to fix the moving "
        "positions and orientations one to one (3 per moving particle, 3 per moving centre, 3 per "
        "turning body, plus one per unit norm of Euler parameters); use P.constraint_force / "
        "B.constraint_force (m a - F) instead");
  }
  // Jᵀ x = a with column block s of Jᵀ the partials of slot s
  GiNaC::matrix Jt(n, columns), rhs(n, 1), unknowns(n, 1);
  for (unsigned i = 0; i < n; ++i) {
    rhs(i, 0) = a[i];
    unknowns(i, 0) = GiNaC::symbol();
    for (std::size_t s = 0; s < slots.size(); ++s) {
      for (unsigned k = 0; k < 3; ++k) {
        Jt(i, static_cast<unsigned>(3 * s) + k) = slots[s].partial[i][static_cast<int>(k)];
      }
    }
    for (std::size_t e = 0; e < extra.size(); ++e) {
      Jt(i, static_cast<unsigned>(3 * slots.size() + e)) = extra[e][i];
    }
  }
  GiNaC::matrix x;
  try {
    if (columns == n) {
      x = Jt.solve(unknowns, rhs);
    } else {
      // x = J (Jᵀ J)⁻¹ a: (Jᵀ J) y = a, x = J y
      const GiNaC::matrix J = Jt.transpose();
      x = J.mul(Jt.mul(J).solve(unknowns, rhs));
    }
  } catch (const std::runtime_error&) {
    throw std::invalid_argument(
        "the coordinates do not determine the positions and orientations here");
  }
  ConstraintLoads loads{std::vector<VectorExpr>(system.particles.size()),
                        std::vector<VectorExpr>(system.bodies.size()),
                        std::vector<VectorExpr>(system.bodies.size())};
  for (std::size_t s = 0; s < slots.size(); ++s) {
    VectorExpr v;
    for (unsigned k = 0; k < 3; ++k) {
      v[static_cast<int>(k)] = simplify(x(static_cast<unsigned>(3 * s) + k, 0));
    }
    switch (slots[s].kind) {
      case Slot::Kind::particle:
        loads.particle_force[slots[s].index] = v;
        break;
      case Slot::Kind::center:
        loads.body_force[slots[s].index] = v;
        break;
      case Slot::Kind::orientation:
        loads.body_moment[slots[s].index] = v;
        break;
    }
  }
  return loads;
}

ConstraintLoads constraint_loads(const System& system, std::size_t k) {
  const Constraint& c = system.constraints.at(k);
  ConstraintLoads loads{std::vector<VectorExpr>(system.particles.size()),
                        std::vector<VectorExpr>(system.bodies.size()),
                        std::vector<VectorExpr>(system.bodies.size())};
  if (c.parametrisation) return loads;
  if (c.loads.empty()) return solve_constraint_loads(system, constraint_row(system, k));
  for (const auto& load : c.loads) {
    loads.body_force[load.body] = load.force;
    loads.body_moment[load.body] = load.moment;
  }
  return loads;
}

std::vector<VectorExpr> constraint_gradient(const System& system, const std::vector<Expr>& a) {
  return solve_constraint_loads(system, a).particle_force;
}

}  // namespace unidyn
