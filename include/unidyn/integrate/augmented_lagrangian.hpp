// The index-3 augmented Lagrangian formulation with mass-orthogonal projections, integrated by the
// trapezoidal rule (Bayo & Ledesma, Nonlinear Dynamics 9, 1996; Cuadrado, Cardenal & Bayo,
// Nonlinear Dynamics 14, 1997, "ALI3-P": the reference method of the IFToMM benchmark problems).
//
// The equations (3.8) M q̈ = f + Aᵀ λ with position constraints Ψ(t, q) = 0 are taken at index 3:
// the multipliers are those of an augmented Lagrangian, λ = −(λ* + α Ψ), with λ* iterated to the
// value that makes Ψ = 0. The trapezoidal rule gives q̇ and q̈ at the step's end from q alone,
//
//   q̇₁ = (2/h) (q₁ − q₀) − q̇₀,     q̈₁ = (4/h²) (q₁ − q₀) − (4/h) q̇₀ − q̈₀,
//
// and Newton's method solves the h²/4-scaled dynamic equilibrium for q₁,
//
//   R(q₁) = h²/4 (M q̈₁ − f) + Aᵀ (μ + β Ψ) = 0,   μ ← μ + β Ψ after each iteration,
//
// with μ = h²/4 λ*, β = h²/4 α and the tangent M + β AᵀA (the damping and stiffness of f left
// out: they change how fast Newton's method converges, not what it converges to). The velocities
// and accelerations are then projected mass-orthogonally onto A q̇ + e = 0 and A q̈ + b = 0:
//
//   min ½ (x − x*)ᵀ M (x − x*)  subject to  A x + c = 0,
//
// by the same augmented Lagrangian, (M + β AᵀA) x = M x* − Aᵀ (σ + β c), σ ← σ + β (A x + c),
// iterated until the rows hold. The projected q̈ is Gauss's principle at (q₁, q̇₁): the
// accelerations the index-1 equations would give, where those have them.
//
// Nothing here inverts A M⁻¹ Aᵀ: M + β AᵀA is positive definite whatever A's rank, so the method
// passes singular positions (a four-bar whose bars align, where the rows lose rank and the
// mechanism could take either branch) on the branch the dynamics selects, and accepts redundant
// rows. Second order; the step is fixed.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <string_view>
#include <vector>

#include "unidyn/integrate/stepper.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

struct AugmentedLagrangianOptions {
  // The step size h (the last step toward a limit is shortened to land on it).
  double step = 1e-3;
  // β AᵀA against M: β = penalty · max diag M / max |row of A|² (Bayo's α = 4 β / h²). Measured
  // on the IFToMM N four-bar (N = 2, 4, 10, 20 s through 30 singular positions): 1e5 and below
  // stall next to a singular position (the multipliers' iteration contracts by 1 / (1 + β s²)
  // in a direction whose singular value s vanishes there), 1e7 took the wrong branch at N = 4.
  double penalty = 1e6;
  // Newton's method and the projections stop when a correction is below this (relative to 1 +
  // |x|) and the rows hold to it (relative to their scale).
  double tolerance = 1e-12;
  // Next to a singular position the multipliers' iteration contracts slowly (N four-bar, N = 40:
  // 100 iterations were too few there).
  int max_iterations = 400;
};

// State y = (q, q̇); every constraint of the system must be a position constraint. Dense output:
// cubic Hermite interpolants of q (with q̇ at both ends) and of q̇ (with q̈). rhs_evaluations
// counts evaluations of the equations.
class AugmentedLagrangian final : public Stepper {
 public:
  // Throws std::invalid_argument for a step that is not positive and finite, or a system with
  // velocity constraints.
  AugmentedLagrangian(const CompiledSystem& system, std::vector<double> parameters,
                      AugmentedLagrangianOptions options = {});

  const AugmentedLagrangianOptions& options() const { return options_; }
  // The most Newton iterations one step needed so far.
  int most_iterations() const { return most_iterations_; }
  std::string_view name() const override { return "alf"; }

 private:
  void restart() override;
  void before_reset_state() override;
  void advance(double t_limit) override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // M, f, A, b at (t, q, q̇) into data_, counted; Ψ and e too when `positions`.
  void evaluate_equations(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                          bool positions);
  // The factor of M + β AᵀA from data_'s M and A (β fixed at the first call).
  void factor_tangent(double t);
  // q₁ by Newton's method on R(q₁) = 0 from the step's start (q₀, q̇₀, q̈₀) and a first guess;
  // the iterations it took, −1 when it did not converge.
  int solve_positions(double t1, double h, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                      const Eigen::VectorXd& a0, Eigen::VectorXd& q1);
  // One trapezoidal step of size h to t1: q₁ by Newton's method, q̇₁ and q̈₁ projected; false when
  // Newton's method did not converge.
  bool trapezoidal_step(double t1, double h, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                        const Eigen::VectorXd& a0, Eigen::VectorXd& q1, Eigen::VectorXd& v1,
                        Eigen::VectorXd& a1);
  // (q, q̇, q̈) from t0 to t1 in one step, or in halves (recursively) where it fails.
  void step_or_halves(double t0, double t1, int depth, Eigen::VectorXd& q, Eigen::VectorXd& v,
                      Eigen::VectorXd& a);
  // x onto A x + c = 0, mass-orthogonally (A, M in data_, M + β AᵀA factored), given M x*.
  void project(double t, const Eigen::VectorXd& M_x_star, const Eigen::VectorXd& c,
               Eigen::VectorXd& x);
  // q̈ at the current point: Gauss's principle by the projection of M⁻¹ f.
  void acceleration_at_start();

  const CompiledSystem& system_;
  std::vector<double> parameters_;
  AugmentedLagrangianOptions options_;
  CompiledSystemData data_;
  int most_iterations_ = 0;
  double beta_ = 0.0;
  // q̈ at the current point (valid when have_acceleration_) and the scaled multipliers μ.
  Eigen::VectorXd qddot_, mu_;
  bool have_acceleration_ = false;
  Eigen::LLT<Eigen::MatrixXd> tangent_;
  // Dense output: the state and q̈ at the start of the last step and at its end.
  Eigen::VectorXd y_previous_, y_end_, qddot_previous_, qddot_end_;
};

}  // namespace unidyn
