// The equations of motion linearised about an operating point (an equilibrium or a steady motion),
// for holonomic and nonholonomic constraints alike, as a first-order system ẋ = A x in independent
// coordinates and speeds (the approach of Peterson, Gede & Hubbard 2015, numerically):
//
//   M q̈ = f(q, q̇, t) + Aᵀ λ,   A q̈ + b = 0,   Ψ(q, t) = 0 (position rows),  A q̇ + e = 0 (all rows).
//
// 1. The derivatives of M, f, A, b, e along each coordinate and rate are the tapes' forward-mode
//    derivatives (numeric/tape.hpp): exact but for round-off, no differences.
// 2. Perturbations keep the constraints: Ψ_q δq = 0 gives the dependent coordinates in terms of the
//    independent ones, δq = P_q ξ; A δq̇ + G δq = 0, G = ∂(A q̇ + e)/∂q, gives the dependent rates,
//    δq̇ = P_u η + R ξ. Which are dependent is chosen by pivoting on the largest remaining entry,
//    the rates of coordinates that appear nowhere in the equations first (a rolling body's x, y).
// 3. The accelerations: differentiating the whole system,
//      [M  −Aᵀ] [δq̈]     [∂(M q̈ − f − Aᵀλ)/∂(q, q̇)]
//      [A    0] [δλ] = − [∂(A q̈ + b)/∂(q, q̇)       ] [δq; δq̇].
// 4. The state x = (ξ, η): ξ̇ is the independent coordinates' rows of δq̇, η̇ the independent rates'
//    rows of δq̈.
// 5. Ignorable coordinates drop out: a coordinate none of the other states' derivatives depend on
//    (its column zero beyond round-off, 1e-9 of the largest entry) is removed, and again until none
//    is left (the bicycle's x and y, then its heading and its wheels' angles).
// The point must be an equilibrium or a steady motion: the kept coordinates at rest and the
// independent rates steady (q̈ = 0 there), and the equations not changing with t there. Otherwise
// NotAnOperatingPoint says which value moves.
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "unidyn/analysis/operating_point.hpp"

namespace unidyn {

// The state given is not an equilibrium or steady motion (bad input).
class NotAnOperatingPoint : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// M δq̈ + C δq̇ + K δq = 0 in all the coordinates (a system without constraints).
struct SecondOrderForm {
  Eigen::MatrixXd M, C, K;
};

struct Linearization {
  // The state: independent coordinates ("phi") that are not ignorable, then the independent rates
  // ("der(phi)"); ẋ = A x.
  std::vector<std::string> state;
  Eigen::MatrixXd A;
  // Coordinates dropped as ignorable, in the order dropped; coordinates and rates eliminated by the
  // constraints.
  std::vector<std::string> ignorable, dependent_coordinates, dependent_rates;
  // M δq̈ + C δq̇ + K δq in all coordinates before the constraints are used (C = ∂(M q̈ − f − Aᵀλ)/∂q̇,
  // K likewise along q); the equations themselves when there are no constraints (second_order).
  SecondOrderForm all_coordinates;
  std::optional<SecondOrderForm> second_order;
  // Whether velocity constraints hold at the point (their rows are not gradients of a Ψ).
  bool velocity_constraints = false;

  // For mode shapes in every coordinate: the system before the ignorable coordinates were dropped
  // (its states the independent coordinates, then the independent rates), which of its states were
  // kept (in the order of `state`) and dropped (in the order dropped), and the map from its state
  // to all coordinates and rates, [δq; δq̇] = to_coordinates · x_full.
  Eigen::MatrixXd full_A;
  std::vector<Eigen::Index> kept, dropped;
  Eigen::MatrixXd to_coordinates;
  std::vector<std::string> coordinates;
};

// Throws NotAnOperatingPoint (the point moves), std::runtime_error (M and the constraints singular
// there).
Linearization linearize(const System& system, const CompiledSystem& compiled,
                        const OperatingPoint& point);

}  // namespace unidyn
