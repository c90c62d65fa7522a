// Dormand–Prince 5(4): stages, error estimate and dense output.
#include "unidyn/integrate/dormand_prince.hpp"

#include <cmath>
#include <utility>

#include "dormand_prince_tableau.hpp"

namespace unidyn {
namespace {

namespace dp = detail::dormand_prince;

}  // namespace

DormandPrince54::DormandPrince54(OdeFunction rhs, DormandPrinceOptions options)
    : EmbeddedRungeKutta(std::move(rhs), options) {}

bool DormandPrince54::attempt(double h, double t_new) {
  const double t0 = t();
  const Eigen::VectorXd& y0 = y();
  auto& k = k_;
  const Eigen::VectorXd& f0 = first_stage();
  // Stages 2–6 at t0 + c_i h; stage 6 at the step's end.
  stage_ = y0 + (h * dp::a21) * f0;
  t_bad_ = t0 + dp::c2 * h;
  if (!evaluate(t_bad_, stage_, k[1])) return false;
  stage_ = y0 + h * (dp::a31 * f0 + dp::a32 * k[1]);
  t_bad_ = t0 + dp::c3 * h;
  if (!evaluate(t_bad_, stage_, k[2])) return false;
  stage_ = y0 + h * (dp::a41 * f0 + dp::a42 * k[1] + dp::a43 * k[2]);
  t_bad_ = t0 + dp::c4 * h;
  if (!evaluate(t_bad_, stage_, k[3])) return false;
  stage_ = y0 + h * (dp::a51 * f0 + dp::a52 * k[1] + dp::a53 * k[2] + dp::a54 * k[3]);
  t_bad_ = t0 + dp::c5 * h;
  if (!evaluate(t_bad_, stage_, k[4])) return false;
  stage_ =
      y0 + h * (dp::a61 * f0 + dp::a62 * k[1] + dp::a63 * k[2] + dp::a64 * k[3] + dp::a65 * k[4]);
  t_bad_ = t_new;
  if (!evaluate(t_new, stage_, k[5])) return false;
  // The fifth-order solution, and its derivative: stage 7, the next step's first (FSAL).
  y_new_ =
      y0 + h * (dp::a71 * f0 + dp::a73 * k[2] + dp::a74 * k[3] + dp::a75 * k[4] + dp::a76 * k[5]);
  if (!y_new_.allFinite()) return false;
  return evaluate(t_new, y_new_, k[6]);
}

double DormandPrince54::error_norm(double h) {
  const auto& k = k_;
  const Eigen::VectorXd& f0 = first_stage();
  // err = h Σ e_i k_i, weighted by atol + rtol max(|y|, |y_new|)
  error_ = h * (dp::e1 * f0 + dp::e3 * k[2] + dp::e4 * k[3] + dp::e5 * k[4] + dp::e6 * k[5] +
                dp::e7 * k[6]);
  return std::sqrt((error_.array() / error_scale(y_new_)).square().mean());
}

// h ‖k7 − k6‖ / ‖y1 − ŷ‖: stages 6 and 7 are f at the step's end, at ŷ (stage 6's argument)
// and at y1 (Hairer's DOPRI5).
double DormandPrince54::stiffness_estimate(double h) const {
  const double apart = (y_new_ - stage_).squaredNorm();
  if (!(apart > 0.0)) return -1.0;
  return std::abs(h) * std::sqrt((k_[6] - k_[5]).squaredNorm() / apart);
}

void DormandPrince54::commit(double h, double t_new) {
  const auto& k = k_;
  const Eigen::VectorXd& f0 = first_stage();
  const Eigen::VectorXd& y0 = y();
  // Dense output (DOPRI5 CONTD5): r1 = y1 − y0, r2 = h k1 − r1, r3 = r1 − h k7 − r2, r4 = h Σ d_i
  // k_i.
  r_[0] = y_new_ - y0;
  r_[1] = h * f0 - r_[0];
  r_[2] = r_[0] - h * k[6] - r_[1];
  r_[3] = h * (dp::d1 * f0 + dp::d3 * k[2] + dp::d4 * k[3] + dp::d5 * k[4] + dp::d6 * k[5] +
               dp::d7 * k[6]);
  // First same as last: f(t_new, y_new) is the next step's first stage.
  exchange_first_stage(k_[6]);
  accept_step(t_new, y_new_);
  y_previous_.swap(y_new_);
}

void DormandPrince54::interpolate(double t, Eigen::VectorXd& y_out) const {
  const double theta = (t - t_previous()) / (this->t() - t_previous());
  const double one_minus = 1.0 - theta;
  // y(t_prev + θh) = y_prev + θ(r1 + (1−θ)(r2 + θ(r3 + (1−θ) r4)))
  y_out = y_previous_ + theta * (r_[0] + one_minus * (r_[1] + theta * (r_[2] + one_minus * r_[3])));
}

}  // namespace unidyn
