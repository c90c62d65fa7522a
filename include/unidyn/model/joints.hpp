// Joints between two bodies, or between a body and the ground (book §8.6, (8.19)–(8.24)).
//
// A joint is a set of integrable constraints, each given with its Lagrange representation
// (8.22): a row Ψ_k whose velocity form is Σ_B (f_kB · v̄_B + h_kB · ω_B) = 0, so that with the
// multiplier μ_k it exerts F_c = Σ_k μ_k f_kB and M_c = Σ_k μ_k h_kB (about x̄_B) on body B.
//
// Ball joint (a common point P; a fixed point when the second end is the ground), k = 1, 2, 3:
//   Ψ_k = (x_P1 − x_P2) · E_k,   x_Pα = x̄_α + Q_α X_α = x̄_α + π_Pα
//   Ψ̇_k = (v̄_1 + ω_1 × π_P1 − v̄_2 − ω_2 × π_P2) · E_k                                 (8.23)
//   f_k1 = E_k,  h_k1 = π_P1 × E_k;   f_k2 = −E_k,  h_k2 = −π_P2 × E_k
// so F_c1 = Σ μ_k E_k = −F_c2 and M_cα = π_Pα × F_cα: the third law (8.24).
//
// Pin (a ball joint whose axes a_1 = Q_1 A_1 and a_2 = Q_2 A_2 stay together; a fixed axis when the
// second end is the ground), two more rows with b_j = Q_2 B_j, {A_2, B_1, B_2} orthonormal:
//   Ψ_3+j = a_1 · b_j
//   Ψ̇_3+j = (ω_1 × a_1) · b_j + a_1 · (ω_2 × b_j) = (ω_1 − ω_2) · (a_1 × b_j)             (8.23)
//   f = 0,  h_1 = a_1 × b_j = −h_2
// so the reaction moment M_r = Σ_j μ_3+j a_1 × b_j is perpendicular to the axis and acts equal
// and opposite on the two bodies: M_c1 = M_r + π_P1 × F_c1, M_c2 = −M_r + π_P2 × F_c2 (8.24).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// One side of a joint: a body with the point X_α and axis A_α in components on its basis e_k
// (from its centre of mass), or the ground (no body) with a fixed point and a fixed direction.
struct JointEnd {
  std::optional<std::size_t> body;
  VectorExpr point;
  VectorExpr axis;  // a unit vector of numbers; used by a pin only
};

// The rows of a ball joint named `name`: constraints name_1 .. name_3.
std::vector<Constraint> ball_joint(const System& system, const std::string& name,
                                   const JointEnd& first, const JointEnd& second,
                                   const SourcePosition& where);

// Rolling without slip of body B on a fixed surface with normal n at the point of contact x_P
// (book §8.6, (8.21), (10.27)): the velocity rows name_1, name_2
//   (v̄ + ω × (x_P − x̄)) · t_j = 0,   t_j ⊥ n,
// with f = t_j and h = (x_P − x̄) × t_j (8.22): the friction force at P and its moment. The normal
// contact is a position constraint of its own. n is a vector of numbers (a plane: t_j complete
// n/‖n‖ to an orthonormal triad) or an expression of the coordinates perpendicular to a basis
// vector E_k throughout (a cylinder about E_k, e.g. rolling inside a pipe: t_1 = E_k,
// t_2 = n × E_k/‖n‖). Throws std::invalid_argument for any other normal.
std::vector<Constraint> rolling_contact(const System& system, const std::string& name,
                                        std::size_t body, const VectorExpr& contact,
                                        const VectorExpr& normal, const SourcePosition& where);

// The rows of a pin: name_1 .. name_3 for the common point, name_4, name_5 for the common axis.
// Throws std::invalid_argument when an axis is not a non-zero vector of numbers.
std::vector<Constraint> pin_joint(const System& system, const std::string& name,
                                  const JointEnd& first, const JointEnd& second,
                                  const SourcePosition& where);

}  // namespace unidyn
