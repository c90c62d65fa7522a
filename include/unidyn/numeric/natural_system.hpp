// A natural conservative system compiled for symplectic integration: L = ½ q̇ᵀ M(q) q̇ − U(q) with
// position constraints Ψ(q) = 0 only, nothing depending on time (book §4.6–4.9: T = T2, every
// force from a potential, scleronomic constraints). Its Hamiltonian is H = ½ pᵀ M⁻¹ p + U with
// p = M q̇, H_p = q̇ and H_q = −∂L/∂q at that q̇.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {

// Registers of one evaluation (one per thread).
struct NaturalSystemData {
  TapeWorkspace workspace;
  std::vector<double> inputs, outputs;
};

class CompiledNaturalSystem {
 public:
  // Throws std::invalid_argument, naming what stands in the way, unless the system is natural:
  // no velocity, unilateral or rough constraints, no non-conservative forces, nothing explicit in
  // t, and T quadratic in q̇ with M free of q̇.
  CompiledNaturalSystem(const System& system, const EquationsOfMotion& equations);

  std::size_t coordinate_count() const { return n_; }
  std::size_t constraint_count() const { return m_; }
  NaturalSystemData make_data() const;

  // M(q), and ∂L/∂q = ∂T/∂q − ∂U/∂q at (q, q̇): separate, since M does not depend on q̇.
  void mass_matrix(const Eigen::VectorXd& q, std::span<const double> parameters,
                   Eigen::MatrixXd& mass, NaturalSystemData& data) const;
  void lagrangian_gradient(const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                           std::span<const double> parameters, Eigen::VectorXd& gradient,
                           NaturalSystemData& data) const;
  // Ψ(q) and G = ∂Ψ/∂q.
  void constraints(const Eigen::VectorXd& q, std::span<const double> parameters,
                   Eigen::VectorXd& psi, Eigen::MatrixXd& jacobian, NaturalSystemData& data) const;

 private:
  // inputs [q, q̇, p] (the constraint tape ignores q̇)
  void load(const Eigen::VectorXd& q, const Eigen::VectorXd* qdot,
            std::span<const double> parameters, NaturalSystemData& data) const;

  std::size_t n_ = 0, m_ = 0, p_ = 0;
  Tape mass_;         // [q, q̇, p] → M (row-major); q̇ unused
  Tape gradient_;     // [q, q̇, p] → ∂L/∂q
  Tape constraints_;  // [q, q̇, p] → Ψ, G (row-major); q̇ unused
};

}  // namespace unidyn
