// The kinetic energy as a quadratic form in the rates (book (3.4)–(3.5), §4.6):
//   T = ½ Σ M_ik q̇^i q̇^k + Σ b_i q̇^i + T0 = T2 + T1 + T0,
// M_ik = Σ_P m_P ∂r_P/∂q^i · ∂r_P/∂q^k, b_i = Σ_P m_P ∂r_P/∂q^i · ∂r_P/∂t, T0 = ½ Σ_P m_P
// ‖∂r_P/∂t‖²; a body adds, with a_i = ∂x̄/∂q^i, g_i = ∂ω/∂q̇^i and ω_t = ω at q̇ = 0 (Koenig,
// (10.12)), M_ik += m a_i · a_k + g_i · J g_k, b_i += m a_i · ∂x̄/∂t + g_i · J ω_t, T0 += ½ m
// ‖∂x̄/∂t‖² + ½ ω_t · J ω_t. T1 and T0 are zero unless the positions or rotations depend on time
// (rheonomic systems).
#pragma once

#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

struct KineticEnergyForm {
  ExprMatrix mass_matrix;
  std::vector<Expr> linear;
  Expr constant;
};

KineticEnergyForm kinetic_energy_form(const System& system);

}  // namespace unidyn
