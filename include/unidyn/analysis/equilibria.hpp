// Equilibria and steady motions found by a multi-start Newton method (`unidyn equilibria`).
//
// The rates are those given (`--at der(q)=VALUE`, 0 when not given) and so are any coordinates
// given; the other coordinates q and the multipliers λ solve
//   f(q, q̇) + A(q)ᵀ λ = 0    (q̈ = 0: the forces balance),    Ψ(q) = 0    (the position
//   constraints),
// by Gauss–Newton steps (least squares, so a continuum of solutions is no obstacle) with exact
// derivatives of the compiled equations and a backtracking line search, from `starts` points: each
// angle (a coordinate the equations are 2π-periodic in) uniform in (−π, π], each other coordinate
// uniform within 2 (1 + |its initial value|) of its initial value, each body's Euler parameters a
// rotation drawn uniformly. Each solution is then linearised
// (analysis/linearization.hpp): one that is not an equilibrium or steady motion there (a rate of a
// coordinate that is not ignorable) is dropped, and solutions equal up to 1e-6 — angles modulo 2π,
// Euler parameters up to their sign (e and −e are one rotation: the first nonzero one is made
// positive), ignorable coordinates not compared — are one. Each comes with its modes and verdict,
// and, at rest with forces from a potential (the linearisation's C = 0 and K symmetric) and no
// velocity constraints, Lagrange–Dirichlet: the stiffness K restricted to the constraints positive
// definite means a strict minimum of the potential (the amended one, with its centrifugal part,
// where a drive turns the system steadily: the bead on the rotating hoop), stable.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unidyn/analysis/modes.hpp"

namespace unidyn {

struct EquilibriumSearch {
  std::size_t starts = 200;
  unsigned seed = 20261126u;
};

struct Equilibrium {
  OperatingPoint point;
  Linearization linearization;
  ModeAnalysis modes;
  // Lagrange–Dirichlet, where it applies: whether the potential has a strict minimum there (on the
  // constraints, ignorable coordinates aside).
  std::optional<bool> potential_minimum;
  // The dimension of the continuum of equilibria through it (the forces balance along it: a body
  // at rest with no forces, anywhere), ignorable coordinates aside; 0 for an isolated one.
  std::size_t continuum = 0;
};

struct EquilibriumSearchResult {
  // The distinct equilibria, in the order of their coordinates (angles in (−π, π]).
  std::vector<Equilibrium> equilibria;
  // The starts whose solution was left out: where the equations are singular (Euler angles at
  // gimbal lock: the equilibrium may exist, but not in these coordinates), and where the motion
  // is not steady.
  std::size_t singular = 0, not_steady = 0;
};

EquilibriumSearchResult find_equilibria(const System& system, const CompiledSystem& compiled,
                                        const std::vector<GivenValue>& given,
                                        const std::vector<double>& parameters,
                                        const EquilibriumSearch& search = {});

}  // namespace unidyn
