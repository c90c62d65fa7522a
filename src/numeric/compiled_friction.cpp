// The constrained solve with rough contacts (equations/friction.hpp): a stuck contact adds rows
// t · (J q̈ + bias) = 0 along the surface's tangents, a sliding one adds its friction λ d to the
// column of its normal row.
#include <array>
#include <cmath>

#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

void CompiledSystem::evaluate_friction(double t, StateRef q, StateRef qdot,
                                       std::span<const double> parameters,
                                       CompiledSystemData& data) const {
  const double* out = evaluate_at(friction_, t, q, qdot, parameters, data);
  const auto N = static_cast<Eigen::Index>(n_);
  for (FrictionValues& f : data.friction) {
    f.jacobian =
        Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>>(out, 3, N);
    out += 3 * n_;
    f.velocity_term = Eigen::Map<const Eigen::Vector3d>(out);
    f.acceleration_bias = Eigen::Map<const Eigen::Vector3d>(out + 3);
    f.normal = Eigen::Map<const Eigen::Vector3d>(out + 6);
    f.dynamic = out[9];
    f.static_coefficient = out[10];
    out += 11;
    // v_rel = J q̇ + e, and its part along the surface
    f.relative_velocity = f.jacobian * qdot + f.velocity_term;
    const Eigen::Vector3d n = f.normal.normalized();
    f.slip = f.relative_velocity - n.dot(f.relative_velocity) * n;
  }
}

namespace {

// Two unit tangents of the surface with normal g: t1 from the basis vector least along g.
std::array<Eigen::Vector3d, 2> tangents(const Eigen::Vector3d& g) {
  const Eigen::Vector3d n = g.normalized();
  Eigen::Index least = 0;
  n.cwiseAbs().minCoeff(&least);
  const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::Unit(least)).normalized();
  return {t1, n.cross(t1)};
}

// The slip direction ĉ: of the slip velocity while it points the phase's way; else the phase's
// own (the slip is too slow to give one, or a trial state lies past the stop that ends the
// phase, where friction must keep its direction for the solution to stay smooth).
Eigen::Vector3d slip_direction(const FrictionValues& f, const FrictionPhase& phase) {
  const double speed = f.slip.norm();
  if (speed > 1e-12 * (1.0 + f.relative_velocity.norm()) && f.slip.dot(phase.direction) > 0) {
    return f.slip / speed;
  }
  return phase.direction;
}

}  // namespace

void CompiledSystem::solve_with_friction(double t, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                                         CompiledSystemData& data) const {
  const auto N = static_cast<Eigen::Index>(n_);
  const std::size_t contacts = friction_constraint_.size();
  std::vector<int> contact_of(m_, -1);  // the rough contact of each constraint
  for (std::size_t c = 0; c < contacts; ++c) contact_of[friction_constraint_[c]] = int(c);
  const auto holds = [&](std::size_t k) { return data.active.empty() || data.active[k]; };
  // Row r belongs to constraint `constraint`; a stick row of contact `contact` along `tangent`.
  struct Row {
    std::size_t constraint;
    int contact = -1;
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  };
  for (int attempt = 0; attempt < 2; ++attempt) {
    std::vector<Row> owner;
    std::vector<Eigen::RowVectorXd> rows;
    std::vector<double> bias;
    for (std::size_t k = 0; k < m_; ++k) {
      if (!holds(k)) continue;
      owner.push_back({k});
      rows.push_back(data.constraint_matrix.row(static_cast<Eigen::Index>(k)));
      bias.push_back(data.constraint_bias[static_cast<Eigen::Index>(k)]);
    }
    // a stuck contact adds t · (J q̈ + bias) = 0 along each tangent that no other row constrains
    for (std::size_t c = 0; c < contacts; ++c) {
      if (!holds(friction_constraint_[c]) || !data.friction_phase[c].stick) continue;
      const FrictionValues& f = data.friction[c];
      for (const Eigen::Vector3d& tangent : tangents(f.normal)) {
        const Eigen::RowVectorXd row = tangent.transpose() * f.jacobian;
        Eigen::MatrixXd others(static_cast<Eigen::Index>(rows.size()), N);
        for (std::size_t r = 0; r < rows.size(); ++r) others.row(Eigen::Index(r)) = rows[r];
        const Eigen::RowVectorXd residual =
            row -
            (others.transpose().colPivHouseholderQr().solve(row.transpose())).transpose() * others;
        if (residual.norm() <= 1e-9 * row.norm()) continue;  // another constraint holds it
        owner.push_back({friction_constraint_[c], int(c), tangent});
        rows.push_back(row);
        bias.push_back(tangent.dot(f.acceleration_bias));
      }
    }
    const auto R = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd A(R, N);
    Eigen::VectorXd b(R);
    for (Eigen::Index r = 0; r < R; ++r) {
      A.row(r) = rows[std::size_t(r)];
      b[r] = bias[std::size_t(r)];
    }
    // the columns: Aᵀ, plus d = −μ_d sign(λ) |g| Jᵀ ĉ on a sliding contact's normal row
    Eigen::MatrixXd C = A.transpose();
    for (Eigen::Index r = 0; r < R; ++r) {
      const Row& o = owner[std::size_t(r)];
      const int c = contact_of[o.constraint];
      if (c < 0 || o.contact >= 0 || data.friction_phase[std::size_t(c)].stick) continue;
      const FrictionValues& f = data.friction[std::size_t(c)];
      const FrictionPhase& phase = data.friction_phase[std::size_t(c)];
      C.col(r) += -f.dynamic * phase.sign * f.normal.norm() * f.jacobian.transpose() *
                  slip_direction(f, phase);
    }
    Eigen::VectorXd solved;
    solve_with(t, A, b, &C, qddot, solved, data);
    // one λ per constraint; each contact's force on its particle: λ g + friction
    lambda = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_));
    for (std::size_t c = 0; c < contacts; ++c) data.contact_force[c].setZero();
    bool consistent = true;
    for (Eigen::Index r = 0; r < R; ++r) {
      const Row& o = owner[std::size_t(r)];
      const int c = contact_of[o.constraint];
      if (o.contact >= 0) {
        data.contact_force[std::size_t(o.contact)] += solved[r] * o.tangent;  // stick friction
        continue;
      }
      lambda[static_cast<Eigen::Index>(o.constraint)] = solved[r];
      if (c < 0) continue;
      const FrictionValues& f = data.friction[std::size_t(c)];
      FrictionPhase& phase = data.friction_phase[std::size_t(c)];
      data.contact_force[std::size_t(c)] += solved[r] * f.normal;
      if (phase.stick) continue;
      data.contact_force[std::size_t(c)] -=
          f.dynamic * std::abs(solved[r]) * f.normal.norm() * slip_direction(f, phase);
      if (solved[r] * phase.sign < 0) {
        phase.sign = -phase.sign;  // |λ| = sign λ was assumed wrongly: solve again
        consistent = false;
      }
    }
    if (consistent) return;
  }
}

}  // namespace unidyn
