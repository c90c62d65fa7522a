// The initial state that keeps what the user gave and computes the rest: the coordinates and
// rates given (in `initial:` or with --set) are fixed; those left out are solved for from the
// constraints that hold at the start — Newton's method on Ψ(q) = 0 over the free coordinates, then
// the linear system A q̇ + e = 0 (Ψ̇ = 0 for position constraints) over the free rates. Each step
// takes the least-norm correction, so a free value that no constraint needs keeps its value (0
// when the model does not give it). Unilateral contacts are not solved for; one that starts inside
// (Ψ < 0) is refused.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "unidyn/integrate/simulation.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

// One tolerance for "a state satisfies its constraints", the same for a simulation's start,
// `check`, the analyses and Python: a constraint's residual measured as a distance — |Ψ_k| over the
// length of its gradient ∂Ψ_k/∂q (in the coordinates' units), |a_k · q̇ + e_k| over |a_k| (in the
// rates') — at most 1e-10 of the state's size (its largest |q_i|, or |q̇_i|; 1 where all are 0). A
// model in millimetres and one in kilometres are held alike, and Ψ = x² + y² − L² (m²) as
// Ψ = |r| − L (m).
inline constexpr double kConstraintTolerance = 1e-10;

// A residual as that fraction: |residual| / |gradient| / size(values) (|residual| / size where the
// gradient is 0).
double relative_residual(double residual, const Eigen::Ref<const Eigen::RowVectorXd>& gradient,
                         const Eigen::VectorXd& values);

// The given values violate a constraint, or leave too few free values to satisfy it: bad input.
class InitialStateError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The rates that give each body listed in `initial:` as B.omega (or B.omega_body) its angular
// velocity at the start: ω = W(q) q̇ solved for the rates of the coordinates of its rotation at the
// initial coordinates (least norm: for Euler parameters the rate keeps e·ė = 0). Throws
// InitialStateError where W cannot give it (Euler angles at gimbal lock).
void apply_initial_angular_velocities(const System& system, SimulationStart& start);

// Completes `start` (its q_given and qdot_given say what is fixed). Returns what was computed, one
// "name = value" each (coordinates, then rates), in the order of the coordinates. Throws
// InitialStateError naming the constraint, its residual and the coordinates it involves.
std::vector<std::string> complete_initial_state(const System& system,
                                                const CompiledSystem& compiled,
                                                SimulationStart& start);

// Whether the start of `full` gives a value or rate of a coordinate that `reduced` (its approach-II
// form) eliminated.
bool gives_eliminated_values(const System& full, const SimulationStart& full_start,
                             const System& reduced);

// Approach II's start from the full model's completed start: each reduced coordinate's value and
// rate taken from it (by name), all of them given.
SimulationStart restricted_start(const System& full, const SimulationStart& full_start,
                                 const System& reduced);

}  // namespace unidyn
