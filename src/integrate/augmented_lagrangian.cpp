// The index-3 augmented Lagrangian formulation with mass-orthogonal projections, trapezoidal rule
// (Bayo & Ledesma 1996; Cuadrado, Cardenal & Bayo 1997).
#include "unidyn/integrate/augmented_lagrangian.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "unidyn/integrate/hermite.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

// |x| in the max norm (0 for an empty vector).
double max_norm(const Eigen::VectorXd& x) {
  return x.size() == 0 ? 0.0 : x.cwiseAbs().maxCoeff();
}

// Newton's method refactors its tangent at the current iterate after this many iterations.
constexpr int kRefactorAfter = 6;
// A step whose Newton iterations fail (one that lands next to a singular position) is taken in
// halves, down to 2^-kMostHalvings of it.
constexpr int kMostHalvings = 12;

}  // namespace

AugmentedLagrangian::AugmentedLagrangian(const CompiledSystem& system,
                                         std::vector<double> parameters,
                                         AugmentedLagrangianOptions options)
    : Stepper([](double, const Eigen::VectorXd&, Eigen::VectorXd&) {
        throw std::logic_error("alf: no right-hand side is evaluated");
      }),
      system_(system),
      parameters_(std::move(parameters)),
      options_(options),
      data_(system.make_data()) {
  if (!(options_.step > 0.0) || !std::isfinite(options_.step)) {
    throw std::invalid_argument("alf: the step size must be positive and finite");
  }
  const auto& position = system_.is_position_constraint();
  if (std::find(position.begin(), position.end(), false) != position.end()) {
    throw std::invalid_argument(
        "alf holds position constraints only, and this model has velocity constraints");
  }
}

void AugmentedLagrangian::restart() {
  have_acceleration_ = false;
  mu_ = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(system_.constraint_count()));
}

void AugmentedLagrangian::before_reset_state() {
  have_acceleration_ = false;
  y_end_ = y();
}

void AugmentedLagrangian::evaluate_equations(double t, const Eigen::VectorXd& q,
                                             const Eigen::VectorXd& qdot, bool positions) {
  system_.equations(t, q, qdot, parameters_, data_);
  if (positions) system_.constraints(t, q, qdot, parameters_, data_);
  ++mutable_stats().rhs_evaluations;
  if (!data_.mass_matrix.allFinite() || !data_.forcing.allFinite() ||
      !data_.constraint_matrix.allFinite() || !data_.constraint_bias.allFinite() ||
      (positions && !data_.constraint_position.allFinite())) {
    throw IntegrationError(describe("the equations are not finite at t = " + detail::to_text(t)),
                           t);
  }
}

void AugmentedLagrangian::factor_tangent(double t) {
  const Eigen::MatrixXd& M = data_.mass_matrix;
  const Eigen::MatrixXd& A = data_.constraint_matrix;
  if (beta_ == 0.0 && A.rows() > 0) {
    // β AᵀA against M: the penalty's stiffness over the step's inertia
    const double rows = A.rowwise().squaredNorm().maxCoeff();
    beta_ = options_.penalty * M.diagonal().cwiseAbs().maxCoeff() / (rows > 0.0 ? rows : 1.0);
  }
  // M + β AᵀA: positive definite when M is, whatever A's rank
  tangent_.compute(A.rows() > 0 ? Eigen::MatrixXd(M + beta_ * A.transpose() * A) : M);
  if (tangent_.info() != Eigen::Success) {
    throw IntegrationError(
        describe("M + β AᵀA is not positive definite at t = " + detail::to_text(t) +
                 " (M is singular where the constraints do not hold it)"),
        t);
  }
}

void AugmentedLagrangian::project(double t, const Eigen::VectorXd& M_x_star,
                                  const Eigen::VectorXd& c, Eigen::VectorXd& x) {
  const Eigen::MatrixXd& A = data_.constraint_matrix;
  if (A.rows() == 0) {
    x = tangent_.solve(M_x_star);
    return;
  }
  // (M + β AᵀA) x = M x* − Aᵀ (σ + β c), σ ← σ + β (A x + c): min ½ |x − x*|²_M on A x + c = 0
  Eigen::VectorXd sigma = Eigen::VectorXd::Zero(A.rows());
  double residual_before = INFINITY;
  for (int k = 0;; ++k) {
    x = tangent_.solve(M_x_star - A.transpose() * (sigma + beta_ * c));
    const Eigen::VectorXd r = A * x + c;
    const double residual = max_norm(r);
    const double scale = max_norm((A * x).cwiseAbs()) + max_norm(c);
    if (residual <= options_.tolerance * scale || residual == 0.0) return;
    // at a singular position a row may be off A's range by round-off: the least-squares x then
    if (k > 2 && residual > 0.5 * residual_before) return;
    if (k >= options_.max_iterations) {
      throw IntegrationError(
          describe("the projection onto the constraints did not converge at t = " +
                   detail::to_text(t)),
          t);
    }
    residual_before = residual;
    sigma += beta_ * r;
  }
}

void AugmentedLagrangian::acceleration_at_start() {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const Eigen::VectorXd q = y().head(n), qdot = y().tail(n);
  evaluate_equations(t(), q, qdot, false);
  factor_tangent(t());
  // Gauss's principle: q̈ closest to M⁻¹ f in M's metric on A q̈ + b = 0 (M x* = f)
  project(t(), data_.forcing, data_.constraint_bias, qddot_);
  have_acceleration_ = true;
}

int AugmentedLagrangian::solve_positions(double t1, double h, const Eigen::VectorXd& q0,
                                         const Eigen::VectorXd& v0, const Eigen::VectorXd& a0,
                                         Eigen::VectorXd& q1) {
  const double h2 = 0.25 * h * h;
  double change_before = INFINITY;
  bool slow = false;
  Eigen::VectorXd qdot1, qddot1;
  for (int iteration = 0; iteration < options_.max_iterations; ++iteration) {
    // the trapezoidal rule's q̇₁ and q̈₁ from q₁
    qdot1 = (2.0 / h) * (q1 - q0) - v0;
    qddot1 = (1.0 / h2) * (q1 - q0) - (4.0 / h) * v0 - a0;
    evaluate_equations(t1, q1, qdot1, true);
    // the tangent of an earlier point no longer serves (A turns fast near a singular position)
    if (iteration == kRefactorAfter || (iteration > 0 && slow)) factor_tangent(t1);
    const Eigen::MatrixXd& A = data_.constraint_matrix;
    const Eigen::VectorXd& psi = data_.constraint_position;
    // μ += β Ψ at each iterate after the predictor, R = h²/4 (M q̈₁ − f) + Aᵀ (μ + β Ψ),
    // q₁ −= (M + β AᵀA)⁻¹ R
    if (iteration > 0 && A.rows() > 0) mu_ += beta_ * psi;
    Eigen::VectorXd R = h2 * (data_.mass_matrix * qddot1 - data_.forcing);
    if (A.rows() > 0) R += A.transpose() * (mu_ + beta_ * psi);
    const Eigen::VectorXd dq = tangent_.solve(R);
    q1 -= dq;
    const double change = max_norm(dq) / (1.0 + max_norm(q1));
    const bool rows_hold = max_norm(psi) <= options_.tolerance * (1.0 + max_norm(q1));
    if (rows_hold && change <= options_.tolerance) return iteration + 1;
    // round-off reached: the corrections no longer decrease
    if (rows_hold && iteration > 3 && change >= change_before && change < 1e-9) {
      return iteration + 1;
    }
    slow = change > 0.25 * change_before;
    change_before = change;
  }
  return -1;
}

bool AugmentedLagrangian::trapezoidal_step(double t1, double h, const Eigen::VectorXd& q0,
                                           const Eigen::VectorXd& v0, const Eigen::VectorXd& a0,
                                           Eigen::VectorXd& q1, Eigen::VectorXd& v1,
                                           Eigen::VectorXd& a1) {
  // the predictor q₀ + h q̇₀ + h²/2 q̈₀, then Newton's method
  q1 = q0 + h * v0 + 0.5 * h * h * a0;
  const int iterations = solve_positions(t1, h, q0, v0, a0, q1);
  if (iterations < 0) return false;
  most_iterations_ = std::max(most_iterations_, iterations);
  // q̇₁ onto A q̇ + e = 0, then q̈₁ onto A q̈ + b = 0, mass-orthogonally at q₁
  v1 = (2.0 / h) * (q1 - q0) - v0;
  a1 = (4.0 / (h * h)) * (q1 - q0) - (4.0 / h) * v0 - a0;
  evaluate_equations(t1, q1, v1, true);
  factor_tangent(t1);
  const Eigen::VectorXd e = data_.constraint_velocity_term;
  project(t1, data_.mass_matrix * v1, e, v1);
  evaluate_equations(t1, q1, v1, false);
  project(t1, data_.mass_matrix * a1, data_.constraint_bias, a1);
  return q1.allFinite() && v1.allFinite() && a1.allFinite();
}

void AugmentedLagrangian::step_or_halves(double t0, double t1, int depth, Eigen::VectorXd& q,
                                         Eigen::VectorXd& v, Eigen::VectorXd& a) {
  const Eigen::VectorXd mu = mu_;
  Eigen::VectorXd q1, v1, a1;
  std::string why = "Newton's method did not converge";
  try {
    if (trapezoidal_step(t1, t1 - t0, q, v, a, q1, v1, a1)) {
      q = q1;
      v = v1;
      a = a1;
      return;
    }
  } catch (const IntegrationError& e) {
    why = e.what();
  }
  if (depth >= kMostHalvings) {
    throw IntegrationError(
        describe(why + " at t = " + detail::to_text(t1) + " (with steps down to " +
                 detail::to_text(t1 - t0) + "); take a smaller step"),
        t1);
  }
  // from the start again, in two halves: the multipliers and the tangent of the start
  mu_ = mu;
  evaluate_equations(t0, q, v, false);
  factor_tangent(t0);
  const double t_half = t0 + 0.5 * (t1 - t0);
  step_or_halves(t0, t_half, depth + 1, q, v, a);
  step_or_halves(t_half, t1, depth + 1, q, v, a);
}

void AugmentedLagrangian::advance(double t_limit) {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const double t0 = t();
  const double t1 = fixed_step_toward(t_limit, options_.step).t_end;
  if (!have_acceleration_) acceleration_at_start();
  Eigen::VectorXd q = y().head(n), v = y().tail(n), a = qddot_;
  step_or_halves(t0, t1, 0, q, v, a);
  Eigen::VectorXd y1(2 * n);
  y1 << q, v;
  y_previous_ = y();
  qddot_previous_ = qddot_;
  accept_step(t1, y1);
  y_end_ = y();
  qddot_ = a;
  qddot_end_ = a;
}

void AugmentedLagrangian::interpolate(double t, Eigen::VectorXd& y_out) const {
  const auto n = static_cast<Eigen::Index>(system_.coordinate_count());
  const double h = this->t() - t_previous();
  // cubic Hermite: q with q̇ at both ends, q̇ with q̈
  const HermiteWeights w = cubic_hermite((t - t_previous()) / h, h);
  y_out.resize(2 * n);
  y_out.head(n) = w.h00 * y_previous_.head(n) + w.h01 * y_end_.head(n) +
                  w.h10 * y_previous_.tail(n) + w.h11 * y_end_.tail(n);
  y_out.tail(n) = w.h00 * y_previous_.tail(n) + w.h01 * y_end_.tail(n) + w.h10 * qddot_previous_ +
                  w.h11 * qddot_end_;
}

}  // namespace unidyn
