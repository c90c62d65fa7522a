// Parser of the model-file expression language (DESIGN.md, "Model file (YAML)").
//
// Grammar (recursive descent; each rule evaluates straight to GiNaC, nothing is executed):
//
//   expression := sum END
//   sum        := product (('+' | '-') product)*
//   product    := signed (('*' | '/') signed)*
//   signed     := ('-' | '+') signed | power            so -x^2 = -(x^2)
//   power      := primary ('^' signed)?                  right-associative: 2^3^2 = 2^9, 2^-1 = 1/2
//   primary    := NUMBER | '(' sum ')' | '[' sum ',' sum ',' sum ']'
//               | 'der' '(' NAME ')' | NAME '(' arguments? ')' | NAME
//   arguments  := sum (',' sum)*
//   NAME       := identifier ('.' identifier)*           m, theta, P.position, top.e3
//   identifier := [A-Za-z_][A-Za-z0-9_]*
//   NUMBER     := (digits ('.' digits?)? | '.' digits) ([eE] [+-]? digits)?    exact rationals
//
// Whitespace, newlines included, may separate any two tokens. Built-in names: pi (GiNaC::Pi),
// deg (π/180: 30*deg), E1 E2 E3 (the fixed basis); functions sin cos tan asin acos atan sinh cosh
// tanh exp log sqrt abs sign of one scalar, atan2(y, x), dot(u, v), cross(u, v), norm(v). sign is
// GiNaC's csgn (−1, 0, 1 for real arguments), abs is GiNaC's abs. Other names and calls go to the
// Scope.
//
// Types: scalar ± scalar, vector ± vector, scalar * vector, vector * scalar, vector / scalar,
// scalar / scalar, scalar ^ scalar. Anything else is a ModelError that says what was expected.
//
// Chains such as a + b - c or a * b / c are built as one GiNaC sum or product, not pairwise, so a
// long chain costs O(n log n) rather than O(n²).
#include "unidyn/symbolic/expression_parser.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <utility>

#include "expression_lexer.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"

namespace unidyn {

std::optional<Value> Scope::call(std::string_view, const std::vector<Value>&) const {
  return std::nullopt;
}

std::vector<std::string> Scope::names() const {
  return {};
}

namespace {

using detail::describe;
using detail::quoted;
using detail::Token;
using detail::TokenKind;
using Limits = ExpressionLimits;
using Values = std::vector<Value>;

// A parsed subexpression, where it starts, and bounds that keep hostile input cheap.
struct Operand {
  Value value;
  SourcePosition where;
  double size = 1;  // upper bound on the nodes of its expression trees
  double bits = 0;  // upper bound on the bits of any exact number in it

  bool is_vector() const { return value.is_vector(); }
};

// ---------------------------------------------------------------------------------------------
// Built-in functions

// Argument types and result, and how the bounds grow.
enum class Shape { scalar, dot, cross, norm };

struct Builtin {
  std::string_view name;
  std::string_view usage;
  std::size_t arity;
  Shape shape;
  Value (*apply)(const Values& args);
};

// clang-format off
const std::array<Builtin, 18> kBuiltins{{
    {"sin", "sin(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::sin(a[0].scalar)); }},
    {"cos", "cos(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::cos(a[0].scalar)); }},
    {"tan", "tan(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::tan(a[0].scalar)); }},
    {"asin", "asin(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::asin(a[0].scalar)); }},
    {"acos", "acos(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::acos(a[0].scalar)); }},
    {"atan", "atan(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::atan(a[0].scalar)); }},
    {"atan2", "atan2(y, x)", 2, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::atan2(a[0].scalar, a[1].scalar)); }},
    {"sinh", "sinh(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::sinh(a[0].scalar)); }},
    {"cosh", "cosh(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::cosh(a[0].scalar)); }},
    {"tanh", "tanh(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::tanh(a[0].scalar)); }},
    {"exp", "exp(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::exp(a[0].scalar)); }},
    {"log", "log(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::log(a[0].scalar)); }},
    {"sqrt", "sqrt(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::sqrt(a[0].scalar)); }},
    {"abs", "abs(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::abs(a[0].scalar)); }},
    {"sign", "sign(x)", 1, Shape::scalar, [](const Values& a) { return Value::of(GiNaC::csgn(a[0].scalar)); }},
    {"dot", "dot(u, v)", 2, Shape::dot, [](const Values& a) { return Value::of(dot(a[0].vector, a[1].vector)); }},
    {"cross", "cross(u, v)", 2, Shape::cross, [](const Values& a) { return Value::of(cross(a[0].vector, a[1].vector)); }},
    {"norm", "norm(v)", 1, Shape::norm, [](const Values& a) { return Value::of(norm(a[0].vector)); }},
}};
// clang-format on

const Builtin* find_builtin(std::string_view name) {
  for (const Builtin& f : kBuiltins) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

// ---------------------------------------------------------------------------------------------
// Messages

std::string kind_name(bool vector) {
  return vector ? "a vector" : "a scalar";
}

std::string position_text(const SourcePosition& p) {
  return std::to_string(p.line) + ":" + std::to_string(p.column);
}

std::string count_text(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

const char* ordinal(std::size_t i) {
  static const char* const kOrdinals[] = {"first", "second", "third"};
  return i < 3 ? kOrdinals[i] : "next";
}

[[noreturn]] void fail(const SourcePosition& where, const std::string& message) {
  throw ModelError(where, message);
}

// Optimal string alignment distance: insertions, deletions, substitutions, adjacent swaps.
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, substitution});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

// Characters two names share at their start.
std::size_t common_prefix(std::string_view a, std::string_view b) {
  std::size_t n = 0;
  while (n < a.size() && n < b.size() && a[n] == b[n]) ++n;
  return n;
}

// "; did you mean 'theta'?" for the closest candidate within two edits, else "". Ties go to the
// longer common start (typos sit more often at the end), then to alphabetical order.
std::string did_you_mean(std::string_view name, std::vector<std::string> candidates) {
  constexpr std::size_t kMaxEdits = 2;
  if (name.size() > 64) return "";
  std::sort(candidates.begin(), candidates.end());
  const std::string* best = nullptr;
  std::size_t best_distance = kMaxEdits + 1;
  std::size_t best_prefix = 0;
  for (const std::string& candidate : candidates) {
    const std::size_t longer = std::max(name.size(), candidate.size());
    if (candidate == name || longer - std::min(name.size(), candidate.size()) > kMaxEdits) continue;
    const std::size_t distance = edit_distance(name, candidate);
    const std::size_t prefix = common_prefix(name, candidate);
    // A one-letter name is within one edit of every other: no hint from that.
    if (distance >= longer) continue;
    if (distance < best_distance || (distance == best_distance && prefix > best_prefix)) {
      best = &candidate;
      best_distance = distance;
      best_prefix = prefix;
    }
  }
  return best ? "; did you mean '" + *best + "'?" : "";
}

// ---------------------------------------------------------------------------------------------
// Bounds on exact numbers

// Bits of an exact number: the longer of numerator and denominator; a float counts as a double.
double number_bits(const GiNaC::numeric& n) {
  if (n.is_rational()) return std::max(n.numer().int_length(), n.denom().int_length());
  if (n.is_crational()) return std::max(number_bits(n.real()), number_bits(n.imag()));
  return 64;
}

// |n| as a double that saturates (cln throws where a double would overflow or underflow).
double magnitude(const GiNaC::numeric& n) {
  constexpr double kHuge = 1e300;
  if (n.is_rational()) {
    const long scale = n.numer().int_length() - n.denom().int_length();
    if (scale > 900) return kHuge;
    if (scale < -900) return 0;
    return std::abs(n.to_double());
  }
  if (n.is_crational()) return magnitude(n.real()) + magnitude(n.imag());
  try {
    return std::abs(n.to_double());
  } catch (const std::exception&) {
    return kHuge;
  }
}

// Bits GiNaC computes per unit of n when it raises `base` to a numeric power n: numbers are
// raised, products distribute the power over their factors, powers multiply their exponents.
double raise_bits(const Expr& base) {
  if (GiNaC::is_a<GiNaC::numeric>(base)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(base);
    return n.is_zero() || GiNaC::abs(n).is_equal(1) ? 0 : number_bits(n);
  }
  if (GiNaC::is_a<GiNaC::power>(base) && GiNaC::is_a<GiNaC::numeric>(base.op(1))) {
    return raise_bits(base.op(0)) * magnitude(GiNaC::ex_to<GiNaC::numeric>(base.op(1)));
  }
  double bits = 0;
  if (GiNaC::is_a<GiNaC::mul>(base)) {
    for (std::size_t i = 0; i < base.nops(); ++i) bits += raise_bits(base.op(i));
  }
  return bits;
}

// The largest number in a value from the Scope (trusted), looking at a bounded number of nodes.
double scope_bits(const Value& value) {
  constexpr std::size_t kMaxNodes = 1'000;
  std::vector<Expr> stack;
  if (value.is_scalar()) stack.push_back(value.scalar);
  if (value.is_vector()) stack.insert(stack.end(), value.vector.c.begin(), value.vector.c.end());
  double bits = 0;
  for (std::size_t visited = 0; !stack.empty() && visited < kMaxNodes; ++visited) {
    const Expr e = stack.back();
    stack.pop_back();
    if (GiNaC::is_a<GiNaC::numeric>(e)) {
      bits = std::max(bits, number_bits(GiNaC::ex_to<GiNaC::numeric>(e)));
    }
    for (std::size_t i = 0; i < e.nops() && stack.size() < kMaxNodes; ++i) stack.push_back(e.op(i));
  }
  return bits;
}

void check_bits(double bits, const SourcePosition& where) {
  if (bits > Limits::max_number_bits) {
    fail(where, "number too large: exact numbers are limited to " +
                    std::to_string(static_cast<long>(Limits::max_number_bits)) + " bits");
  }
}

void check_size(double size, const SourcePosition& where) {
  if (size > Limits::max_size) {
    fail(where, "expression too large: it would grow beyond " +
                    std::to_string(static_cast<long>(Limits::max_size)) +
                    " terms (nested cross products?)");
  }
}

// Runs GiNaC (or the Scope): its exceptions become ModelErrors at the token that caused them.
template <class F>
auto guarded(const SourcePosition& where, std::string_view what, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const ModelError&) {
    throw;
  } catch (const std::exception& e) {
    throw ModelError(where, "cannot evaluate " + std::string(what) + ": " + e.what());
  }
}

bool is_constant(std::string_view name) {
  return name == "pi" || name == "deg" || name == "E1" || name == "E2" || name == "E3";
}

Value negated(const Value& v) {
  return v.is_vector() ? Value::of(-v.vector) : Value::of(-v.scalar);
}

// ---------------------------------------------------------------------------------------------
// The parser

class Parser {
 public:
  Parser(std::string_view text, const Scope& scope, const SourcePosition& origin)
      : lexer_(text, origin), scope_(scope) {}

  Operand parse();

 private:
  // Counts nesting for the duration of a rule; too deep is an error.
  class Nested {
   public:
    explicit Nested(Parser& parser) : parser_(parser) {
      if (parser_.depth_ >= Limits::max_depth) {
        fail(parser_.current_.where, "expression nested too deeply: at most " +
                                         std::to_string(Limits::max_depth) + " levels");
      }
      ++parser_.depth_;
    }
    ~Nested() { --parser_.depth_; }
    Nested(const Nested&) = delete;
    Nested& operator=(const Nested&) = delete;

   private:
    Parser& parser_;
  };

  bool at(TokenKind kind) const { return current_.kind == kind; }
  Token advance();
  Token expect(TokenKind kind, const std::string& what);
  void expect_closing(TokenKind kind, const char* what, const Token& open);
  [[noreturn, gnu::noinline]] void fail_closing(const char* what, const Token& open) const;

  // The rules; those marked noinline are kept out of the recursive rules' frames, so that the
  // stack stays small at the deepest nesting allowed.
  Operand parse_sum();
  [[gnu::noinline]] Operand sum_chain(Operand first);
  Operand parse_product();
  [[gnu::noinline]] Operand product_chain(Operand first);
  Operand parse_signed();
  Operand parse_power();
  [[gnu::noinline]] Operand raise(const Operand& base, const Operand& exponent, const Token& op);
  Operand parse_primary();
  [[gnu::noinline]] Operand parse_number();
  [[gnu::noinline]] Operand parse_group();
  [[gnu::noinline]] Operand parse_vector_literal();
  [[gnu::noinline]] Operand parse_name();
  [[gnu::noinline]] Operand builtin_constant(const Token& name) const;
  [[gnu::noinline]] Operand parse_der(const Token& name);
  std::vector<Operand> parse_arguments(const Token& open);
  [[gnu::noinline]] Operand apply_builtin(const Builtin& f, const Token& name,
                                          const std::vector<Operand>& args);
  [[gnu::noinline]] Operand call_scope(const Token& name, const std::vector<Operand>& args);

  bool scope_knows(std::string_view name) const;
  std::vector<std::string> scope_names() const;
  std::vector<std::string> coordinate_names() const;

  detail::Lexer lexer_;
  const Scope& scope_;
  Token current_;
  int depth_ = 0;
  std::map<std::string, double, std::less<>> name_bits_;
};

Token Parser::advance() {
  Token token = std::move(current_);
  current_ = lexer_.next();
  return token;
}

Token Parser::expect(TokenKind kind, const std::string& what) {
  if (!at(kind)) fail(current_.where, "expected " + what + ", found " + describe(current_));
  return advance();
}

// The bracket that closes `open`; the message is only built when it is missing.
void Parser::expect_closing(TokenKind kind, const char* what, const Token& open) {
  if (!at(kind)) fail_closing(what, open);
  advance();
}

void Parser::fail_closing(const char* what, const Token& open) const {
  fail(current_.where, "expected " + std::string(what) + " to close the " + quoted(open.text) +
                           " at " + position_text(open.where) + ", found " + describe(current_));
}

Operand Parser::parse() {
  current_ = lexer_.next();
  Operand result = parse_sum();
  // Whatever is left over could not continue the expression.
  switch (current_.kind) {
    case TokenKind::end:
      return result;
    case TokenKind::right_paren:
      fail(current_.where, "unmatched ')'");
    case TokenKind::right_bracket:
      fail(current_.where, "unmatched ']'");
    case TokenKind::comma:
      fail(current_.where, "unexpected ',' outside a vector or a call");
    default:
      fail(current_.where, "expected an operator such as '*' or '+' before " + describe(current_));
  }
}

// sum := product (('+' | '-') product)*
Operand Parser::parse_sum() {
  Operand first = parse_product();
  if (!at(TokenKind::plus) && !at(TokenKind::minus)) return first;
  return sum_chain(std::move(first));
}

// The terms of a sum, collected and added at once (component-wise for vectors).
Operand Parser::sum_chain(Operand first) {
  const bool vector = first.is_vector();
  const SourcePosition first_op = current_.where;
  std::array<GiNaC::exvector, 3> terms;
  auto append = [&](const Value& v) {
    if (!vector) terms[0].push_back(v.scalar);
    for (int i = 0; vector && i < 3; ++i) terms[static_cast<std::size_t>(i)].push_back(v.vector[i]);
  };
  append(first.value);
  double size = first.size;
  double bits = first.bits;
  while (at(TokenKind::plus) || at(TokenKind::minus)) {
    const Token op = advance();
    Operand term = parse_product();
    if (term.is_vector() != vector) {
      fail(op.where, "'" + std::string(op.text) + "' needs two scalars or two vectors, not " +
                         kind_name(vector) + " and " + kind_name(term.is_vector()));
    }
    append(op.kind == TokenKind::minus ? negated(term.value) : term.value);
    size += term.size + 1;
    bits = std::max(bits, term.bits);
    check_size(size, op.where);
  }
  // A sum of k numbers has at most log2(k) more bits than the largest.
  bits += std::ceil(std::log2(static_cast<double>(terms[0].size())));
  check_bits(bits, first_op);
  Value sum = guarded(first_op, "the sum", [&] {
    if (!vector) return Value::of(GiNaC::add(terms[0]));
    return Value::of(VectorExpr(GiNaC::add(terms[0]), GiNaC::add(terms[1]), GiNaC::add(terms[2])));
  });
  return {std::move(sum), first.where, size, bits};
}

// product := signed (('*' | '/') signed)*
Operand Parser::parse_product() {
  Operand first = parse_signed();
  if (!at(TokenKind::star) && !at(TokenKind::slash)) return first;
  return product_chain(std::move(first));
}

// The scalar factors of a product, multiplied at once, times at most one vector.
Operand Parser::product_chain(Operand first) {
  const SourcePosition first_op = current_.where;
  GiNaC::exvector factors;
  std::optional<VectorExpr> vector;
  if (first.is_vector()) vector = first.value.vector;
  if (!first.is_vector()) factors.push_back(first.value.scalar);
  double size = first.size;
  double bits = first.bits;
  while (at(TokenKind::star) || at(TokenKind::slash)) {
    const Token op = advance();
    Operand factor = parse_signed();
    size += factor.size + 1;
    bits += factor.bits;
    check_size(size, op.where);
    check_bits(bits, op.where);
    // vector * vector has no meaning; a scalar multiplies, a vector is carried along.
    if (op.kind == TokenKind::star) {
      if (factor.is_vector() && vector) {
        fail(op.where, "cannot multiply two vectors: use dot(a, b) or cross(a, b)");
      }
      if (factor.is_vector()) vector = factor.value.vector;
      if (!factor.is_vector()) factors.push_back(factor.value.scalar);
      continue;
    }
    // Only a non-zero scalar divides.
    if (factor.is_vector()) fail(op.where, "cannot divide by a vector: a divisor must be a scalar");
    if (factor.value.scalar.is_zero()) fail(op.where, "division by zero");
    factors.push_back(
        guarded(op.where, "'/'", [&] { return GiNaC::pow(factor.value.scalar, -1); }));
  }
  Expr scalar = guarded(first_op, "the product", [&] { return Expr(GiNaC::mul(factors)); });
  if (!vector) return {Value::of(scalar), first.where, size, bits};
  // The scalar is repeated in each of the three components.
  check_size(3 * size, first_op);
  Value product = guarded(first_op, "the product", [&] { return Value::of(scalar * *vector); });
  return {std::move(product), first.where, 3 * size, bits};
}

// signed := ('-' | '+') signed | power
Operand Parser::parse_signed() {
  const Nested nested(*this);
  if (!at(TokenKind::minus) && !at(TokenKind::plus)) return parse_power();
  const Token op = advance();
  Operand operand = parse_signed();
  if (op.kind == TokenKind::minus) {
    operand.value = guarded(op.where, "'-'", [&] { return negated(operand.value); });
  }
  operand.where = op.where;
  operand.size += 1;
  return operand;
}

// power := primary ('^' signed)?
Operand Parser::parse_power() {
  Operand base = parse_primary();
  if (!at(TokenKind::caret)) return base;
  const Token op = advance();
  const Operand exponent = parse_signed();
  return raise(base, exponent, op);
}

// base ^ exponent, refused before GiNaC computes a number beyond the limit.
Operand Parser::raise(const Operand& base, const Operand& exponent, const Token& op) {
  if (base.is_vector()) {
    fail(op.where, "cannot raise a vector to a power: use dot(v, v) for its square");
  }
  if (exponent.is_vector()) fail(exponent.where, "an exponent must be a scalar, not a vector");
  const Expr& b = base.value.scalar;
  const Expr& e = exponent.value.scalar;
  double bits = base.bits + exponent.bits;
  if (GiNaC::is_a<GiNaC::numeric>(e)) {
    const auto& n = GiNaC::ex_to<GiNaC::numeric>(e);
    // Refused here, not by GiNaC: a power that throws from its evaluation leaks in GiNaC.
    if (b.is_zero() && n.is_zero()) fail(op.where, "0^0 is undefined");
    if (b.is_zero() && !n.is_pos_integer() && !(n.is_real() && n.is_positive())) {
      fail(op.where, "division by zero: 0 to a power that is not positive");
    }
    bits = std::max(bits, raise_bits(b) * magnitude(n));
  }
  check_bits(bits, op.where);
  Expr result = guarded(op.where, "'^'", [&] { return GiNaC::pow(b, e); });
  // A power of a sum is where a few characters become millions of terms once expanded.
  if (GiNaC::is_a<GiNaC::power>(result) && GiNaC::is_a<GiNaC::add>(result.op(0))) {
    if (const double terms = expanded_terms_bound(result); terms > kMaxModelExpressionTerms) {
      char count[64];
      std::snprintf(count, sizeof count, "%.3g", terms);
      fail(op.where, std::string("this power of a sum would expand to up to ") + count +
                         " terms (more than " +
                         std::to_string(static_cast<long>(kMaxModelExpressionTerms)) +
                         "): write it with fewer terms or a smaller exponent");
    }
  }
  return {Value::of(result), base.where, base.size + exponent.size + 1, bits};
}

// primary := NUMBER | '(' sum ')' | '[' sum ',' sum ',' sum ']' | name, call or der(q)
Operand Parser::parse_primary() {
  switch (current_.kind) {
    case TokenKind::number:
      return parse_number();
    case TokenKind::left_paren:
      return parse_group();
    case TokenKind::left_bracket:
      return parse_vector_literal();
    case TokenKind::name:
      return parse_name();
    default:
      fail(current_.where, "expected a number, a name, '(' or '[', found " + describe(current_));
  }
}

Operand Parser::parse_number() {
  const Token token = advance();
  const Expr value = detail::exact_number(token.text, token.where);
  const double bits = number_bits(GiNaC::ex_to<GiNaC::numeric>(value));
  return {Value::of(value), token.where, 1, bits};
}

// '(' sum ')'
Operand Parser::parse_group() {
  const Token open = advance();
  Operand inner = parse_sum();
  expect_closing(TokenKind::right_paren, "')'", open);
  inner.where = open.where;
  return inner;
}

// '[' sum ',' sum ',' sum ']': three scalar components on E1, E2, E3.
Operand Parser::parse_vector_literal() {
  const Token open = advance();
  VectorExpr v;
  double size = 1;
  double bits = 0;
  for (int i = 0; i < 3; ++i) {
    if (i > 0 && !at(TokenKind::comma)) {
      fail(current_.where, "a vector has three components: expected ',' after the " +
                               std::string(ordinal(static_cast<std::size_t>(i - 1))) + ", found " +
                               describe(current_));
    }
    if (i > 0) advance();
    const Operand component = parse_sum();
    if (component.is_vector()) {
      fail(component.where, "a component of a vector must be a scalar, not a vector");
    }
    v[i] = component.value.scalar;
    size += component.size;
    bits = std::max(bits, component.bits);
  }
  if (at(TokenKind::comma)) {
    fail(current_.where, "a vector has three components: expected ']' after the third");
  }
  expect_closing(TokenKind::right_bracket, "']'", open);
  return {Value::of(v), open.where, size, bits};
}

// A name: a call, a built-in constant, or a value from the Scope.
Operand Parser::parse_name() {
  const Token name = advance();
  if (name.text == "der" && at(TokenKind::left_paren)) return parse_der(name);
  if (at(TokenKind::left_paren)) {
    const Token open = advance();
    const std::vector<Operand> args = parse_arguments(open);
    if (const Builtin* f = find_builtin(name.text)) return apply_builtin(*f, name, args);
    return call_scope(name, args);
  }
  if (is_constant(name.text)) return builtin_constant(name);
  if (name.text == "der") fail(name.where, "'der' is a function: write der(q) for the rate of q");
  if (const Builtin* f = find_builtin(name.text)) {
    fail(name.where, quoted(name.text) + " is a function: write " + std::string(f->usage));
  }
  std::optional<Value> value =
      guarded(name.where, quoted(name.text), [&] { return scope_.lookup(name.text); });
  if (!value) {
    fail(name.where, "unknown name " + quoted(name.text) + did_you_mean(name.text, scope_names()));
  }
  const double size = value->is_vector() ? 3 : 1;
  // A name may be used many times: its numbers are looked at once.
  auto [cached, inserted] = name_bits_.try_emplace(std::string(name.text), 0.0);
  if (inserted) cached->second = scope_bits(*value);
  return {std::move(*value), name.where, size, cached->second};
}

// pi, deg = π/180 (so that 30*deg is 30 degrees in radians) and the fixed basis E1, E2, E3.
Operand Parser::builtin_constant(const Token& name) const {
  if (name.text == "pi") return {Value::of(GiNaC::Pi), name.where, 1, 0};
  if (name.text == "deg") return {Value::of(GiNaC::Pi / 180), name.where, 1, 8};
  const int i = name.text[1] - '0';
  return {Value::of(basis_vector_expr(i)), name.where, 3, 1};
}

// 'der' '(' NAME ')': the rate symbol of a coordinate.
Operand Parser::parse_der(const Token& name) {
  advance();
  if (!at(TokenKind::name)) {
    fail(current_.where,
         "der needs the name of a coordinate, as in der(theta); found " + describe(current_));
  }
  const Token q = advance();
  expect(TokenKind::right_paren, "')' after der(" + std::string(q.text) + ": der takes one name");
  std::optional<Expr> rate = guarded(q.where, "der", [&] { return scope_.rate(q.text); });
  if (!rate) {
    const std::string hint = did_you_mean(q.text, coordinate_names());
    if (scope_knows(q.text)) {
      fail(q.where, quoted(q.text) + " is not a coordinate: der(q) needs a coordinate" + hint);
    }
    fail(q.where, "unknown coordinate " + quoted(q.text) + hint);
  }
  Value value = Value::of(*rate);
  const double bits = scope_bits(value);
  return {std::move(value), name.where, 1, bits};
}

// arguments? ')' after the '('.
std::vector<Operand> Parser::parse_arguments(const Token& open) {
  std::vector<Operand> args;
  if (at(TokenKind::right_paren)) {
    advance();
    return args;
  }
  for (;;) {
    args.push_back(parse_sum());
    if (!at(TokenKind::comma)) break;
    advance();
  }
  expect_closing(TokenKind::right_paren, "',' or ')'", open);
  return args;
}

// sin(x) ... norm(v): count and types of the arguments, then GiNaC.
Operand Parser::apply_builtin(const Builtin& f, const Token& name,
                              const std::vector<Operand>& args) {
  const std::string fname(f.name);
  if (args.size() != f.arity) {
    fail(name.where, fname + " takes " + count_text(f.arity, "argument") + ", " +
                         std::string(f.usage) + "; found " + std::to_string(args.size()));
  }
  const bool wants_vector = f.shape != Shape::scalar;
  double size = 0;
  double bits = 0;
  Values values;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i].is_vector() != wants_vector) {
      const std::string which =
          f.arity > 1 ? " as its " + std::string(ordinal(i)) + " argument" : "";
      fail(args[i].where, fname + " needs " + kind_name(wants_vector) + which + ", not " +
                              kind_name(args[i].is_vector()) + ": " + std::string(f.usage));
    }
    size += args[i].size;
    bits = std::max(bits, args[i].bits);
    values.push_back(args[i].value);
  }
  // dot, cross and norm multiply components and repeat them.
  switch (f.shape) {
    case Shape::scalar:
      size += 1;
      break;
    case Shape::dot: {
      size += 4;
      bits = 2 * bits + 2;
      break;
    }
    case Shape::cross: {
      size = 2 * size + 9;
      bits = 2 * bits + 1;
      break;
    }
    case Shape::norm: {
      size = 2 * size + 5;
      bits = 2 * bits + 2;
      break;
    }
  }
  check_size(size, name.where);
  check_bits(bits, name.where);
  Value value = guarded(name.where, fname, [&] { return f.apply(values); });
  return {std::move(value), name.where, size, bits};
}

// A call the Scope answers, such as top.point([X1, X2, X3]).
Operand Parser::call_scope(const Token& name, const std::vector<Operand>& args) {
  double size = 1;
  double bits = 0;
  Values values;
  for (const Operand& arg : args) {
    size += 3 * arg.size;
    bits = std::max(bits, arg.bits);
    values.push_back(arg.value);
  }
  std::optional<Value> value =
      guarded(name.where, quoted(name.text), [&] { return scope_.call(name.text, values); });
  if (!value) {
    if (is_constant(name.text) || scope_knows(name.text)) {
      fail(name.where, quoted(name.text) + " is not a function; to multiply, write " +
                           std::string(name.text) + "*(...)");
    }
    std::vector<std::string> functions{"der"};
    for (const Builtin& f : kBuiltins) functions.emplace_back(f.name);
    fail(name.where, "unknown function " + quoted(name.text) + did_you_mean(name.text, functions));
  }
  check_size(size, name.where);
  bits = std::max(bits, scope_bits(*value));
  check_bits(bits, name.where);
  return {std::move(*value), name.where, size, bits};
}

// The Scope, asked only to word an error: its own failures leave the hint out.
bool Parser::scope_knows(std::string_view name) const {
  try {
    return scope_.lookup(name).has_value();
  } catch (const std::exception&) {
    return false;
  }
}

std::vector<std::string> Parser::scope_names() const {
  std::vector<std::string> names{"pi", "deg", "E1", "E2", "E3"};
  try {
    for (std::string& name : scope_.names()) names.push_back(std::move(name));
  } catch (const std::exception&) {
  }
  return names;
}

std::vector<std::string> Parser::coordinate_names() const {
  std::vector<std::string> coordinates;
  try {
    for (std::string& name : scope_.names()) {
      if (scope_.rate(name)) coordinates.push_back(std::move(name));
    }
  } catch (const std::exception&) {
  }
  return coordinates;
}

// Length first, so nothing is spent on text that is refused anyway.
Operand parse_operand(std::string_view text, const Scope& scope, const SourcePosition& origin) {
  if (text.size() > Limits::max_length) {
    fail(detail::Lexer({}, origin).position(),
         "expression too long: " + std::to_string(text.size()) + " characters, at most " +
             std::to_string(Limits::max_length));
  }
  return Parser(text, scope, origin).parse();
}

}  // namespace

Value parse_expression(std::string_view text, const Scope& scope, const SourcePosition& origin) {
  return parse_operand(text, scope, origin).value;
}

Expr parse_scalar(std::string_view text, const Scope& scope, const SourcePosition& origin) {
  Operand result = parse_operand(text, scope, origin);
  if (result.is_vector()) fail(result.where, "expected a scalar, but this expression is a vector");
  return result.value.scalar;
}

VectorExpr parse_vector(std::string_view text, const Scope& scope, const SourcePosition& origin) {
  Operand result = parse_operand(text, scope, origin);
  if (!result.is_vector()) fail(result.where, "expected a vector, but this expression is a scalar");
  return result.value.vector;
}

bool is_reserved_name(std::string_view name) {
  return is_constant(name) || name == "der" || find_builtin(name) != nullptr;
}

}  // namespace unidyn
