// RATTLE for H = ½ pᵀ M(q)⁻¹ p + U(q) with holonomic constraints (HLW §VII.1.4, (1.26)).
#include "unidyn/integrate/rattle.hpp"

#include <cmath>
#include <span>
#include <stdexcept>
#include <utility>

#include "unidyn/integrate/hermite.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

// |dx| relative to 1 + |x|, in the max norm.
double relative_change(const Eigen::VectorXd& dx, const Eigen::VectorXd& x) {
  if (dx.size() == 0) return 0.0;
  return dx.cwiseAbs().maxCoeff() / (1.0 + x.cwiseAbs().maxCoeff());
}

// (Yoshida 1990) The weights γ_i of a symmetric composition of RATTLE of the given order: the step
// h is made of substeps γ_1 h, …, γ_s h (Σ γ_i = 1). Order 4: the triple jump γ = (a, 1 − 2a, a),
// a = 1 / (2 − 2^{1/3}); order 6: Yoshida's solution A, seven substeps (w3 w2 w1 w0 w1 w2 w3).
std::span<const double> composition_weights(int order) {
  static const double second[] = {1.0};
  static const double a = 1.0 / (2.0 - std::cbrt(2.0));
  static const double fourth[] = {a, 1.0 - 2.0 * a, a};
  static const double w1 = -1.17767998417887, w2 = 0.235573213359357, w3 = 0.784513610477560;
  static const double w0 = 1.0 - 2.0 * (w1 + w2 + w3);
  static const double sixth[] = {w3, w2, w1, w0, w1, w2, w3};
  if (order == 4) return fourth;
  if (order == 6) return sixth;
  return second;
}

}  // namespace

Rattle::Rattle(const CompiledNaturalSystem& system, std::vector<double> parameters,
               RattleOptions options)
    : Stepper([](double, const Eigen::VectorXd&, Eigen::VectorXd&) {
        throw std::logic_error("rattle: no right-hand side is evaluated");
      }),
      system_(system),
      parameters_(std::move(parameters)),
      options_(options),
      data_(system.make_data()) {
  if (!(options_.step > 0.0) || !std::isfinite(options_.step)) {
    throw std::invalid_argument("rattle: the step size must be positive and finite");
  }
  if (options_.order != 2 && options_.order != 4 && options_.order != 6) {
    throw std::invalid_argument("rattle: the order must be 2, 4 or 6");
  }
}

void Rattle::restart() {
  have_momentum_ = false;
  lambda_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(system_.constraint_count()));
}

void Rattle::before_reset_state() {
  have_momentum_ = false;
  y_end_ = y();
}

void Rattle::factor_mass(const Eigen::VectorXd& q, Eigen::LLT<Eigen::MatrixXd>& factor,
                         double t_at) {
  system_.mass_matrix(q, parameters_, mass_matrix_, data_);
  ++mutable_stats().rhs_evaluations;
  factor.compute(mass_matrix_);
  if (factor.info() != Eigen::Success) {
    throw IntegrationError(describe("M is not positive definite at t = " + detail::to_text(t_at) +
                                    " (redundant coordinates such as Euler parameters, or a "
                                    "singular chart)"),
                           t_at);
  }
}

const Eigen::VectorXd& Rattle::gradient_at(const Eigen::VectorXd& q,
                                           const Eigen::LLT<Eigen::MatrixXd>& factor,
                                           const Eigen::VectorXd& p) {
  velocity_ = factor.solve(p);
  system_.lagrangian_gradient(q, velocity_, parameters_, gradient_, data_);
  ++mutable_stats().rhs_evaluations;
  return gradient_;
}

void Rattle::momentum_from_state() {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  system_.mass_matrix(y().head(n), parameters_, mass_matrix_, data_);
  ++mutable_stats().rhs_evaluations;
  p_ = mass_matrix_ * y().tail(n);
  have_momentum_ = true;
}

void Rattle::advance(double t_limit) {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const double t0 = t();
  const auto [h, t1] = fixed_step_toward(t_limit, options_.step);
  if (!have_momentum_) momentum_from_state();
  // the step as the composition's substeps γ_i h, each a RATTLE step from the last
  Eigen::VectorXd q = y().head(n), p = p_;
  for (const double gamma : composition_weights(options_.order)) substep(gamma * h, t0, q, p);
  // q̇ = M⁻¹ p with M at the end (factored by the last substep)
  Eigen::VectorXd y1(2 * n);
  y1 << q, mass_.solve(p);
  if (!y1.allFinite()) {
    throw IntegrationError(describe("the state became non-finite at t = " + detail::to_text(t1)),
                           t1);
  }
  y_previous_ = y();
  accept_step(t1, y1);
  y_end_ = y();
  p_ = p;
  have_momentum_ = true;
}

void Rattle::substep(double h, double t0, Eigen::VectorXd& q, Eigen::VectorXd& p) {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const auto m = static_cast<Eigen::Index>(system_.constraint_count());
  const Eigen::VectorXd q0 = q, p0 = p;
  // At q0: M0⁻¹ (as its factor) and G0.
  Eigen::VectorXd psi;
  Eigen::MatrixXd G0, G1;
  system_.constraints(q0, parameters_, psi, G0, data_);
  factor_mass(q0, M0_, t0);
  const Eigen::LLT<Eigen::MatrixXd>& M0 = M0_;

  // First half: p½ and q1 by fixed-point iteration, λ by Newton's method inside.
  Eigen::VectorXd p_half = p0 + 0.5 * h * gradient_at(q0, M0, p0);  // H_q = −∂L/∂q
  Eigen::VectorXd q1 = q0 + h * M0.solve(p_half);
  Eigen::VectorXd& lambda = lambda_;
  double change_previous = INFINITY;
  int iteration = 0;
  for (;; ++iteration) {
    if (iteration >= options_.max_iterations) {
      throw IntegrationError(describe("the implicit step did not converge at t = " +
                                      detail::to_text(t0) + "; take a smaller step"),
                             t0);
    }
    // p̃ = p0 + h/2 ∂L/∂q(q0, M0⁻¹ p½)
    const Eigen::VectorXd p_tilde = p0 + 0.5 * h * gradient_at(q0, M0, p_half);
    // W = h/2 (M0⁻¹ + M1⁻¹), M1 at the current q1
    factor_mass(q1, mass_, t0);
    const Eigen::LLT<Eigen::MatrixXd>& M1 = mass_;
    const auto W = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd {
      return 0.5 * h * (M0.solve(v) + M1.solve(v));
    };
    Eigen::VectorXd q1_new = q0 + W(p_tilde - 0.5 * h * G0.transpose() * lambda);
    // λ: g(q1(λ)) = 0 by Newton with J = −h/2 G(q1) W G0ᵀ
    for (int newton = 0; m > 0 && newton < options_.max_iterations; ++newton) {
      system_.constraints(q1_new, parameters_, psi, G1, data_);
      Eigen::MatrixXd WG0t(n, m);
      for (Eigen::Index k = 0; k < m; ++k) WG0t.col(k) = W(G0.row(k).transpose());
      const Eigen::MatrixXd J = -0.5 * h * G1 * WG0t;
      const Eigen::VectorXd d_lambda = J.partialPivLu().solve(-psi);
      lambda += d_lambda;
      q1_new = q0 + W(p_tilde - 0.5 * h * G0.transpose() * lambda);
      if (relative_change(d_lambda, lambda) <= options_.tolerance) break;
      if (psi.cwiseAbs().maxCoeff() == 0.0) break;
    }
    const Eigen::VectorXd p_half_new = p_tilde - 0.5 * h * G0.transpose() * lambda;
    const double change = std::max(relative_change(p_half_new - p_half, p_half_new),
                                   relative_change(q1_new - q1, q1_new));
    p_half = p_half_new;
    q1 = q1_new;
    if (change <= options_.tolerance || (iteration > 2 && change >= change_previous)) break;
    change_previous = change;
  }
  most_iterations_ = std::max(most_iterations_, iteration + 1);

  // Second half, explicit: p* = p½ + h/2 ∂L/∂q(q1, M1⁻¹ p½), p1 = p* − h/2 G1ᵀ μ with G1 M1⁻¹ p1 =
  // 0.
  factor_mass(q1, mass_, t0);
  Eigen::VectorXd p1 = p_half + 0.5 * h * gradient_at(q1, mass_, p_half);
  if (m > 0) {
    system_.constraints(q1, parameters_, psi, G1, data_);
    const Eigen::MatrixXd M1_inv_G1t = mass_.solve(G1.transpose());
    const Eigen::VectorXd mu =
        (0.5 * h * G1 * M1_inv_G1t).partialPivLu().solve(G1 * mass_.solve(p1));
    p1 -= 0.5 * h * G1.transpose() * mu;
  }
  q = q1;
  p = p1;
}

void Rattle::interpolate(double t, Eigen::VectorXd& y_out) const {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const double h = this->t() - t_previous(), theta = (t - t_previous()) / h;
  const double one_minus = 1.0 - theta;
  // q: cubic Hermite with q̇ at both ends; q̇: linear
  const HermiteWeights w = cubic_hermite(theta, h);
  y_out.resize(2 * n);
  y_out.head(n) = w.h00 * y_previous_.head(n) + w.h01 * y_end_.head(n) +
                  w.h10 * y_previous_.tail(n) + w.h11 * y_end_.tail(n);
  y_out.tail(n) = one_minus * y_previous_.tail(n) + theta * y_end_.tail(n);
}

}  // namespace unidyn
