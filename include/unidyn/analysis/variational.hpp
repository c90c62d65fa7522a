// The alternative principles of book §4.11, evaluated on a compiled system: d'Alembert's virtual
// work, Gauss's least constraint and Hamilton's action — each a check on a motion found by the
// balance laws that does not use them.
//
//   (4.36) virtual work: Σ (F_K − m_K r̈_K) · d_K = dᵀ (f − M q̈) for a virtual displacement d; on
//          the true motion it is zero for every d with A d = 0 (4.37), and −λ · (A d) for others;
//   Gauss (1829): the true q̈ minimises the constraint Z(q̈) = ½ (q̈ − M⁻¹f)ᵀ M (q̈ − M⁻¹f) among
//          the q̈ with A q̈ + b = 0 — the Lagrange prescription's forces are the least ones;
//   (4.41) Hamilton: the true motion between fixed q(t0), q(t1) makes I = ∫ L dt, L = T − U,
//          stationary (holonomic constraints; not for non-integrable ones).
// Here M, f, A, b are those of CompiledSystem::solve (f: the generalised applied forces less the
// convective terms, so that M q̈ = f + Aᵀλ).
#pragma once

#include <Eigen/Dense>
#include <span>
#include <vector>

#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

// dᵀ (f − M q̈) at (t, q, q̇) for the accelerations q̈ and the displacement d.
double virtual_work(const CompiledSystem& compiled, std::span<const double> parameters, double t,
                    const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                    const Eigen::VectorXd& qddot, const Eigen::VectorXd& d);

// Gauss's Z(q̈) = ½ (q̈ − M⁻¹f)ᵀ M (q̈ − M⁻¹f) at (t, q, q̇).
double gauss_constraint(const CompiledSystem& compiled, std::span<const double> parameters,
                        double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                        const Eigen::VectorXd& qddot);

// A path q(t), q̇(t) sampled at equally spaced times t0 + k h, k = 0 .. 2N.
struct SampledPath {
  double t0 = 0.0, step = 0.0;
  std::vector<Eigen::VectorXd> q, qdot;
};

// L = T − U at (t, q, q̇) (the model's kinetic and potential energies).
double lagrangian(const CompiledSystem& compiled, std::span<const double> parameters, double t,
                  const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);

// (4.41) I = ∫ L dt along the path, by Simpson's rule (an odd number of samples, at least 3;
// std::invalid_argument otherwise).
double action_integral(const CompiledSystem& compiled, std::span<const double> parameters,
                       const SampledPath& path);

}  // namespace unidyn
