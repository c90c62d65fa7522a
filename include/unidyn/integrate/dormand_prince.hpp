// The Dormand–Prince 5(4) explicit Runge–Kutta pair with step-size control and dense output.
#pragma once

#include <Eigen/Core>
#include <array>
#include <string_view>

#include "unidyn/integrate/embedded_runge_kutta.hpp"

namespace unidyn {

// The RK5(4)7M pair of Dormand & Prince (1980), "A family of embedded Runge–Kutta formulae",
// J. Comput. Appl. Math. 6, 19–26, as in HNW I, §II.5, Table 5.2: fifth-order solution,
// fourth-order error estimate, first-same-as-last (6 evaluations per step). Dense output is the
// fourth-order continuous extension of Shampine (1986) used by Hairer's DOPRI5 (HNW I, §II.6).
class DormandPrince54 final : public EmbeddedRungeKutta {
 public:
  // Throws std::invalid_argument for inconsistent options.
  explicit DormandPrince54(OdeFunction rhs, DormandPrinceOptions options = {});

  std::string_view name() const override { return "dopri5"; }

 private:
  int order() const override { return 5; }
  double controller_exponent(double beta) const override { return 0.2 - 0.75 * beta; }
  bool attempt(double h, double t_new) override;
  double error_norm(double h) override;
  void commit(double h, double t_new) override;
  double stiffness_estimate(double h) const override;
  // DOPRI5's stability region reaches −3.3 on the negative axis; Hairer's test uses 3.25
  double stability_bound() const override { return 3.25; }
  void interpolate(double t, Eigen::VectorXd& y_out) const override;

  // Stages 2–7 in k_[1..6] (the first is first_stage(): first same as last).
  std::array<Eigen::VectorXd, 7> k_;
  Eigen::VectorXd stage_, y_new_, error_;
  // Dense output of the last step: y(t_prev + θh) = y_prev + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ) r4))).
  Eigen::VectorXd y_previous_;
  std::array<Eigen::VectorXd, 4> r_;
};

}  // namespace unidyn
