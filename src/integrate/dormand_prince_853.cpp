// Dormand–Prince 8(5,3): stages, the combined error estimate and the seventh-order dense output.
#include "unidyn/integrate/dormand_prince_853.hpp"

#include <cmath>
#include <cstddef>
#include <utility>

#include "dormand_prince_853_tableau.hpp"

namespace unidyn {
namespace {

namespace dop = detail::dop853;
using Stages = std::array<Eigen::VectorXd, 16>;

// Σ_j a_j k_j over a row of the tableau, at component i.
template <std::size_t N>
double row_sum(const dop::Term (&row)[N], const Stages& k, Eigen::Index i) {
  double sum = 0.0;
  for (const dop::Term& term : row) sum += term.coefficient * k[term.stage][i];
  return sum;
}

// out = y0 + h Σ_j a_j k_j
template <std::size_t N>
void stage_state(const dop::Term (&row)[N], const Eigen::VectorXd& y0, double h, const Stages& k,
                 Eigen::VectorXd& out) {
  out.resize(y0.size());
  for (Eigen::Index i = 0; i < y0.size(); ++i) out[i] = y0[i] + h * row_sum(row, k, i);
}

// out = h Σ_j d_j k_j
template <std::size_t N>
void scaled_sum(const dop::Term (&row)[N], double h, const Stages& k, Eigen::VectorXd& out) {
  out.resize(k[0].size());
  for (Eigen::Index i = 0; i < out.size(); ++i) out[i] = h * row_sum(row, k, i);
}

}  // namespace

DormandPrince853::DormandPrince853(OdeFunction rhs, DormandPrinceOptions options)
    : EmbeddedRungeKutta(std::move(rhs), options) {}

bool DormandPrince853::attempt(double h, double t_new) {
  const double t0 = t();
  const Eigen::VectorXd& y0 = y();
  auto& k = k_;
  k[0] = first_stage();
  // k_i = f(t0 + c_i h, y0 + h Σ a_ij k_j), i = 2 … 12; stage 12 at the step's end.
  const auto stage = [&](const auto& row, int i) {
    stage_state(row, y0, h, k, stage_);
    t_bad_ = i == 11 ? t_new : t0 + dop::c[static_cast<std::size_t>(i)] * h;
    return evaluate(t_bad_, stage_, k[static_cast<std::size_t>(i)]);
  };
  if (!(stage(dop::a2, 1) && stage(dop::a3, 2) && stage(dop::a4, 3) && stage(dop::a5, 4) &&
        stage(dop::a6, 5) && stage(dop::a7, 6) && stage(dop::a8, 7) && stage(dop::a9, 8) &&
        stage(dop::a10, 9) && stage(dop::a11, 10) && stage(dop::a12, 11))) {
    return false;
  }
  // The eighth-order solution y0 + h Σ b_i k_i, and its derivative k_13 (the next first stage).
  scaled_sum(dop::b, 1.0, k, slope_);
  y_new_ = y0 + h * slope_;
  t_bad_ = t_new;
  if (!y_new_.allFinite()) return false;
  return evaluate(t_new, y_new_, k[12]);
}

double DormandPrince853::error_norm(double h) {
  const auto& k = k_;
  const Eigen::ArrayXd& scale = error_scale(y_new_);
  // Σ (err5_i / sk_i)² and Σ (err3_i / sk_i)², without the factor h.
  double sum5 = 0.0, sum3 = 0.0;
  for (Eigen::Index i = 0; i < scale.size(); ++i) {
    const double e5 = row_sum(dop::e5, k, i) / scale[i];
    const double e3 = (slope_[i] - row_sum(dop::b3, k, i)) / scale[i];
    sum5 += e5 * e5;
    sum3 += e3 * e3;
  }
  // err = |h| err5² / sqrt(n (err5² + 0.01 err3²)): fifth order where err5 dominates, and kept
  // from being too optimistic by the third-order estimate (HNW I, §II.10).
  double denominator = sum5 + 0.01 * sum3;
  if (denominator <= 0.0) denominator = 1.0;
  return std::abs(h) * sum5 / std::sqrt(double(scale.size()) * denominator);
}

void DormandPrince853::commit(double h, double t_new) {
  const auto& k = k_;
  const Eigen::VectorXd& y0 = y();
  // The part of the dense output that needs no extra stage: r1 = y1 − y0, r2 = h k1 − r1,
  // r3 = r1 − h k13 − r2.
  r_[0] = y_new_ - y0;
  r_[1] = h * k[0] - r_[0];
  r_[2] = r_[0] - h * k[12] - r_[1];
  h_last_ = h;
  dense_ready_ = false;
  // First same as last: f(t_new, y_new) is the next step's first stage (k_[12] keeps a copy for
  // the dense output).
  stage_ = k[12];
  exchange_first_stage(stage_);
  accept_step(t_new, y_new_);
  y_previous_.swap(y_new_);
}

void DormandPrince853::prepare_dense() {
  if (dense_ready_) return;
  auto& k = k_;
  const double h = h_last_;
  const double t0 = t_previous();
  // The extra stages k_14, k_15, k_16 from the step's start; a non-finite one ends the integration.
  stage_state(dop::a14, y_previous_, h, k, stage_);
  evaluate_finite(t0 + dop::c[13] * h, stage_, k[13]);
  stage_state(dop::a15, y_previous_, h, k, stage_);
  evaluate_finite(t0 + dop::c[14] * h, stage_, k[14]);
  stage_state(dop::a16, y_previous_, h, k, stage_);
  evaluate_finite(t0 + dop::c[15] * h, stage_, k[15]);
  // r4 … r7 = h Σ d_i k_i
  scaled_sum(dop::d4, h, k, r_[3]);
  scaled_sum(dop::d5, h, k, r_[4]);
  scaled_sum(dop::d6, h, k, r_[5]);
  scaled_sum(dop::d7, h, k, r_[6]);
  dense_ready_ = true;
}

void DormandPrince853::interpolate(double t, Eigen::VectorXd& y_out) const {
  const double s = (t - t_previous()) / (this->t() - t_previous());
  const double s1 = 1.0 - s;
  const auto& r = r_;
  // (HNW I, §II.6) the continuous extension in Hairer's nested form
  y_out = y_previous_ +
          s * (r[0] + s1 * (r[1] + s * (r[2] + s1 * (r[3] + s * (r[4] + s1 * (r[5] + s * r[6]))))));
}

}  // namespace unidyn
