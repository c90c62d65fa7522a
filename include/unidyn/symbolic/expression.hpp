// Symbolic scalars and vectors on GiNaC (book Ch. 1, 3): the building blocks of derived equations.
//
// A scalar is a GiNaC::ex in the coordinates q, their rates der(q), accelerations, time t and the
// model's parameters. A vector is three scalars: its components on the fixed basis {E1, E2, E3}.
#pragma once

#include <ginac/ginac.h>

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

namespace unidyn {

using Expr = GiNaC::ex;

// GiNaC's hash of an expression, for containers keyed by expressions (with GiNaC::ex_is_equal).
struct ExprHash {
  std::size_t operator()(const Expr& x) const { return x.gethash(); }
};

struct VectorExpr {
  std::array<Expr, 3> c{0, 0, 0};

  VectorExpr() = default;
  VectorExpr(Expr x, Expr y, Expr z) : c{x, y, z} {}

  const Expr& operator[](int i) const { return c[static_cast<std::size_t>(i)]; }
  Expr& operator[](int i) { return c[static_cast<std::size_t>(i)]; }
};

// A rows × cols array of expressions, row-major.
struct ExprMatrix {
  std::size_t rows = 0;
  std::size_t cols = 0;
  std::vector<Expr> data;

  ExprMatrix() = default;
  ExprMatrix(std::size_t r, std::size_t c) : rows(r), cols(c), data(r * c, Expr(0)) {}
  Expr& operator()(std::size_t i, std::size_t j) { return data[i * cols + j]; }
  const Expr& operator()(std::size_t i, std::size_t j) const { return data[i * cols + j]; }
};

VectorExpr operator+(const VectorExpr& a, const VectorExpr& b);
VectorExpr operator-(const VectorExpr& a, const VectorExpr& b);
VectorExpr operator-(const VectorExpr& a);
VectorExpr operator*(const Expr& s, const VectorExpr& a);
VectorExpr operator*(const VectorExpr& a, const Expr& s);
VectorExpr operator/(const VectorExpr& a, const Expr& s);
Expr dot(const VectorExpr& a, const VectorExpr& b);
VectorExpr cross(const VectorExpr& a, const VectorExpr& b);
Expr norm(const VectorExpr& a);

// ∂a/∂x componentwise.
VectorExpr diff(const VectorExpr& a, const GiNaC::symbol& x);
// Substitution componentwise.
VectorExpr subs(const VectorExpr& a, const GiNaC::exmap& map);
// Fixed basis vector E_i, i = 1, 2, 3.
VectorExpr basis_vector_expr(int i);

// The sum of the terms made at once (adding them one by one copies the growing sum each time).
Expr sum_of(const std::vector<Expr>& terms);

// Where something is in a model file: "file:line:column" (1-based; 0 means unknown).
struct SourcePosition {
  std::string file;
  int line = 0;
  int column = 0;

  std::string str() const;
  // The position `offset` characters further along the same line.
  SourcePosition advanced(int offset) const { return {file, line, column + offset}; }
};

// A mistake in a model: carries where it is, and prints as "file:line:column: message".
class ModelError : public std::runtime_error {
 public:
  ModelError(SourcePosition where, const std::string& message);
  const SourcePosition& where() const { return where_; }
  const std::string& message() const { return message_; }

 private:
  SourcePosition where_;
  std::string message_;
};

}  // namespace unidyn
