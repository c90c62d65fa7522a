// Instruction tape: compilation of GiNaC expressions to a register program, and its evaluation.
//
// Compilation runs in passes: (0) sums with their common factors taken out (the multivariate
// Horner scheme, symbolic/horner_form.hpp); (1) expressions → instructions on virtual registers in
// SSA form, with common subexpressions shared by GiNaC structural equality and by instruction value
// numbering, constants folded; (2) sin and cos of one argument fused into sincos; (3) dead
// instructions removed; (4) virtual registers mapped to reusable physical registers.
#include "unidyn/numeric/tape.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <compare>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>

#include "tape_execute.hpp"
#include "tape_program.hpp"
#include "unidyn/symbolic/horner_form.hpp"

namespace unidyn {

namespace {

using GiNaC::ex;
using GiNaC::is_a;
using GiNaC::is_exactly_a;

using detail::kNone;
using detail::Node;
using detail::Program;
using detail::Value;
// Integer exponents up to this size become multiplications; larger ones use std::pow.
constexpr long kMaxMultipliedPower = 64;

// Value of a single-result operation on numbers (for constant folding).
double fold(TapeOp op, double x, double y) {
  double r[3] = {x, y, 0.0};
  detail::execute(TapeInstruction{op, 2, 0, 1}, r);
  return r[2];
}

// Name of an operation in listings.
const char* op_name(TapeOp op) {
  static constexpr const char* names[] = {"add",  "sub",  "mul",  "div",   "neg",    "recip",
                                          "sqrt", "pow",  "sin",  "cos",   "sincos", "tan",
                                          "asin", "acos", "atan", "atan2", "sinh",   "cosh",
                                          "tanh", "exp",  "log",  "abs",   "sign",   "step"};
  return names[static_cast<std::size_t>(op)];
}

// The printed form of an expression, for error messages.
std::string str(const ex& e) {
  std::ostringstream os;
  os << e;
  return os.str();
}

[[noreturn]] void fail(const std::string& what, const ex& e) {
  throw std::invalid_argument("Tape::compile: " + what + ": " + str(e));
}

// FNV-1a: a hash of text that is the same in every run.
std::uint64_t hash_text(std::string_view text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (const char c : text) h = (h ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
  return h;
}

// Combine a hash with the next one, order-sensitively.
std::uint64_t mix(std::uint64_t h, std::uint64_t next) {
  return h ^ (next + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
}

// The numeric coefficient of a term of a sum (1 if it has none).
GiNaC::numeric coefficient(const ex& term) {
  if (is_exactly_a<GiNaC::numeric>(term)) return GiNaC::ex_to<GiNaC::numeric>(term);
  if (is_exactly_a<GiNaC::mul>(term) && term.nops() > 0) {
    const ex last = term.op(term.nops() - 1);
    if (is_exactly_a<GiNaC::numeric>(last)) return GiNaC::ex_to<GiNaC::numeric>(last);
  }
  return 1;
}

// A power with a real negative numeric exponent: a factor of a denominator.
bool is_reciprocal_factor(const ex& factor) {
  if (!is_exactly_a<GiNaC::power>(factor)) return false;
  const ex exponent = factor.op(1);
  return is_exactly_a<GiNaC::numeric>(exponent) &&
         GiNaC::ex_to<GiNaC::numeric>(exponent).is_negative();
}

// The supported functions: GiNaC name → operation and number of arguments.
std::optional<std::pair<TapeOp, std::size_t>> function_op(const std::string& name) {
  static const std::map<std::string, std::pair<TapeOp, std::size_t>> table = {
      {"sin", {TapeOp::sin, 1}},     {"cos", {TapeOp::cos, 1}},   {"tan", {TapeOp::tan, 1}},
      {"asin", {TapeOp::asin, 1}},   {"acos", {TapeOp::acos, 1}}, {"atan", {TapeOp::atan, 1}},
      {"atan2", {TapeOp::atan2, 2}}, {"sinh", {TapeOp::sinh, 1}}, {"cosh", {TapeOp::cosh, 1}},
      {"tanh", {TapeOp::tanh, 1}},   {"exp", {TapeOp::exp, 1}},   {"log", {TapeOp::log, 1}},
      {"abs", {TapeOp::abs, 1}},     {"csgn", {TapeOp::sign, 1}}, {"step", {TapeOp::step, 1}}};
  const auto found = table.find(name);
  if (found == table.end()) return std::nullopt;
  return found->second;
}

// Pass 1: expressions → SSA instructions, with CSE and constant folding.
class Builder {
 public:
  explicit Builder(const std::vector<ex>& inputs) {
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      if (!GiNaC::is_a<GiNaC::symbol>(inputs[i])) fail("an input is not a symbol", inputs[i]);
      const bool fresh = inputs_.emplace(inputs[i], static_cast<std::uint32_t>(i)).second;
      if (!fresh) fail("input symbol listed twice", inputs[i]);
    }
  }

  // The value of e in a register (a negated one negated by an instruction).
  Value compile(const ex& e) { return plain(signed_value(e)); }

  const std::vector<double>& constants() const { return constants_; }
  std::vector<Node>& nodes() { return nodes_; }
  std::uint32_t temp_count() const { return temp_count_; }

 private:
  // A register and whether its value is to be negated. Signs travel with the values through
  // sums and products and become instructions only where a function, a root or an output needs
  // them: −x(a − b) and x(b − a), which GiNaC writes either way by its own order of terms (and so
  // by the memory layout), make one tape; a negation in IEEE arithmetic is exact, so the values
  // are those of the expression as written.
  struct Signed {
    Value value;
    bool negative = false;
  };
  // The value of s in a register: a negated difference turned (b − a for a − b), a negated
  // product or quotient of a number with the number negated, else a negation.
  Value plain(Signed s) {
    if (!s.negative) return s.value;
    if (s.value.kind == Value::Kind::temp) {
      const Node n = nodes_[s.value.index];  // (the instruction that made temporary i is the i-th)
      if (n.op == TapeOp::sub) return emit(TapeOp::sub, n.b, n.a);
      if (n.op == TapeOp::mul || n.op == TapeOp::div) {
        if (n.a.kind == Value::Kind::constant)
          return emit(n.op, constant(-constants_[n.a.index]), n.b);
        if (n.b.kind == Value::Kind::constant)
          return emit(n.op, n.a, constant(-constants_[n.b.index]));
      }
    }
    return emit(TapeOp::neg, s.value);
  }
  static Signed negated(Signed s, bool negate = true) { return {s.value, s.negative != negate}; }

  // e as a signed register; every structurally equal subexpression is compiled once.
  Signed signed_value(const ex& e) {
    if (const auto found = memo_.find(e); found != memo_.end()) return found->second;
    const Signed v = compile_uncached(e);
    if (v.value.kind == Value::Kind::constant && !std::isfinite(constants_[v.value.index]))
      fail("constant subexpression is not a finite real number", e);
    memo_.emplace(e, v);
    return v;
  }

  // Dispatch on the GiNaC class.
  Signed compile_uncached(const ex& e) {
    if (is_exactly_a<GiNaC::numeric>(e)) return compile_numeric(GiNaC::ex_to<GiNaC::numeric>(e));
    if (is_a<GiNaC::symbol>(e)) return {compile_symbol(e)};
    if (is_exactly_a<GiNaC::constant>(e)) return {compile_constant(e)};
    if (is_exactly_a<GiNaC::add>(e)) return compile_add(e);
    if (is_exactly_a<GiNaC::mul>(e)) return compile_mul(e);
    if (is_exactly_a<GiNaC::power>(e)) return compile_power(e);
    if (is_a<GiNaC::fderivative>(e)) fail("unevaluated derivative", e);
    if (is_exactly_a<GiNaC::function>(e)) return {compile_function(e)};
    fail(std::string("unsupported expression (GiNaC class ") +
             GiNaC::ex_to<GiNaC::basic>(e).class_name() + ")",
         e);
  }

  // Real numbers (exact rationals rounded to double): the magnitude, and the sign; complex ones
  // are refused.
  Signed compile_numeric(const GiNaC::numeric& n) {
    if (!n.is_real()) fail("complex number", n);
    const double d = n.to_double();
    return {constant(std::fabs(d)), std::signbit(d)};
  }

  // An input symbol: its register; any other symbol is refused.
  Value compile_symbol(const ex& e) {
    const auto found = inputs_.find(e);
    if (found == inputs_.end()) fail("symbol is not among the inputs", e);
    return {Value::Kind::input, found->second};
  }

  // Pi; GiNaC's other constants (Euler, Catalan) are refused.
  Value compile_constant(const ex& e) {
    if (!e.is_equal(GiNaC::Pi)) fail("unsupported constant", e);
    return constant(std::numbers::pi);
  }

  // Sum: the terms, each without its sign, in the order of their stable keys, each added or
  // subtracted by its sign (so that a sum and its negative make one instruction sequence).
  Signed compile_add(const ex& e) {
    std::vector<std::pair<ex, bool>> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const ex term = e.op(i);
      const bool negative = coefficient(term).is_negative();
      terms.emplace_back(negative ? -term : term, negative);
    }
    std::stable_sort(terms.begin(), terms.end(), [this](const auto& a, const auto& b) {
      return stable_key(a.first) < stable_key(b.first);
    });
    std::vector<Signed> values;
    for (const auto& [term, negative] : terms)
      values.push_back(negated(signed_value(term), negative));
    while (values.size() > 2 && take_made_sum(values)) {
    }
    Signed sum = values.front();
    for (std::size_t i = 1; i < values.size(); ++i) {
      const Signed& term = values[i];
      // ±(x + y) or ±(x − y), the sign of the sum so far
      const TapeOp op = term.negative == sum.negative ? TapeOp::add : TapeOp::sub;
      sum = {emit(op, sum.value, term.value), sum.negative};
    }
    return sum;
  }

  // The first pair of signed terms (in their order) whose sum or difference an instruction makes
  // already: replaced by it, in the first one's place. Whether there was one.
  bool take_made_sum(std::vector<Signed>& values) const {
    const auto made = [this](TapeOp op, Value a, Value b) -> std::optional<Value> {
      if (op == TapeOp::add && b < a) std::swap(a, b);
      const auto found = numbering_.find(std::make_tuple(op, a, b));
      if (found == numbering_.end()) return std::nullopt;
      return found->second;
    };
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (std::size_t j = i + 1; j < values.size(); ++j) {
        const Signed a = values[i], b = values[j];
        std::optional<Signed> sum;
        if (a.negative == b.negative) {
          if (const auto v = made(TapeOp::add, a.value, b.value)) sum = Signed{*v, a.negative};
        } else if (const auto v = made(TapeOp::sub, a.value, b.value)) {
          sum = Signed{*v, a.negative};  // ±(a − b)
        } else if (const auto w = made(TapeOp::sub, b.value, a.value)) {
          sum = Signed{*w, b.negative};  // ±(b − a)
        }
        if (!sum) continue;
        values[i] = *sum;
        values.erase(values.begin() + static_cast<std::ptrdiff_t>(j));
        return true;
      }
    }
    return false;
  }

  // Product: coefficient × (numerator factors) / (denominator factors).
  Signed compile_mul(const ex& e) {
    const GiNaC::numeric c = coefficient(e);
    GiNaC::exvector factors;
    for (std::size_t i = 0; i < (c.is_equal(1) ? e.nops() : e.nops() - 1); ++i)
      factors.push_back(e.op(i));
    if (!c.is_equal(1)) return scale(c, signed_value(GiNaC::mul(factors)), e);
    GiNaC::exvector numerator, denominator;
    for (const ex& factor : factors) {
      if (is_reciprocal_factor(factor)) {
        denominator.push_back(GiNaC::pow(factor.op(0), -factor.op(1)));
      } else {
        numerator.push_back(factor);
      }
    }
    if (denominator.empty()) return product(numerator);
    const Signed below = signed_value(GiNaC::mul(denominator));
    if (numerator.empty()) return {emit(TapeOp::recip, below.value), below.negative};
    const Signed above = signed_value(GiNaC::mul(numerator));
    return {emit(TapeOp::div, above.value, below.value), above.negative != below.negative};
  }

  // c · v: |c| · v (none for ±1) and the sign of c.
  Signed scale(const GiNaC::numeric& c, Signed v, const ex& e) {
    if (!c.is_real()) fail("complex number " + str(c) + " in", e);
    const Signed number = compile_numeric(c);
    const Value magnitude =
        GiNaC::abs(c).is_equal(1) ? v.value : emit(TapeOp::mul, number.value, v.value);
    return {magnitude, v.negative != number.negative};
  }

  // Left fold of a product of factors with positive or symbolic exponents: first any product of
  // two of them made already (by an earlier product, whatever its order), then the rest in
  // register order, so that products sharing factors share partial products.
  Signed product(GiNaC::exvector factors) {
    sort_reproducibly(factors);
    std::vector<Value> values;
    bool negative = false;
    for (const ex& f : factors) {
      const Signed v = signed_value(f);
      values.push_back(v.value);
      negative = negative != v.negative;
    }
    std::sort(values.begin(), values.end());
    while (values.size() > 2 && take_made_pair(values)) std::sort(values.begin(), values.end());
    Value p = values.front();
    for (std::size_t i = 1; i < values.size(); ++i) p = emit(TapeOp::mul, p, values[i]);
    return {p, negative};
  }

  // The first pair of `values` (in their order) whose product an instruction makes already:
  // replaced by that product. Whether there was one.
  bool take_made_pair(std::vector<Value>& values) const {
    for (std::size_t i = 0; i < values.size(); ++i) {
      for (std::size_t j = i + 1; j < values.size(); ++j) {
        const auto made = numbering_.find(std::make_tuple(
            TapeOp::mul, std::min(values[i], values[j]), std::max(values[i], values[j])));
        if (made == numbering_.end()) continue;
        values[i] = made->second;
        values.erase(values.begin() + static_cast<std::ptrdiff_t>(j));
        return true;
      }
    }
    return false;
  }

  // base^exponent: integer and half-integer exponents by multiplication and sqrt, else std::pow;
  // an integer power of a negated value is its power, negated when the exponent is odd.
  Signed compile_power(const ex& e) {
    const ex exponent = e.op(1);
    if (!is_exactly_a<GiNaC::numeric>(exponent))
      return {emit(TapeOp::pow, compile(e.op(0)), compile(exponent))};
    const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(exponent);
    if (!n.is_real()) fail("complex number", exponent);
    const double d = n.to_double();
    const double twice = 2.0 * d;
    if (std::floor(twice) != twice || std::fabs(twice) > 2.0 * kMaxMultipliedPower)
      return {emit(TapeOp::pow, compile(e.op(0)), constant(d))};
    const auto halves = static_cast<long>(twice);
    const Signed base = signed_value(e.op(0));
    if (halves % 2 != 0) {
      const Value root = half_power(plain(base), std::labs(halves));
      return {halves < 0 ? emit(TapeOp::recip, root) : root};
    }
    const long k = halves / 2;
    const Value power = integer_power(base.value, std::labs(k));
    return {k < 0 ? emit(TapeOp::recip, power) : power, base.negative && k % 2 != 0};
  }

  // base^(halves/2) for halves > 0: x^k or x^k · √x.
  Value half_power(Value base, long halves) {
    if (halves % 2 == 0) return integer_power(base, halves / 2);
    const Value root = emit(TapeOp::sqrt, base);
    if (halves == 1) return root;
    return emit(TapeOp::mul, integer_power(base, halves / 2), root);
  }

  // base^n for n ≥ 1 by repeated squaring; value numbering shares the partial powers.
  Value integer_power(Value base, long n) {
    if (n == 1) return base;
    if (n % 2 == 1) return emit(TapeOp::mul, integer_power(base, n - 1), base);
    const Value half = integer_power(base, n / 2);
    return emit(TapeOp::mul, half, half);
  }

  // One of the supported functions, by GiNaC name.
  Value compile_function(const ex& e) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    const auto op = function_op(name);
    if (!op) fail("unsupported function " + name, e);
    if (e.nops() != op->second) fail("wrong number of arguments to " + name, e);
    const Value a = compile(e.op(0));
    return emit(op->first, a, op->second == 2 ? compile(e.op(1)) : a);
  }

  // A constant register, one per distinct value.
  Value constant(double v) {
    const auto bits = std::bit_cast<std::uint64_t>(v);
    const auto [found, fresh] =
        constant_index_.emplace(bits, static_cast<std::uint32_t>(constants_.size()));
    if (fresh) constants_.push_back(v);
    return {Value::Kind::constant, found->second};
  }

  // Append an instruction unless its operands are constants (folded) or the same instruction
  // exists already (value numbering; operands of + and × in canonical order).
  Value emit(TapeOp op, Value a, Value b) {
    if (a.kind == Value::Kind::constant && b.kind == Value::Kind::constant)
      return constant(fold(op, constants_[a.index], constants_[b.index]));
    if ((op == TapeOp::add || op == TapeOp::mul) && b < a) std::swap(a, b);
    const auto key = std::make_tuple(op, a, b);
    if (const auto found = numbering_.find(key); found != numbering_.end()) return found->second;
    const Value v{Value::Kind::temp, temp_count_++};
    nodes_.push_back(Node{op, a, b, v.index});
    numbering_.emplace(key, v);
    return v;
  }
  Value emit(TapeOp op, Value a) { return emit(op, a, a); }

  // Terms or factors in the order of their stable keys (ties keep GiNaC's order).
  void sort_reproducibly(std::vector<ex>& operands) {
    std::stable_sort(operands.begin(), operands.end(),
                     [this](const ex& a, const ex& b) { return stable_key(a) < stable_key(b); });
  }

  // A hash of e's structure that, unlike GiNaC's (which depends on where the library is loaded),
  // is the same in every run: compiling sums and products in its order makes the tape, and so
  // every rounding, reproducible from run to run.
  std::uint64_t stable_key(const ex& e) { return signed_key(e).first; }

  // The stable key of e blind to its sign, and that sign: x and −x, x (a − b) and −x (b − a)
  // have one key and opposite signs, as the compiled values have one register and opposite
  // flags. A sum's sign is that of its term of least key; its key holds its terms' keys and
  // their signs relative to that one (a − b and a + b differ).
  std::pair<std::uint64_t, int> signed_key(const ex& e) {
    if (const auto found = keys_.find(e); found != keys_.end()) return found->second;
    std::uint64_t key = hash_text(GiNaC::ex_to<GiNaC::basic>(e).class_name());
    int sign = 1;
    if (is_exactly_a<GiNaC::numeric>(e)) {
      const GiNaC::numeric& n = GiNaC::ex_to<GiNaC::numeric>(e);
      key = mix(key, hash_text(str(GiNaC::abs(n))));
      sign = n.is_negative() ? -1 : 1;
    } else if (is_a<GiNaC::symbol>(e) || is_exactly_a<GiNaC::constant>(e)) {
      key = mix(key, hash_text(str(e)));
    } else if (is_exactly_a<GiNaC::add>(e)) {
      std::vector<std::pair<std::uint64_t, int>> terms;
      for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(signed_key(e.op(i)));
      std::sort(terms.begin(), terms.end());
      sign = terms.front().second;
      for (const auto& [k, s] : terms) key = mix(mix(key, k), s == sign ? 1 : 2);
    } else if (is_exactly_a<GiNaC::mul>(e)) {
      // a product's ±1 is no factor; −x has x's key
      std::vector<std::uint64_t> factors;
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const ex f = e.op(i);
        const auto [k, s] = signed_key(f);
        sign *= s;
        const bool unit = is_exactly_a<GiNaC::numeric>(f) &&
                          GiNaC::abs(GiNaC::ex_to<GiNaC::numeric>(f)).is_equal(1);
        if (!unit) factors.push_back(k);
      }
      std::sort(factors.begin(), factors.end());
      if (factors.size() == 1) {
        key = factors.front();
      } else {
        for (const std::uint64_t k : factors) key = mix(key, k);
      }
    } else if (is_exactly_a<GiNaC::power>(e)) {
      // an integer power of −x is ± that of x; any other is another value
      const auto [base, base_sign] = signed_key(e.op(0));
      const ex exponent = e.op(1);
      key = mix(mix(key, base), stable_key(exponent));
      if (exponent.info(GiNaC::info_flags::odd)) {
        sign = base_sign;
      } else if (!exponent.info(GiNaC::info_flags::even)) {
        key = mix(key, base_sign > 0 ? 1 : 2);
      }
    } else {
      // a function of −x is another value
      if (is_a<GiNaC::function>(e))
        key = mix(key, hash_text(GiNaC::ex_to<GiNaC::function>(e).get_name()));
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const auto [k, s] = signed_key(e.op(i));
        key = mix(mix(key, k), s > 0 ? 1 : 2);
      }
    }
    keys_.emplace(e, std::make_pair(key, sign));
    return {key, sign};
  }

  std::unordered_map<ex, std::uint32_t, std::hash<ex>, GiNaC::ex_is_equal> inputs_;
  std::unordered_map<ex, std::pair<std::uint64_t, int>, std::hash<ex>, GiNaC::ex_is_equal> keys_;
  std::unordered_map<ex, Signed, std::hash<ex>, GiNaC::ex_is_equal> memo_;
  std::map<std::tuple<TapeOp, Value, Value>, Value> numbering_;
  std::unordered_map<std::uint64_t, std::uint32_t> constant_index_;
  std::vector<double> constants_;
  std::vector<Node> nodes_;
  std::uint32_t temp_count_ = 0;
};

}  // namespace

void TapeWorkspace::reserve(const Tape& tape) {
  if (registers_.size() < tape.register_count()) registers_.resize(tape.register_count());
}

Tape Tape::compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs) {
  // Pass 0: fewer multiplications (the bicycle's M, f, A, b: 2 827 → 2 098 operations).
  const std::vector<GiNaC::ex> factored = horner_form(outputs);
  // Pass 1, one output at a time so that errors can say which.
  Builder builder(inputs);
  std::vector<Value> values;
  for (std::size_t k = 0; k < factored.size(); ++k) {
    try {
      values.push_back(builder.compile(factored[k]));
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string(error.what()) + " (in output " + std::to_string(k) +
                                  ")");
    }
  }
  // Passes 2–4.
  std::vector<Node>& nodes = builder.nodes();
  detail::fuse_sincos(nodes);
  detail::remove_dead(nodes, values, builder.temp_count());
  Program program = detail::allocate_registers(inputs.size(), builder.constants(), nodes, values,
                                               builder.temp_count());
  // The tape itself.
  Tape tape;
  for (const ex& s : inputs) tape.input_names_.push_back(GiNaC::ex_to<GiNaC::symbol>(s).get_name());
  tape.constants_ = std::move(program.constants);
  tape.instructions_ = std::move(program.instructions);
  tape.output_registers_ = std::move(program.outputs);
  tape.register_count_ = program.register_count;
  return tape;
}

void Tape::evaluate(std::span<const double> inputs, std::span<double> outputs,
                    TapeWorkspace& workspace) const {
  if (inputs.size() != input_count() || outputs.size() != output_count())
    throw std::invalid_argument("Tape::evaluate: expected " + std::to_string(input_count()) +
                                " inputs and " + std::to_string(output_count()) + " outputs, got " +
                                std::to_string(inputs.size()) + " and " +
                                std::to_string(outputs.size()));
  workspace.reserve(*this);
  double* r = workspace.registers_.data();
  // Load inputs and constants, run the program, gather the outputs.
  std::copy(inputs.begin(), inputs.end(), r);
  std::copy(constants_.begin(), constants_.end(), r + input_count());
  for (const TapeInstruction& i : instructions_) detail::execute(i, r);
  for (std::size_t k = 0; k < outputs.size(); ++k) outputs[k] = r[output_registers_[k]];
}

std::vector<double> Tape::evaluate(std::span<const double> inputs) const {
  std::vector<double> outputs(output_count());
  TapeWorkspace workspace(*this);
  evaluate(inputs, outputs, workspace);
  return outputs;
}

std::string Tape::listing() const {
  std::ostringstream os;
  os.precision(17);
  os << "tape: " << input_count() << " inputs, " << output_count() << " outputs, "
     << instruction_count() << " instructions, " << register_count() << " registers\n";
  // Inputs and constants, then the program, then where the outputs are.
  for (std::size_t i = 0; i < input_count(); ++i)
    os << "  r" << i << " = input " << input_names_[i] << '\n';
  for (std::size_t k = 0; k < constants_.size(); ++k)
    os << "  r" << input_count() + k << " = " << constants_[k] << '\n';
  for (const TapeInstruction& i : instructions_) {
    os << "  r" << i.dst;
    if (i.op == TapeOp::sincos) os << ", r" << i.b;
    os << " = " << op_name(i.op) << " r" << i.a;
    if (detail::is_binary(i.op)) os << ", r" << i.b;
    os << '\n';
  }
  for (std::size_t k = 0; k < output_count(); ++k)
    os << "  out" << k << " = r" << output_registers_[k] << '\n';
  return os.str();
}

}  // namespace unidyn
