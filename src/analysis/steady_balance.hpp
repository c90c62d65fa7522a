// The conditions for a state to stay as it is (an equilibrium or a steady motion), as residuals of
// the unknowns and their exact Jacobian, for analysis/equilibria.cpp.
//
// Unknowns x = [q_free; rates; accelerations; λ]: the coordinates solved for, the rates of cyclic
// coordinates that follow from a momentum given or from the constraints, the accelerations of the
// coordinates that appear nowhere and whose rates follow from the constraints (a rolling disk's
// centre turns as it circles: its ẍ, ÿ are not 0), and the multipliers. The other coordinates and
// rates are as given; every other acceleration is 0. The residual:
//   f(q, q̇) + Aᵀλ − M q̈          n rows: the forces balance,
//   Ψ(q)                          m rows: the position constraints (0 for velocity constraints),
//   A q̇ + e,  A q̈ + b             m rows each: the constraints' rates and accelerations,
//   ∂T/∂q̇ᵢ − pᵢ                   one row per momentum given (Routh's cyclic coordinates).
// The Jacobian: forward-mode derivatives of the tapes along q and q̇ (numeric/tape.hpp), and the
// terms linear in q̇, q̈ and λ.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {

struct SteadyBalance {
  const CompiledSystem& compiled;
  double t = 0.0;
  std::vector<double> parameters;
  // The coordinates and rates not solved for (the others are overwritten by the unknowns).
  Eigen::VectorXd q, qdot;
  std::vector<Eigen::Index> free_q, free_rate, free_acceleration;
  // ∂T/∂q̇ of some coordinates (inputs [t, q, q̇, p]), and which of its outputs are given, as what.
  const Tape* momentum = nullptr;
  std::vector<Eigen::Index> momentum_given;
  Eigen::VectorXd momentum_value;

  struct State {
    Eigen::VectorXd q, qdot, qddot, lambda;
  };

  // The number of unknowns other than λ, and in all.
  Eigen::Index motion_unknowns() const;
  Eigen::Index unknowns() const;
  // The state the unknowns stand for.
  State state(const Eigen::VectorXd& x) const;
  // The unknowns of a state (λ = 0).
  Eigen::VectorXd unknowns_at(const Eigen::VectorXd& q_values) const;
  // The residual at x; with J, its Jacobian in x.
  Eigen::VectorXd residual(const Eigen::VectorXd& x, Eigen::MatrixXd* J = nullptr) const;
};

}  // namespace unidyn
