// Approach II: elimination of the integrable constraints that can be solved for a coordinate.
#include "unidyn/equations/reduction.hpp"

#include <optional>

#include "unidyn/equations/friction.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"

namespace unidyn {
namespace {

// The coordinate Ψ can be solved for: Ψ linear in q^k with a coefficient free of every coordinate
// and rate. nullopt when there is none.
std::optional<std::size_t> solvable_coordinate(const System& system, const Expr& psi) {
  const auto& q = system.coordinates();
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Expr a = derivative(psi, q[k].value);
    if (a.is_zero()) continue;
    bool free = true;
    for (const auto& c : q) free = free && !a.has(c.value) && !a.has(c.rate);
    if (free) return k;
  }
  return std::nullopt;
}

// A body's centre and rotation with coordinate k substituted; its Euler chart loses the angle
// (no chart) or follows the renumbering of the coordinates after k.
void substitute_body(Body& body, const GiNaC::exmap& map, std::size_t k) {
  body.center = subs(body.center, map);
  // a coordinate of the tree is now a function of the others: no longer a tree of joints
  body.joint.reset();
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned j = 0; j < 3; ++j) body.rotation(i, j) = body.rotation(i, j).subs(map);
  }
  if (!body.chart) return;
  for (const std::size_t angle : body.chart->coordinates) {
    if (angle == k) {
      body.chart.reset();
      return;
    }
  }
  for (std::size_t& angle : body.chart->coordinates) {
    if (angle > k) --angle;
  }
}

}  // namespace

Reduction eliminate_constraints(const System& full) {
  Reduction result{full, {}};
  System& system = result.system;
  for (bool eliminated = true; eliminated;) {
    eliminated = false;
    for (std::size_t c = 0; c < system.constraints.size(); ++c) {
      const Constraint& constraint = system.constraints[c];
      // (§3.8) friction needs the normal force, and a unilateral contact may let go: both keep
      // their multipliers
      if (constraint.kind != Constraint::Kind::position || carries_friction(system, c) ||
          constraint.unilateral) {
        continue;
      }
      const auto k = solvable_coordinate(system, constraint.expression);
      if (!k) continue;
      // q^k = q^k − Ψ / (∂Ψ/∂q^k), its rate and acceleration by the total derivative
      const CoordinateSymbols coordinate = system.coordinates()[*k];
      const Expr solution = normal_within_budget(
          coordinate.value -
              constraint.expression / derivative(constraint.expression, coordinate.value),
          "approach II");
      GiNaC::exmap map{{coordinate.value, solution}};
      const Expr rate = system.configuration.total_derivative(solution);
      map[coordinate.rate] = rate;
      map[coordinate.acceleration] = system.configuration.total_derivative(rate);
      result.notes.push_back("eliminated " + coordinate.name + " by constraint " + constraint.name);

      // The reduced model: every expression substituted, the coordinate and constraint removed.
      System reduced = system;
      reduced.configuration = system.configuration.without(*k);
      for (auto& p : reduced.particles) p.position = subs(p.position, map);
      for (auto& b : reduced.bodies) substitute_body(b, map, *k);
      for (auto& f : reduced.forces) {
        f.potential = f.potential.subs(map);
        f.angle.reset();
        for (auto& pf : f.forces) pf.force = subs(pf.force, map);
        for (auto& bf : f.body_forces) {
          bf.point = subs(bf.point, map);
          bf.force = subs(bf.force, map);
        }
        for (auto& m : f.moments) m.moment = subs(m.moment, map);
      }
      reduced.constraints.erase(reduced.constraints.begin() + static_cast<std::ptrdiff_t>(c));
      for (auto& other : reduced.constraints) {
        other.expression = other.expression.subs(map);
        for (auto& load : other.loads) {
          load.force = subs(load.force, map);
          load.moment = subs(load.moment, map);
        }
        if (other.friction) {
          other.friction->dynamic_coefficient = other.friction->dynamic_coefficient.subs(map);
          other.friction->static_coefficient = other.friction->static_coefficient.subs(map);
          other.friction->viscous_coefficient = other.friction->viscous_coefficient.subs(map);
          other.friction->at = subs(other.friction->at, map);
          other.friction->surface_velocity = subs(other.friction->surface_velocity, map);
        }
      }
      reduced.initial_values.erase(reduced.initial_values.begin() +
                                   static_cast<std::ptrdiff_t>(*k));
      reduced.initial_rates.erase(reduced.initial_rates.begin() + static_cast<std::ptrdiff_t>(*k));
      for (auto* given : {&reduced.initial_value_given, &reduced.initial_rate_given}) {
        if (given->size() > *k) given->erase(given->begin() + static_cast<std::ptrdiff_t>(*k));
      }
      for (auto* outputs : {&reduced.outputs, &reduced.conserved, &reduced.stop_when}) {
        std::vector<Output> kept;
        for (auto& o : *outputs) {
          if (o.expression.has(constraint.multiplier)) {
            result.notes.push_back("dropped output " + o.name + ": it needs " + constraint.name +
                                   ".lambda, which approach II does not give");
            continue;
          }
          kept.push_back({o.name, o.expression.subs(map), o.where});
        }
        *outputs = kept;
      }
      system = reduced;
      eliminated = true;
      break;
    }
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    result.notes.push_back(
        "kept constraint " + c.name +
        (c.kind == Constraint::Kind::velocity ? ": a velocity constraint (Routh–Voss, (3.8))"
         : carries_friction(system, k)
             ? ": its friction needs its normal force, which approach II does not give"
         : c.unilateral ? ": it is unilateral, and its contact may be lost"
                        : ": it is not linear in a coordinate with a constant coefficient"));
  }
  return result;
}

}  // namespace unidyn
