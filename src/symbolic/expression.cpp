// Symbolic vectors and model-file positions.
#include "unidyn/symbolic/expression.hpp"

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printable_text.hpp"

namespace unidyn {

VectorExpr operator+(const VectorExpr& a, const VectorExpr& b) {
  return {a[0] + b[0], a[1] + b[1], a[2] + b[2]};
}

VectorExpr operator-(const VectorExpr& a, const VectorExpr& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

VectorExpr operator-(const VectorExpr& a) {
  return {-a[0], -a[1], -a[2]};
}

VectorExpr operator*(const Expr& s, const VectorExpr& a) {
  return {s * a[0], s * a[1], s * a[2]};
}

VectorExpr operator*(const VectorExpr& a, const Expr& s) {
  return s * a;
}

VectorExpr operator/(const VectorExpr& a, const Expr& s) {
  return {a[0] / s, a[1] / s, a[2] / s};
}

Expr dot(const VectorExpr& a, const VectorExpr& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

VectorExpr cross(const VectorExpr& a, const VectorExpr& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

Expr norm(const VectorExpr& a) {
  return GiNaC::sqrt(dot(a, a));
}

VectorExpr diff(const VectorExpr& a, const GiNaC::symbol& x) {
  return {derivative(a[0], x), derivative(a[1], x), derivative(a[2], x)};
}

VectorExpr subs(const VectorExpr& a, const GiNaC::exmap& map) {
  return {a[0].subs(map), a[1].subs(map), a[2].subs(map)};
}

VectorExpr basis_vector_expr(int i) {
  VectorExpr e;
  e[i - 1] = 1;
  return e;
}

std::string SourcePosition::str() const {
  std::string s = file.empty() ? "<input>" : file;
  if (line > 0) {
    s += ":" + std::to_string(line);
    if (column > 0) s += ":" + std::to_string(column);
  }
  return s;
}

// The message quotes what the user typed: control characters are escaped (one line, no terminal
// escape sequences).
ModelError::ModelError(SourcePosition where, const std::string& message)
    : std::runtime_error(printable(where.str() + ": " + message)),
      where_(std::move(where)),
      message_(message) {}

Expr sum_of(const std::vector<Expr>& terms) {
  return GiNaC::dynallocate<GiNaC::add>(terms);
}

}  // namespace unidyn
