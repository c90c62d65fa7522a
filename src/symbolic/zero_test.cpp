// Zero testing by exact evaluation at random points: modular arithmetic, the circle parametrised.
//
// The arithmetic is that of the field GF(p), p = 2⁶¹ − 1 (a rational a/b is a·b⁻¹ mod p), and, for
// the sines and cosines, GF(p²) = GF(p)[i], i² = −1 (p ≡ 3 mod 4, so −1 has no root in GF(p)):
// cos x + i sin x of x = Σ n_k u_k + m π/2 is i^m Π (cos u_k + i sin u_k)^(n_k). A rational value
// that is not 0 mod p is not 0; a rational that is 0 mod p but not 0 is hit with probability 1/p.
#include "unidyn/symbolic/zero_test.hpp"

#include <map>
#include <random>
#include <set>
#include <unordered_map>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/process_map.hpp"

namespace unidyn {
namespace {

using GiNaC::is_a;
using GiNaC::is_exactly_a;
using GiNaC::numeric;

__extension__ using Wide = unsigned __int128;

constexpr std::uint64_t kPrime = (std::uint64_t{1} << 61) - 1;

std::uint64_t add_mod(std::uint64_t a, std::uint64_t b) {
  const std::uint64_t s = a + b;
  return s >= kPrime ? s - kPrime : s;
}

std::uint64_t sub_mod(std::uint64_t a, std::uint64_t b) {
  return a >= b ? a - b : a + kPrime - b;
}

std::uint64_t mul_mod(std::uint64_t a, std::uint64_t b) {
  const Wide product = static_cast<Wide>(a) * b;
  // 2⁶¹ ≡ 1 (mod p): the high and low 61 bits add
  const std::uint64_t low = static_cast<std::uint64_t>(product) & kPrime;
  const std::uint64_t high = static_cast<std::uint64_t>(product >> 61);  // < 2⁶¹
  const std::uint64_t sum = low + high;                                  // < 2⁶²
  return add_mod(sum & kPrime, sum >> 61);
}

std::uint64_t pow_mod(std::uint64_t a, std::uint64_t n) {
  std::uint64_t result = 1;
  for (; n > 0; n >>= 1, a = mul_mod(a, a)) {
    if (n & 1) result = mul_mod(result, a);
  }
  return result;
}

// a⁻¹ = a^(p − 2) (Fermat); none for 0
std::optional<std::uint64_t> inverse_mod(std::uint64_t a) {
  if (a == 0) return std::nullopt;
  return pow_mod(a, kPrime - 2);
}

// An integer of any size mod p.
std::uint64_t integer_mod(const numeric& n) {
  const numeric r = GiNaC::mod(n, numeric(static_cast<long>(kPrime)));  // in [0, p)
  return static_cast<std::uint64_t>(r.to_long());
}

// A rational number mod p; none for a denominator divisible by p or a number that is not rational.
std::optional<std::uint64_t> rational_mod(const numeric& x) {
  if (!x.is_rational()) return std::nullopt;
  const auto inverse = inverse_mod(integer_mod(x.denom()));
  if (!inverse) return std::nullopt;
  return mul_mod(integer_mod(x.numer()), *inverse);
}

// cos + i sin in GF(p²)
struct Turn {
  std::uint64_t c = 1, s = 0;
  Turn operator*(const Turn& o) const {
    return {sub_mod(mul_mod(c, o.c), mul_mod(s, o.s)), add_mod(mul_mod(c, o.s), mul_mod(s, o.c))};
  }
};

Turn power(Turn z, std::int64_t n) {
  if (n < 0) {
    z.s = sub_mod(0, z.s);  // on the circle, z⁻¹ is the conjugate
    n = -n;
  }
  Turn result;
  for (; n > 0; n >>= 1, z = z * z) {
    if (n & 1) result = result * z;
  }
  return result;
}

// The numeric factor of a term and the rest: 3 q → (3, q).
std::pair<numeric, Expr> split_coefficient(const Expr& term) {
  if (is_a<numeric>(term)) return {GiNaC::ex_to<numeric>(term), 1};
  if (!is_exactly_a<GiNaC::mul>(term)) return {1, term};
  numeric c = 1;
  Expr rest = 1;
  for (std::size_t i = 0; i < term.nops(); ++i) {
    if (is_a<numeric>(term.op(i))) {
      c *= GiNaC::ex_to<numeric>(term.op(i));
    } else {
      rest *= term.op(i);
    }
  }
  return {c, rest};
}

// An angle u: a symbol or a product of powers of symbols (Ω t).
bool is_angle_atom(const Expr& e) {
  if (is_a<GiNaC::symbol>(e)) return true;
  if (is_exactly_a<GiNaC::power>(e)) {
    return is_a<GiNaC::symbol>(e.op(0)) && e.op(1).info(GiNaC::info_flags::posint);
  }
  if (!is_exactly_a<GiNaC::mul>(e)) return false;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (!is_angle_atom(e.op(i))) return false;
  }
  return true;
}

void collect_symbols(const Expr& e, std::set<Expr, GiNaC::ex_is_less>& out) {
  if (is_a<GiNaC::symbol>(e)) out.insert(e);
  for (std::size_t i = 0; i < e.nops(); ++i) collect_symbols(e.op(i), out);
}

bool is_trig(const Expr& e) {
  return GiNaC::is_the_function<GiNaC::sin_SERIAL>(e) ||
         GiNaC::is_the_function<GiNaC::cos_SERIAL>(e) ||
         GiNaC::is_the_function<GiNaC::tan_SERIAL>(e);
}

// What an expression is made of: its sines, cosines and tangents, the symbols outside them and
// all its symbols; each shared node visited once.
struct Parts {
  GiNaC::exset trig;
  std::set<Expr, GiNaC::ex_is_less> outside_symbols, symbols;

  explicit Parts(const Expr& e) { visit(e, false); }

 private:
  void visit(const Expr& e, bool inside_trig) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (!visited_[inside_trig].emplace(node, e).second) return;
    if (is_a<GiNaC::symbol>(e)) {
      symbols.insert(e);
      if (!inside_trig) outside_symbols.insert(e);
      return;
    }
    const bool trig_here = is_trig(e);
    if (trig_here) trig.insert(e);
    for (std::size_t i = 0; i < e.nops(); ++i) visit(e.op(i), inside_trig || trig_here);
  }

  // the nodes seen outside and inside the trigonometric functions (held: see Evaluator)
  std::unordered_map<const GiNaC::basic*, Expr> visited_[2];
};

struct CanonicalLess {
  bool operator()(const Expr& a, const Expr& b) const { return canonical_less(a, b); }
};

// A trigonometric argument Σ n_k (u_k / L_k) + m π/2: n_k integers (in the unit u_k / L_k).
struct Argument {
  std::map<Expr, numeric, CanonicalLess> multiples;  // u_k → its coefficient (rational)
  numeric quarter_turns = 0;
};

// The argument decomposed, or none when it is not such a combination.
std::optional<Argument> decompose(const Expr& argument) {
  const Expr x = GiNaC::expand(argument);
  Argument a;
  const auto add_term = [&](const Expr& term) {
    const auto [c, rest] = split_coefficient(term);
    if (!c.is_rational()) return false;
    if (rest.is_equal(1)) return c.is_zero();
    if (rest.is_equal(GiNaC::Pi)) {
      a.quarter_turns += 2 * c;
      return (2 * c).is_integer();
    }
    if (!is_angle_atom(rest)) return false;
    a.multiples[rest] += c;
    return true;
  };
  if (is_exactly_a<GiNaC::add>(x)) {
    for (std::size_t i = 0; i < x.nops(); ++i) {
      if (!add_term(x.op(i))) return std::nullopt;
    }
  } else if (!add_term(x)) {
    return std::nullopt;
  }
  return a;
}

// The values of an expression at a batch of points: one per point, and which points it is
// defined at (not at one where a denominator is 0).
struct Values {
  std::vector<std::uint64_t> at;
  std::vector<bool> defined;
};

using PointValues =
    std::unordered_map<Expr, std::vector<std::uint64_t>, ExprHash, GiNaC::ex_is_equal>;

// The expression at a batch of points, by its nodes (shared nodes once, each visited once for all
// the points); none where it cannot be evaluated exactly.
class Evaluator {
 public:
  Evaluator(const PointValues& symbols, const PointValues& functions, std::size_t points)
      : symbols_(symbols), functions_(functions), points_(points) {}

  std::optional<Values> operator()(const Expr& e) {
    const GiNaC::basic* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(node); it != memo_.end()) return it->second.second;
    std::optional<Values> value = evaluate(e);
    // the node held, so that its address is not reused by another (op() makes some anew)
    return memo_.emplace(node, std::make_pair(e, std::move(value))).first->second.second;
  }

 private:
  // the same value at every point
  Values constant(std::uint64_t v) const {
    return {std::vector<std::uint64_t>(points_, v), std::vector<bool>(points_, true)};
  }

  std::optional<Values> evaluate(const Expr& e) {
    if (is_a<numeric>(e)) {
      const auto value = rational_mod(GiNaC::ex_to<numeric>(e));
      if (!value) return std::nullopt;
      return constant(*value);
    }
    if (is_a<GiNaC::symbol>(e) || is_a<GiNaC::function>(e)) {
      const auto& table = is_a<GiNaC::symbol>(e) ? symbols_ : functions_;
      const auto it = table.find(e);
      if (it == table.end()) return std::nullopt;
      return Values{it->second, std::vector<bool>(points_, true)};
    }
    if (is_exactly_a<GiNaC::add>(e) || is_exactly_a<GiNaC::mul>(e)) {
      const bool sum = is_exactly_a<GiNaC::add>(e);
      Values result = constant(sum ? 0 : 1);
      for (std::size_t i = 0; i < e.nops(); ++i) {
        const auto term = (*this)(e.op(i));
        if (!term) return std::nullopt;
        for (std::size_t k = 0; k < points_; ++k) {
          result.at[k] =
              sum ? add_mod(result.at[k], term->at[k]) : mul_mod(result.at[k], term->at[k]);
          result.defined[k] = result.defined[k] && term->defined[k];
        }
      }
      return result;
    }
    if (is_exactly_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::integer)) {
      auto base = (*this)(e.op(0));
      if (!base) return std::nullopt;
      const numeric n = GiNaC::ex_to<numeric>(e.op(1));
      const auto exponent = static_cast<std::uint64_t>(GiNaC::abs(n).to_long());
      for (std::size_t k = 0; k < points_; ++k) {
        std::uint64_t& v = base->at[k];
        if (!n.is_pos_integer()) {
          const auto inverse = inverse_mod(v);
          if (!inverse) base->defined[k] = false;
          v = inverse.value_or(0);
        }
        v = pow_mod(v, exponent);
      }
      return base;
    }
    return std::nullopt;  // radicals, other functions, constants
  }

  const PointValues& symbols_;
  const PointValues& functions_;
  std::size_t points_;
  std::unordered_map<const GiNaC::basic*, std::pair<Expr, std::optional<Values>>> memo_;
};

}  // namespace

std::optional<bool> vanishes_identically(const Expr& e, int points) {
  // the sines, cosines and tangents, and their arguments decomposed into angles
  const Parts parts(e);
  const GiNaC::exset& trig = parts.trig;
  std::map<Expr, Argument, CanonicalLess> arguments;
  std::map<Expr, numeric, CanonicalLess> units;  // angle u → L: its unit is u / L
  for (const Expr& f : trig) {
    const auto a = decompose(f.op(0));
    if (!a) return std::nullopt;
    for (const auto& [u, c] : a->multiples) {
      numeric& L = units.emplace(u, 1).first->second;
      L = GiNaC::lcm(L, c.denom());
    }
    arguments.emplace(f.op(0), *a);
  }
  // each angle with a symbol of its own: in it to the first power, in no other angle and nowhere
  // outside the trigonometric functions (t of Ω t, Ω being anywhere): the angle's value then fixes
  // that symbol's alone, and the others keep values of their own
  std::map<Expr, int, GiNaC::ex_is_less> in_angles;
  std::vector<std::set<Expr, GiNaC::ex_is_less>> angle_parts;
  for (const auto& [u, L] : units) {
    angle_parts.emplace_back();
    collect_symbols(u, angle_parts.back());
    for (const Expr& x : angle_parts.back()) ++in_angles[x];
  }
  std::set<Expr, GiNaC::ex_is_less> angle_symbols;
  std::size_t k = 0;
  for (const auto& [u, L] : units) {
    bool found = false;
    for (const Expr& x : angle_parts[k]) {
      if (in_angles[x] == 1 && parts.outside_symbols.count(x) == 0 && u.degree(x) == 1) {
        angle_symbols.insert(x);
        found = true;
        break;
      }
    }
    if (!found) return std::nullopt;
    ++k;
  }
  std::set<Expr, CanonicalLess> others;  // the symbols given values of their own, in a fixed order
  for (const Expr& s : parts.symbols) {
    if (angle_symbols.count(s) == 0) others.insert(s);
  }

  // random points: τ = a/b of each unit angle, a value a/b of each other symbol
  std::mt19937_64 engine(0x5eed'0f'7e57ULL);
  std::uniform_int_distribution<std::int64_t> numerator(-(std::int64_t{1} << 40),
                                                        std::int64_t{1} << 40);
  std::uniform_int_distribution<std::int64_t> denominator(1, std::int64_t{1} << 40);
  const auto random_rational = [&] { return numeric(numerator(engine)) / denominator(engine); };
  // batches of points until `points` of them are defined, at most 4 × points drawn
  int evaluated = 0, drawn = 0;
  while (evaluated < points && drawn < 4 * points) {
    const auto batch = static_cast<std::size_t>(std::min(points - evaluated, 4 * points - drawn));
    drawn += static_cast<int>(batch);
    PointValues symbols, functions;
    std::vector<bool> defined(batch, true);
    for (std::size_t point = 0; point < batch; ++point) {
      for (const Expr& s : others) symbols[s].push_back(*rational_mod(random_rational()));
      std::map<Expr, Turn, CanonicalLess> unit_turns;
      for (const auto& [u, L] : units) {
        const auto tau = rational_mod(random_rational());
        const std::uint64_t t2 = mul_mod(*tau, *tau);
        const auto scale = inverse_mod(add_mod(1, t2));
        if (!scale) defined[point] = false;
        unit_turns[u] = {mul_mod(sub_mod(1, t2), scale.value_or(0)),
                         mul_mod(mul_mod(2, *tau), scale.value_or(0))};
      }
      for (const Expr& f : trig) {
        const Argument& a = arguments.at(f.op(0));
        Turn z = power(Turn{0, 1}, GiNaC::mod(a.quarter_turns, 4).to_long());
        for (const auto& [u, c] : a.multiples) {
          z = z * power(unit_turns.at(u), (c * units.at(u)).to_long());
        }
        std::uint64_t value = z.c;
        if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(f)) {
          value = z.s;
        } else if (!GiNaC::is_the_function<GiNaC::cos_SERIAL>(f)) {
          const auto inverse = inverse_mod(z.c);
          if (!inverse) defined[point] = false;
          value = mul_mod(z.s, inverse.value_or(0));
        }
        functions[f].push_back(value);
      }
    }
    // not exactly evaluable: no answer; undefined at a point (a denominator 0): another point
    Evaluator evaluate(symbols, functions, batch);
    const auto values = evaluate(e);
    if (!values) return std::nullopt;
    for (std::size_t point = 0; point < batch; ++point) {
      if (!defined[point] || !values->defined[point]) continue;
      if (values->at[point] != 0) return false;
      ++evaluated;
    }
  }
  if (evaluated < points) return std::nullopt;
  return true;
}

bool identically_zero(const Expr& e) {
  if (const auto decided = vanishes_identically(e)) return *decided;
  return simplify(e).is_zero();
}

}  // namespace unidyn

namespace unidyn {
namespace {

// vanishes_identically(e) as a number to travel between processes: 1 true, 0 false, −1 undecided.
Expr vanishes_as_number(const Expr& e) {
  const std::optional<bool> zero = vanishes_identically(e);
  return zero ? Expr(*zero ? 1 : 0) : Expr(-1);
}

}  // namespace

std::vector<std::optional<bool>> vanish_identically(const std::vector<Expr>& es) {
  std::vector<std::optional<bool>> out;
  for (const Expr& answer : map_in_processes(es, vanishes_as_number)) {
    out.push_back(answer.is_equal(-1) ? std::nullopt : std::optional<bool>(answer.is_equal(1)));
  }
  return out;
}

}  // namespace unidyn
