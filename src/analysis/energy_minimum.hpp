// Energy methods for the stability of an equilibrium or a steady motion (analysis/equilibria.cpp).
//
// Lagrange–Dirichlet: at rest, with forces from a potential U (the balance's stiffness K symmetric)
// and no velocity constraints, K restricted to the constraints' tangent (δq = P ξ, Ψ_q P = 0) is
// U's Hessian there (the multipliers' part Pᵀ A_qᵀλ P included); positive definite means a strict
// minimum of U on the constraints: stable.
//
// Routh: with cyclic coordinates s (the equations do not depend on them, the linearisation found
// them ignorable) and the other rates 0, their momenta p_s = ∂T/∂ṡ are conserved, and the motion of
// the rest r is that of a system with the amended potential V_p(r) = U + ½ pᵀ M_ss⁻¹ p. Its
// gradient is the balance E_r = −(f + Aᵀλ)_r at the rates ṡ(r) that keep p, so its Hessian is
//   K_rr + C_rs dṡ/dr,   dṡ/dr = −M_ss⁻¹ ∂p_s/∂r      (C = ∂E/∂q̇, ∂p_s/∂ṡ = M_ss),
// and positive definite on the constraints means a strict minimum of V_p: stable for
// perturbations that keep the momenta, and the steady motions near it for those that do not
// (Routh's theorem; gyroscopic terms do not enter it).
#pragma once

#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "unidyn/analysis/linearization.hpp"

namespace unidyn {

// Whether the (amended) potential has a strict minimum on the constraints at the point; nothing
// where neither method applies: velocity constraints, a rate of a coordinate that is not cyclic,
// a cyclic coordinate the linearisation did not find ignorable, or a Hessian that is not symmetric
// (forces without a potential). momentum_q: ∂p_s/∂q, one row per cyclic coordinate.
std::optional<bool> energy_minimum(const Linearization& linearization, const OperatingPoint& point,
                                   const std::vector<Eigen::Index>& cyclic,
                                   const Eigen::MatrixXd& momentum_q);

}  // namespace unidyn
