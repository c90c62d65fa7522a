// The representative point of a system of particles (book §4.7, after Casey): one particle of mass
// m = Σ m_i moving in E^{3N} with the system's kinetic energy.
//
// With the fixed orthonormal basis ē_K of E^{3N} (K = 3(i − 1) + j for particle i and direction
// E_j), the scaled bases e_K = √(m_i/m) ē_K and e^K = √(m/m_i) ē_K (e_K · e^J = δ_K^J) give
//   (4.15) r = Σ_i Σ_j (r_i · E_j) e_K,   (4.16) Φ = Σ_i Σ_j (F_i · E_j) e^K,
// the coordinate bases a_K = ∂r/∂q^K and a^J = grad q^J = Σ (∂q^J/∂x_i^j) e^K (a_K · a^J = δ),
// and the metric a_JK = a_J · a_K of the line element ds² = a_JK dq^J dq^K, with
// T = (m/2) a_JK q̇^J q̇^K (§4.10, (4.27)).
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// A vector of E^{3N} by its components on ē_1 .. ē_3N.
using PointVector = std::vector<Expr>;

struct RepresentativePoint {
  Expr mass;                           // m = Σ m_i
  std::vector<Expr> scale;             // √(m_i/m) for each K: e_K = scale_K ē_K
  PointVector position;                // r (4.15)
  std::vector<PointVector> covariant;  // a_K = ∂r/∂q^K
  // a^J, when the coordinates are 3N and fix the particles one to one; else empty
  std::vector<PointVector> contravariant;
  GiNaC::matrix metric;  // a_JK
};

// The representative point of a system of particles (the positions may depend on t). Throws
// std::invalid_argument for a system with rigid bodies, which have no such point.
RepresentativePoint representative_point(const System& system);

// u · v in E^{3N}.
Expr dot(const PointVector& u, const PointVector& v);

}  // namespace unidyn
