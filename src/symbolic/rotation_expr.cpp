// Symbolic rotation tensors.
#include "unidyn/symbolic/rotation_expr.hpp"

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

TensorExpr identity_tensor_expr() {
  return GiNaC::ex_to<GiNaC::matrix>(GiNaC::unit_matrix(3));
}

TensorExpr elementary_rotation_expr(int i, const Expr& angle) {
  // (6.5) cos γ (I − E⊗E) − sin γ εE + E⊗E: on the cyclic pair (a, b) after i the 2×2 rotation
  TensorExpr L = identity_tensor_expr();
  const unsigned a = static_cast<unsigned>(i % 3), b = static_cast<unsigned>((i + 1) % 3);
  L(a, a) = GiNaC::cos(angle);
  L(b, b) = GiNaC::cos(angle);
  L(b, a) = GiNaC::sin(angle);
  L(a, b) = -GiNaC::sin(angle);
  return L;
}

TensorExpr euler_rotation_expr(const EulerSet& set, const Expr& first, const Expr& second,
                               const Expr& third) {
  return elementary_rotation_expr(set.first, first)
      .mul(elementary_rotation_expr(set.second, second))
      .mul(elementary_rotation_expr(set.third, third));
}

TensorExpr axis_angle_rotation_expr(const VectorExpr& r, const Expr& angle) {
  // (6.8) L(φ, r) = cos φ I + sin φ skew(r) + (1 − cos φ) r⊗r
  TensorExpr L(3, 3);
  const Expr c = GiNaC::cos(angle), s = GiNaC::sin(angle);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) {
      L(i, k) = (1 - c) * r[static_cast<int>(i)] * r[static_cast<int>(k)] + (i == k ? c : Expr(0));
    }
  }
  // skew(r) a = r × a
  L(0, 1) -= s * r[2];
  L(0, 2) += s * r[1];
  L(1, 0) += s * r[2];
  L(1, 2) -= s * r[0];
  L(2, 0) -= s * r[1];
  L(2, 1) += s * r[0];
  return L;
}

TensorExpr euler_parameter_rotation_expr(const Expr& e0, const VectorExpr& e) {
  // (6.36) ((e0² − e · e) I + 2 e⊗e + 2 e0 skew(e)) / (e0² + e · e): divided by the squared norm it
  // is a rotation for any (e0, e) ≠ 0, so ω = axial(Q̇ Qᵀ) is an angular velocity off the unit
  // sphere too (and the kinetic energy does not see the norm)
  TensorExpr Q(3, 3);
  const Expr d = e0 * e0 - dot(e, e);
  const Expr norm_squared = e0 * e0 + dot(e, e);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) {
      Q(i, k) = 2 * e[static_cast<int>(i)] * e[static_cast<int>(k)] + (i == k ? d : Expr(0));
    }
  }
  Q(0, 1) -= 2 * e0 * e[2];
  Q(0, 2) += 2 * e0 * e[1];
  Q(1, 0) += 2 * e0 * e[2];
  Q(1, 2) -= 2 * e0 * e[0];
  Q(2, 0) -= 2 * e0 * e[1];
  Q(2, 1) += 2 * e0 * e[0];
  return Q.mul_scalar(1 / norm_squared);
}

VectorExpr times(const TensorExpr& A, const VectorExpr& v) {
  VectorExpr out;
  for (unsigned i = 0; i < 3; ++i) {
    out[static_cast<int>(i)] = A(i, 0) * v[0] + A(i, 1) * v[1] + A(i, 2) * v[2];
  }
  return out;
}

VectorExpr column(const TensorExpr& A, int k) {
  const auto K = static_cast<unsigned>(k);
  return {A(0, K), A(1, K), A(2, K)};
}

TensorExpr transpose(const TensorExpr& A) {
  return A.transpose();
}

VectorExpr axial_expr(const TensorExpr& A) {
  // c = −½ ε[A], ε[A]_i = ε_ijk A_jk
  return {(A(2, 1) - A(1, 2)) / 2, (A(0, 2) - A(2, 0)) / 2, (A(1, 0) - A(0, 1)) / 2};
}

TensorExpr simplified(const TensorExpr& A) {
  TensorExpr out(3, 3);
  for (unsigned i = 0; i < 3; ++i) {
    for (unsigned k = 0; k < 3; ++k) out(i, k) = simplify(A(i, k));
  }
  return out;
}

VectorExpr simplified(const VectorExpr& v) {
  return {simplify(v[0]), simplify(v[1]), simplify(v[2])};
}

}  // namespace unidyn
