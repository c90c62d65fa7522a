// The derived equations compiled for fast evaluation, and the constrained system solved for q̈
// and the multipliers λ at a state (DESIGN.md "Equations and numerics").
//
//   M(q, t) q̈ = f(q, q̇, t) + Aᵀ λ,     A q̈ + b = 0
//
// solved through the Schur complement: with M = L Lᵀ, (A M⁻¹ Aᵀ) λ = −b − A M⁻¹ f, then
// q̈ = M⁻¹ (f + Aᵀ λ); when M is only semi-definite (redundant coordinates such as Euler
// parameters), through the whole saddle-point system instead.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {

// The mutable side: registers and matrices one evaluation needs (one per thread).
struct CompiledSystemData {
  TapeWorkspace workspace;
  std::vector<double> inputs;
  std::vector<double> outputs;
  Eigen::MatrixXd mass_matrix;
  Eigen::VectorXd forcing;
  Eigen::MatrixXd constraint_matrix;
  Eigen::VectorXd constraint_bias;
  Eigen::VectorXd constraint_velocity_term;
  Eigen::VectorXd constraint_position;
  // Which constraints hold now (unilateral contact made or lost); empty: all of them.
  std::vector<bool> active;
};

class CompiledSystem {
 public:
  CompiledSystem(const System& system, const EquationsOfMotion& equations);

  std::size_t coordinate_count() const { return n_; }
  std::size_t constraint_count() const { return m_; }
  std::size_t parameter_count() const { return p_; }
  std::size_t observation_count() const { return observation_names_.size(); }
  // Names of what observe() returns: kinetic_energy, potential_energy, then the outputs, the
  // conserved quantities and the stop_when expressions of the model.
  const std::vector<std::string>& observation_names() const { return observation_names_; }
  // Which constraints are position constraints (the others are velocity constraints).
  const std::vector<bool>& is_position_constraint() const { return is_position_; }

  CompiledSystemData make_data() const;

  // q̈ and λ at (t, q, q̇). Throws std::runtime_error when M is not positive definite or the
  // constraints are dependent (A M⁻¹ Aᵀ singular).
  void solve(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
             std::span<const double> parameters, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
             CompiledSystemData& data) const;

  // Fills data.constraint_matrix, constraint_velocity_term and constraint_position at (t, q, q̇).
  void constraints(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                   std::span<const double> parameters, CompiledSystemData& data) const;

  // Energies, outputs and conserved quantities at a solved state.
  void observe(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
               const Eigen::VectorXd& qddot, const Eigen::VectorXd& lambda,
               std::span<const double> parameters, std::span<double> values,
               CompiledSystemData& data) const;

 private:
  // q̈ and λ of M q̈ = f + Aᵀ λ, A q̈ + b = 0 for the given rows A, b (M and f in data).
  void solve_with(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                  Eigen::VectorXd& qddot, Eigen::VectorXd& lambda, CompiledSystemData& data) const;
  // The full (n + rows) system when M is only semi-definite.
  void solve_saddle_point(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                          CompiledSystemData& data) const;
  void load_state(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                  std::span<const double> parameters, CompiledSystemData& data) const;

  std::size_t n_ = 0, m_ = 0, p_ = 0;
  Tape dynamics_;     // [t, q, q̇, p] → M, f, A, b
  Tape constraints_;  // [t, q, q̇, p] → A, e, Ψ
  Tape observer_;     // [t, q, q̇, q̈, λ, p] → T, U, outputs, conserved
  std::vector<std::string> observation_names_;
  std::vector<bool> is_position_;
  // Some coordinates are redundant (Euler parameters): M is semi-definite, whatever round-off
  // makes of its Cholesky factor, and the saddle-point system is solved instead.
  bool redundant_coordinates_ = false;
};

}  // namespace unidyn
