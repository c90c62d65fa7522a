// The expression language of model files (DESIGN.md, "Model file (YAML)"): text → GiNaC.
//
// A safe recursive-descent parser that evaluates as it parses, straight to GiNaC: nothing a model
// file says is ever executed. Scalars: numbers (exact rationals: 0.05 → 1/20, 1e-3 → 1/1000), names
// and dotted names from a Scope, der(q), pi, + - * / ^, and sin cos tan asin acos atan atan2 sinh
// cosh tanh exp log sqrt abs sign. Vectors: [a, b, c] (components on E1, E2, E3), E1 E2 E3, names
// from the Scope, and dot cross norm. The full grammar is at the top of expression_parser.cpp.
//
// Every mistake throws ModelError at the line:column of the offending token; nothing else is
// thrown (exceptions from GiNaC or from the Scope become ModelErrors at the token that caused
// them). Hostile input is refused rather than obeyed: see ExpressionLimits.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "unidyn/symbolic/expression.hpp"

namespace unidyn {

// What an expression evaluates to: a scalar or a vector.
struct Value {
  enum class Kind { scalar, vector };

  Kind kind = Kind::scalar;
  Expr scalar = 0;      // when kind == scalar
  VectorExpr vector{};  // when kind == vector

  static Value of(Expr s) { return {Kind::scalar, std::move(s), {}}; }
  static Value of(VectorExpr v) { return {Kind::vector, 0, std::move(v)}; }

  bool is_scalar() const { return kind == Kind::scalar; }
  bool is_vector() const { return kind == Kind::vector; }
};

// What names mean; supplied by the model layer. Its values are trusted; the text is not.
class Scope {
 public:
  virtual ~Scope() = default;

  // A plain or dotted name ("m", "theta", "t", "P.position", "top.e3"); nullopt if unknown.
  virtual std::optional<Value> lookup(std::string_view name) const = 0;
  // der(name): the rate symbol of a coordinate; nullopt if `name` is not a coordinate.
  virtual std::optional<Expr> rate(std::string_view name) const = 0;
  // A call of a dotted name with arguments, e.g. top.point([X1,X2,X3]); nullopt if unknown.
  // Default: no callable names.
  virtual std::optional<Value> call(std::string_view name, const std::vector<Value>& args) const;
  // Every name lookup() knows, for "did you mean" hints. Default: none.
  virtual std::vector<std::string> names() const;
};

// Bounds that keep hostile text from exhausting time or memory; exceeding one is a ModelError.
struct ExpressionLimits {
  // Characters of text.
  static constexpr std::size_t max_length = 100'000;
  // Nesting of parentheses, brackets, calls, unary signs and right-associative ^.
  static constexpr int max_depth = 256;
  // Bits of any exact number (numerator or denominator), about 39 000 decimal digits. Checked
  // before each operation on an upper bound computed from its operands (a sum of k terms adds
  // log2 k bits, a product adds the operands' bits, a^n multiplies the bits of the numbers GiNaC
  // would raise by |n|), so 10^100000 and 2^99999999999 are refused without being computed, while
  // x^99999999999 stays the symbolic power it is.
  static constexpr double max_number_bits = 131'072;
  // Nodes of the expression tree, estimated from the operands; stops exponential growth such as
  // nested cross products, which share subtrees in GiNaC but would be unfolded by later steps.
  // Names from the Scope count as one node.
  static constexpr double max_size = 1e6;
};

// Parses and evaluates `text`. `origin` is where text starts in the model file (line and column of
// its first character, 1-based); later lines of a multi-line text count columns from 1. An origin
// with line 0 (unknown) makes positions relative to the text (1:1 is its first character).
// Columns count UTF-8 code points. Throws ModelError.
Value parse_expression(std::string_view text, const Scope& scope, const SourcePosition& origin);
// As parse_expression, and an error if the result is a vector.
Expr parse_scalar(std::string_view text, const Scope& scope, const SourcePosition& origin);
// As parse_expression, and an error if the result is a scalar.
VectorExpr parse_vector(std::string_view text, const Scope& scope, const SourcePosition& origin);

// Names the language defines itself (pi, E1, E2, E3, der and the functions); they take precedence
// over the Scope, so the model layer should refuse parameters or coordinates with these names.
bool is_reserved_name(std::string_view name);

}  // namespace unidyn
