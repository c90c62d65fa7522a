// The constrained solve with rough contacts (equations/friction.hpp): a stuck contact adds rows
// t · (J q̈ + bias) = 0 along the tangents off its normals, a sliding one adds its friction
// λ_j d_j to the column of each of its normal rows, with d_j = −μ_d (N̂ · g_j) Jᵀ ĉ for the
// direction N̂ of the normal force N = Σ_j λ_j g_j, iterated until the solve's N points along N̂.
#include <cmath>
#include <stdexcept>

#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/numeric/number_text.hpp"

namespace unidyn {
namespace {

// An orthonormal basis of the span of the normals g_j (Gram–Schmidt in order; a g_j along the
// earlier ones adds nothing).
Eigen::Matrix3Xd orthonormal_span(const Eigen::Matrix3Xd& normals) {
  Eigen::Matrix3Xd basis(3, 0);
  for (Eigen::Index j = 0; j < normals.cols(); ++j) {
    Eigen::Vector3d v = normals.col(j);
    v -= basis * (basis.transpose() * v);
    if (v.norm() <= 1e-12 * normals.col(j).norm() || v.norm() == 0.0) continue;
    basis.conservativeResize(3, basis.cols() + 1);
    basis.col(basis.cols() - 1) = v.normalized();
  }
  return basis;
}

// Unit tangents off the normals' span: on a surface t1 = n × E_k with E_k the basis vector least
// along n, and t2 = n × t1; on a curve n1 × n2.
Eigen::Matrix3Xd tangents_off(const Eigen::Matrix3Xd& basis) {
  if (basis.cols() == 1) {
    const Eigen::Vector3d n = basis.col(0);
    Eigen::Index least = 0;
    n.cwiseAbs().minCoeff(&least);
    const Eigen::Vector3d t1 = n.cross(Eigen::Vector3d::Unit(least)).normalized();
    Eigen::Matrix3Xd t(3, 2);
    t << t1, n.cross(t1);
    return t;
  }
  if (basis.cols() == 2) return basis.col(0).cross(basis.col(1)).normalized();
  if (basis.cols() == 0) return Eigen::Matrix3d::Identity();
  return Eigen::Matrix3Xd(3, 0);
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

// The normal force's direction to assume: the last one found, moved onto the normals' span now
// (one normal: ±g/|g|, the sign of λ); the first normal's direction before any.
Eigen::Vector3d assumed_normal(const FrictionValues& f, const FrictionPhase& phase) {
  const Eigen::Vector3d along = f.normal_part(phase.normal_direction);
  if (along.norm() > 1e-3 * phase.normal_direction.norm() && along.norm() > 0) {
    return along.normalized();
  }
  return f.normals.col(0).normalized();
}

// Attempts at the normal force's direction before the solve gives up (one normal needs at most
// two: the sign of λ; on a curve the fixed point's error shrinks by about μ per attempt).
constexpr int normal_attempts = 64;

}  // namespace

void CompiledSystem::evaluate_friction(double t, StateRef q, StateRef qdot,
                                       std::span<const double> parameters,
                                       CompiledSystemData& data) const {
  const double* out = evaluate_at(friction_, t, q, qdot, parameters, data);
  const auto N = static_cast<Eigen::Index>(n_);
  for (std::size_t c = 0; c < data.friction.size(); ++c) {
    FrictionValues& f = data.friction[c];
    const auto normals = static_cast<Eigen::Index>(friction_rows_[c].size());
    f.jacobian =
        Eigen::Map<const Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::RowMajor>>(out, 3, N);
    out += 3 * n_;
    f.velocity_term = Eigen::Map<const Eigen::Vector3d>(out);
    f.acceleration_bias = Eigen::Map<const Eigen::Vector3d>(out + 3);
    f.normals = Eigen::Map<const Eigen::Matrix3Xd>(out + 6, 3, normals);
    out += 6 + 3 * normals;
    f.dynamic = out[0];
    f.static_coefficient = out[1];
    f.viscous = out[2];
    out += 3;
    f.normal_basis = orthonormal_span(f.normals);
    f.tangents = tangents_off(f.normal_basis);
    // v_rel = J q̇ + e, and its part along the surface or curve
    f.relative_velocity = f.jacobian * qdot + f.velocity_term;
    f.slip = f.tangential_part(f.relative_velocity);
  }
}

void CompiledSystem::solve_with_friction(double t, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                                         CompiledSystemData& data) const {
  const auto N = static_cast<Eigen::Index>(n_);
  const std::size_t contacts = friction_constraint_.size();
  // the rough contact of each constraint, and its normal's column there
  std::vector<std::pair<int, Eigen::Index>> contact_of(m_, {-1, 0});
  for (std::size_t c = 0; c < contacts; ++c) {
    for (std::size_t j = 0; j < friction_rows_[c].size(); ++j) {
      contact_of[friction_rows_[c][j]] = {int(c), Eigen::Index(j)};
    }
  }
  const auto holds = [&](std::size_t k) { return data.active.empty() || data.active[k]; };
  // a contact touches while its rough constraint holds; it slides unless stuck
  const auto touching = [&](std::size_t c) { return holds(friction_constraint_[c]); };
  const auto sliding = [&](std::size_t c) { return touching(c) && !data.friction_phase[c].stick; };
  // the viscous friction −c v_t of the sliding contacts, a force of the state alone
  for (std::size_t c = 0; c < contacts; ++c) {
    const FrictionValues& f = data.friction[c];
    if (sliding(c) && f.viscous != 0.0) data.forcing -= f.viscous * f.jacobian.transpose() * f.slip;
  }
  std::vector<Eigen::Vector3d> normal(contacts);
  for (std::size_t c = 0; c < contacts; ++c) {
    normal[c] = assumed_normal(data.friction[c], data.friction_phase[c]);
  }
  // Row r belongs to constraint `constraint`; a stick row of contact `contact` along `tangent`.
  struct Row {
    std::size_t constraint;
    int contact = -1;
    Eigen::Vector3d tangent = Eigen::Vector3d::Zero();
  };
  for (int attempt = 0; attempt < normal_attempts; ++attempt) {
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
      if (!touching(c) || !data.friction_phase[c].stick) continue;
      const FrictionValues& f = data.friction[c];
      for (Eigen::Index i = 0; i < f.tangents.cols(); ++i) {
        const Eigen::Vector3d tangent = f.tangents.col(i);
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
    // the columns: Aᵀ, plus d_j = −μ_d (N̂ · g_j) Jᵀ ĉ on a sliding contact's normal rows
    Eigen::MatrixXd C = A.transpose();
    for (Eigen::Index r = 0; r < R; ++r) {
      const Row& o = owner[std::size_t(r)];
      const auto [c, j] = contact_of[o.constraint];
      if (c < 0 || o.contact >= 0 || !sliding(std::size_t(c))) continue;
      const FrictionValues& f = data.friction[std::size_t(c)];
      C.col(r) -= f.dynamic * normal[std::size_t(c)].dot(f.normals.col(j)) *
                  f.jacobian.transpose() * slip_direction(f, data.friction_phase[std::size_t(c)]);
    }
    // solve_with factors M in place: a further attempt starts again from M
    if (attempt > 0) {
      Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          data.mass_factor.data(), N, N) = data.mass_matrix;
    }
    Eigen::VectorXd solved;
    solve_with(t, A, b, &C, qddot, solved, data);
    // one λ per constraint; each contact's force on its particle: Σ λ_j g_j + friction
    lambda = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(m_));
    std::vector<Eigen::Vector3d> normal_force(contacts, Eigen::Vector3d::Zero());
    for (std::size_t c = 0; c < contacts; ++c) data.contact_force[c].setZero();
    for (Eigen::Index r = 0; r < R; ++r) {
      const Row& o = owner[std::size_t(r)];
      if (o.contact >= 0) {
        data.contact_force[std::size_t(o.contact)] += solved[r] * o.tangent;  // stick friction
        continue;
      }
      lambda[static_cast<Eigen::Index>(o.constraint)] = solved[r];
      const auto [c, j] = contact_of[o.constraint];
      if (c >= 0)
        normal_force[std::size_t(c)] += solved[r] * data.friction[std::size_t(c)].normals.col(j);
    }
    // a sliding contact is solved when its normal force points along the N̂ assumed
    bool consistent = true;
    for (std::size_t c = 0; c < contacts; ++c) {
      const FrictionValues& f = data.friction[c];
      FrictionPhase& phase = data.friction_phase[c];
      data.contact_force[c] += normal_force[c];
      if (!sliding(c)) continue;
      data.contact_force[c] -=
          f.dynamic * normal[c].dot(normal_force[c]) * slip_direction(f, phase) +
          f.viscous * f.slip;
      const double size = normal_force[c].norm();
      if (!(size > 0)) continue;  // no normal force: no friction, whatever N̂
      const Eigen::Vector3d found = normal_force[c] / size;
      if ((found - normal[c]).norm() > 1e-13) consistent = false;
      normal[c] = found;
      phase.normal_direction = found;
    }
    if (consistent) return;
  }
  throw std::runtime_error(
      "the friction at t = " + detail::to_text(t) +
      " has no consistent normal force (the direction assumed for it is never the one solved for: "
      "a Painlevé-type paradox, or friction too large for the contact's geometry)");
}

}  // namespace unidyn
