// RATTLE: the symplectic, constraint-preserving integrator of natural conservative systems, in the
// form for a general Hamiltonian H(p, q) = ½ pᵀ M(q)⁻¹ p + U(q) with holonomic constraints g(q) = 0
// (Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed., §VII.1.4, (1.26);
// Jay 1996). One step of size h from (q0, p0):
//
//   p½ = p0 − h/2 (H_q(p½, q0) + G(q0)ᵀ λ)
//   q1 = q0 + h/2 (H_p(p½, q0) + H_p(p½, q1)),     g(q1) = 0
//   p1 = p½ − h/2 (H_q(p½, q1) + G(q1)ᵀ μ),        G(q1) H_p(p1, q1) = 0
//
// with H_p = M⁻¹ p = q̇ and H_q = −∂L/∂q at that q̇. The first line and the constraint are implicit:
// a fixed-point iteration on (p½, q1) with Newton's method for λ inside, to round-off; the last
// line is explicit in p1 after a linear solve for μ. Second order, symmetric and symplectic; the
// constraints g = 0 and G q̇ = 0 hold to round-off at every step, and the energy error stays
// bounded (no drift) over long runs.
//
// Higher orders by composition (Yoshida 1990; HLW §II.4, §V.3): a step h made of RATTLE substeps
// γ_1 h, …, γ_s h with symmetric weights Σ γ_i = 1 is again symmetric, symplectic and
// constraint-preserving, of order 4 with the triple jump (s = 3) and of order 6 with Yoshida's
// solution A (s = 7; one weight is negative, a substep backwards).
#pragma once

#include <Eigen/Dense>
#include <span>
#include <string_view>
#include <vector>

#include "unidyn/integrate/stepper.hpp"
#include "unidyn/numeric/natural_system.hpp"

namespace unidyn {

struct RattleOptions {
  // The step size h (the last step toward a limit is shortened to land on it).
  double step = 1e-3;
  // 2 (RATTLE itself), 4 or 6 (composed; 3 or 7 RATTLE substeps a step).
  int order = 2;
  // The implicit equations are solved until a correction is below this (relative to 1 + |x|),
  // or stops decreasing (round-off reached).
  double tolerance = 1e-15;
  int max_iterations = 100;
};

// State y = (q, q̇). Dense output: the cubic Hermite interpolant of q with q̇ at both ends, q̇
// linear (within the second order's error; between the steps of the higher orders, third order in
// q and second in q̇ — the values at the steps keep the method's order). rhs_evaluations counts
// evaluations of M and of ∂L/∂q.
class Rattle final : public Stepper {
 public:
  // Throws std::invalid_argument for a step that is not positive and finite or an order other than
  // 2, 4 and 6.
  Rattle(const CompiledNaturalSystem& system, std::vector<double> parameters,
         RattleOptions options = {});

  const RattleOptions& options() const { return options_; }
  // The most fixed-point iterations one step needed so far.
  int most_iterations() const { return most_iterations_; }
  std::string_view name() const override {
    return options_.order == 6 ? "rattle6" : options_.order == 4 ? "rattle4" : "rattle";
  }

 private:
  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // One RATTLE step of size h from (q, p), in place; leaves M(q1)'s factor in mass_.
  void substep(double h, double t0, Eigen::VectorXd& q, Eigen::VectorXd& p);
  // p = M(q) q̇ at the current state.
  void momentum_from_state();
  // The Cholesky factor of M(q) into `factor` (IntegrationError when M is not positive definite).
  void factor_mass(const Eigen::VectorXd& q, Eigen::LLT<Eigen::MatrixXd>& factor, double t_at);
  // ∂L/∂q at (q, M⁻¹ p), M given by its factor.
  const Eigen::VectorXd& gradient_at(const Eigen::VectorXd& q,
                                     const Eigen::LLT<Eigen::MatrixXd>& factor,
                                     const Eigen::VectorXd& p);

  const CompiledNaturalSystem& system_;
  std::vector<double> parameters_;
  RattleOptions options_;
  NaturalSystemData data_;
  int most_iterations_ = 0;
  // p at the current point, valid when have_momentum_.
  Eigen::VectorXd p_;
  bool have_momentum_ = false;
  // The multiplier λ of the last step (the next step's first guess).
  Eigen::VectorXd lambda_;
  // Workspace: M, the factors of M at the step's start (M0_) and at the current q1 (mass_),
  // q̇ = M⁻¹ p and ∂L/∂q.
  Eigen::MatrixXd mass_matrix_;
  Eigen::LLT<Eigen::MatrixXd> M0_, mass_;
  Eigen::VectorXd velocity_, gradient_;
  // Dense output: the state at the start of the last step, and at its end as computed (kept
  // when reset_state() replaces it).
  Eigen::VectorXd y_previous_, y_end_;
};

}  // namespace unidyn
