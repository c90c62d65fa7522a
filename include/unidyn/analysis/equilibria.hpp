// Equilibria and steady motions found by a multi-start Newton method (`unidyn equilibria`).
//
// The rates are those given (`--at der(q)=VALUE`, 0 when not given) and so are any coordinates
// given. Cyclic coordinates (`--cyclic`, Routh's: the equations do not depend on them) are not
// solved for: each is held at its value (given, else the model's initial one) and its rate is
// given, or follows from its momentum p = ∂T/∂q̇ given (`--at p(q)=VALUE`), or from the
// constraints (a rolling disk's centre, whose acceleration is then free: it turns as it circles).
// The other coordinates q, the rates and accelerations that follow, and the multipliers λ solve
//   f(q, q̇) + Aᵀλ − M q̈ = 0 (the forces balance),   Ψ(q) = 0,   A q̇ + e = 0,   A q̈ + b = 0,
//   ∂T/∂q̇ = p (the momenta given)
// (analysis/steady_balance.hpp) by Gauss–Newton steps (least squares, so a continuum of solutions
// is no obstacle) with exact derivatives of the compiled equations and a backtracking line
// search, from `starts` points: each angle (a coordinate the equations are 2π-periodic in) uniform
// in (−π, π], each other coordinate uniform within 2 (1 + |its initial value|) of its initial
// value, each body's Euler parameters a rotation drawn uniformly. Each solution is then linearised
// (analysis/linearization.hpp): one that is not an equilibrium or steady motion there (a rate of a
// coordinate that is not ignorable) is dropped, and solutions equal up to 1e-6 — angles modulo 2π,
// Euler parameters up to their sign (e and −e are one rotation: the first nonzero one is made
// positive), ignorable coordinates not compared — are one. Each comes with its modes and verdict,
// and, where an energy method applies (analysis/energy_minimum.hpp), whether the potential has a
// strict minimum on the constraints there: Lagrange–Dirichlet at rest (the potential amended by
// the centrifugal part of any steady drive: the bead on the rotating hoop), Routh's amended
// potential with cyclic coordinates.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unidyn/analysis/modes.hpp"

namespace unidyn {

struct EquilibriumSearch {
  std::size_t starts = 200;
  unsigned seed = 20261126u;
  // The cyclic coordinates, by name.
  std::vector<std::string> cyclic;
};

struct Equilibrium {
  OperatingPoint point;
  Linearization linearization;
  ModeAnalysis modes;
  // Where an energy method applies: whether the potential (Lagrange–Dirichlet) or the amended
  // potential (Routh, with cyclic coordinates) has a strict minimum there on the constraints,
  // ignorable coordinates aside.
  std::optional<bool> potential_minimum;
  bool amended = false;
  // The dimension of the continuum of equilibria through it (the forces balance along it: a body
  // at rest with no forces, anywhere), ignorable coordinates aside; 0 for an isolated one.
  std::size_t continuum = 0;
};

struct EquilibriumSearchResult {
  // The distinct equilibria, in the order of their coordinates (angles in (−π, π]), then of their
  // rates.
  std::vector<Equilibrium> equilibria;
  // The cyclic coordinates (EquilibriumSearch::cyclic): held, not solved for.
  std::vector<std::string> cyclic;
  // The starts whose solution was left out: where the equations are singular (Euler angles at
  // gimbal lock: the equilibrium may exist, but not in these coordinates), and where the motion
  // is not steady.
  std::size_t singular = 0, not_steady = 0;
};

// Throws std::invalid_argument (bad input): equations that change with t (analysis/
// time_dependence.hpp: their rest states are periodic motions, analysis/floquet.hpp), a cyclic
// coordinate that is not one, given a value
// of its rate and its momentum, a momentum given for a coordinate not said to be cyclic, or a value
// that is not a real number.
EquilibriumSearchResult find_equilibria(const System& system, const CompiledSystem& compiled,
                                        const std::vector<GivenValue>& given,
                                        const std::vector<double>& parameters,
                                        const EquilibriumSearch& search = {});

}  // namespace unidyn
