// The Dormand–Prince 8(5,3) explicit Runge–Kutta pair (DOP853) with step-size control and a
// seventh-order dense output: the method for tight tolerances.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string_view>

#include "unidyn/integrate/embedded_runge_kutta.hpp"

namespace unidyn {

// Hairer's DOP853 (HNW I, §II.10 and its appendix): the eighth-order RK8(7)13M stages of Prince &
// Dormand (1981), "High order embedded Runge–Kutta formulae", J. Comput. Appl. Math. 7, 67–75,
// with an error estimate combining a fifth- and a third-order embedded solution,
// err = err5² / sqrt(err5² + 0.01 err3²), 12 evaluations per step (first same as last). The
// seventh-order continuous extension needs 3 more, evaluated only in steps where dense() is called.
class DormandPrince853 final : public EmbeddedRungeKutta {
 public:
  // Throws std::invalid_argument for inconsistent options.
  explicit DormandPrince853(OdeFunction rhs,
                            DormandPrinceOptions options = DormandPrinceOptions::dop853());

  std::string_view name() const override { return "dop853"; }

 private:
  int order() const override { return 8; }
  double controller_exponent(double beta) const override { return 1.0 / 8.0 - 0.2 * beta; }
  bool attempt(double h, double t_new) override;
  double error_norm(double h) override;
  void commit(double h, double t_new) override;
  void prepare_dense() override;
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // Stages k_1 … k_16 (k_[0] a copy of the first stage, k_[12] = f(t_new, y_new)).
  std::array<Eigen::VectorXd, 16> k_;
  // Σ b_i k_i of the last attempt (y_new = y + h Σ b_i k_i), a stage's state, the new state.
  Eigen::VectorXd slope_, stage_, y_new_;
  // Dense output of the last step, from y_previous_ over h_last_: y(t_prev + θh) = y_prev +
  // θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ)(r4 + θ(r5 + (1−θ)(r6 + θ r7)))))); r4 … r7 need the extra
  // stages and are filled by prepare_dense() (dense_ready_).
  Eigen::VectorXd y_previous_;
  std::array<Eigen::VectorXd, 7> r_;
  double h_last_ = 0.0;
  bool dense_ready_ = false;
};

}  // namespace unidyn
