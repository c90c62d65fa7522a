// The equations of motion reduced to independent coordinates and speeds at one state, the step
// both the linearisation about an operating point (analysis/linearization.hpp) and the Floquet
// analysis of a periodic motion (analysis/floquet.hpp) take. With
//
//   M q̈ = f(q, q̇, t) + Aᵀ λ,   A q̈ + b = 0,   Ψ(q, t) = 0 (position rows),  A q̇ + e = 0 (all rows),
//
// a perturbation that keeps the constraints is δq = P_q ξ (Ψ_q δq = 0), δq̇ = P_u η + R ξ
// (A δq̇ + G δq = 0, G = ∂(A q̇ + e)/∂q), and differentiating the whole system
//
//   [M  −Aᵀ] [δq̈]     [∂(M q̈ − f − Aᵀλ)/∂(t, q, q̇)]
//   [A    0] [δλ] = − [∂(A q̈ + b)/∂(t, q, q̇)       ] [δt; δq; δq̇]  =:  [D; ·] [δt; δq; δq̇]
//
// gives ẋ = F x for x = (ξ, η): ξ̇ the independent coordinates' rows of δq̇, η̇ the independent
// rates' rows of δq̈. F is the Jacobian of the reduced vector field at any state on the
// constraints, at rest or moving, so it serves along a periodic motion as well as at a point.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

#include "unidyn/analysis/linearization.hpp"

namespace unidyn::detail {

// Entries below this fraction of the largest are round-off (for dependence and ignorability).
constexpr double kNegligible = 1e-9;

// The largest |entry| of x; 0 when it has none.
template <class Derived>
double largest(const Eigen::MatrixBase<Derived>& x) {
  return x.size() == 0 ? 0.0 : x.cwiseAbs().maxCoeff();
}

std::string rate_name(const std::string& coordinate);

// The choice of dependent coordinates and rates, and the independent ones, in order.
struct Choice {
  std::vector<Eigen::Index> dependent_q, independent_q, dependent_u, independent_u;
};

// The reduced system at a state: ẋ = F x for x = (ξ, η), with the maps P_q, P_u, R and δq̈ = D
// [δt; δq; δq̇]; M, f, the constraint rows A_all (every row, held or not) and the balance's
// derivatives ∂(M q̈ − f − Aᵀλ)/∂(t, q, q̇) there.
struct ReducedSystem {
  Choice choice;
  Eigen::MatrixXd F, P_q, P_u, R, D, M, A_all, balance;
  Eigen::VectorXd f;
};

// The reduced system at point (its t, q, q̇, q̈, λ and the constraints that hold). The dependent
// coordinates and rates are chosen here (pivoting on the largest remaining entry, the rates of
// coordinates that appear nowhere in the equations first) unless `given` says them. Throws
// std::runtime_error when the constraints are dependent or M and the constraints singular there.
ReducedSystem reduced_system(const CompiledSystem& compiled, const OperatingPoint& point,
                             const Choice* given);

// A state near the point, on the constraints: the independent coordinates and rates moved by small
// amounts of their own, the dependent ones completed (integrate/initial_state.hpp), q̈ and λ solved.
// Nothing when the constraints or the equations cannot be satisfied there.
std::optional<OperatingPoint> nearby_state(const System& system, const CompiledSystem& compiled,
                                           const OperatingPoint& point, const ReducedSystem& at);

// The linearisation's names and maps from the reduction `at`: the independent coordinates that
// are not ignorable, then the independent rates (state), A = F over them, the dependent names,
// the ignorable ones dropped and the map to every coordinate and rate. A coordinate is ignorable
// when no other state's derivative depends on it in any of `samples` (F at the point, at a state
// near it, along its motion: an influence that vanishes only at the point shows nearby): its
// column below kNegligible of each sample's largest entry, again until none is left. With no
// samples, none is dropped. M, C, K and the checks of the point are the caller's.
Linearization reduced_linearization(const System& system, const ReducedSystem& at,
                                    const std::vector<Eigen::MatrixXd>& samples);

}  // namespace unidyn::detail
