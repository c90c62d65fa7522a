// Rotation tensors with symbolic entries (book Ch. 6 applied to bodies, Ch. 7): components
// Q_ik = E_i · Q E_k as a 3×3 GiNaC::matrix.
#pragma once

#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

using TensorExpr = GiNaC::matrix;

TensorExpr identity_tensor_expr();
// (6.5) L(γ, E_i), i = 1, 2, 3
TensorExpr elementary_rotation_expr(int i, const Expr& angle);
// (6.20) R_I(γ¹) R_J(γ²) R_K(γ³)
TensorExpr euler_rotation_expr(const EulerSet& set, const Expr& first, const Expr& second,
                               const Expr& third);
// (6.8) L(φ, r) for a unit axis r
TensorExpr axis_angle_rotation_expr(const VectorExpr& axis, const Expr& angle);
// (6.36) from Euler parameters (e0, e), divided by e0² + e · e (a rotation for any (e0, e) ≠ 0)
TensorExpr euler_parameter_rotation_expr(const Expr& e0, const VectorExpr& e);

VectorExpr times(const TensorExpr& A, const VectorExpr& v);
VectorExpr column(const TensorExpr& A, int k);
TensorExpr transpose(const TensorExpr& A);
// c = −½ ε[A]: the axial vector of the skew part of A
VectorExpr axial_expr(const TensorExpr& A);
// Every entry simplified (sin² + cos² = 1 and the like)
TensorExpr simplified(const TensorExpr& A);
VectorExpr simplified(const VectorExpr& v);

}  // namespace unidyn
