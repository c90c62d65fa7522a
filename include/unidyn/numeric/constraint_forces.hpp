// The constraints' forces on each particle and body along a run, from the run's multipliers (the
// report's arrows and plots): F_c = Σ_k λ_k f_k, with f_k the constraint's load on the particle or
// body (8.22; ∂Ψ_k/∂r for a particle and a position constraint, kinematics/constraint_gradient.hpp)
// — the constraints' own forces, friction not included — on E1, E2, E3, a body's at its centre.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {

class ConstraintForces {
 public:
  explicit ConstraintForces(const System& system);

  // "N.Fc.x", "N.Fc.y", "N.Fc.z" for each particle and body a constraint acts on; the names N.
  const std::vector<std::string>& columns() const { return columns_; }
  const std::vector<std::string>& owners() const { return owners_; }
  // Why there are no columns though there are constraints ("" otherwise): the coordinates do not
  // fix the positions one to one (kinematics/constraint_gradient.hpp).
  const std::string& unavailable() const { return unavailable_; }

  // The columns' values at (t, q, q̇, λ), appended to `row`.
  void append(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
              const Eigen::VectorXd& lambda, const std::vector<double>& parameters,
              std::vector<double>& row);

 private:
  std::vector<std::string> columns_, owners_;
  std::string unavailable_;
  // inputs [t, q, q̇, p, λ]
  Tape tape_;
  TapeWorkspace workspace_;
  std::vector<double> inputs_, outputs_;
};

}  // namespace unidyn
