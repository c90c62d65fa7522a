// Text and LaTeX of expressions with sums, products and signs in a canonical order.
#include "unidyn/symbolic/canonical_text.hpp"

#include "unidyn/symbolic/expairs.hpp"

#include <algorithm>
#include <map>
#include <memory>
#include <sstream>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

namespace unidyn {
namespace {

using GiNaC::is_exactly_a;

// GiNaC's precedences: a sum, a product and a power are parenthesised inside anything that binds
// at least as tightly.
constexpr unsigned kAdd = 40, kMul = 50, kPower = 60, kAtom = 70;

bool is_half(const Expr& x) {
  return x.is_equal(GiNaC::numeric(1, 2));
}
bool is_negative_number(const Expr& x) {
  return is_exactly_a<GiNaC::numeric>(x) && GiNaC::ex_to<GiNaC::numeric>(x).is_negative();
}
bool is_odd(const Expr& x) {
  return x.info(GiNaC::info_flags::odd);
}
// A sum raised to an integer power, whose sign can be taken out of its base.
bool is_power_of_sum(const Expr& e) {
  return is_exactly_a<GiNaC::power>(e) && is_exactly_a<GiNaC::add>(e.op(0)) &&
         e.op(1).info(GiNaC::info_flags::integer);
}

// A product split into its number and its other factors; anything else is 1 × itself.
struct Split {
  GiNaC::numeric coefficient = 1;
  std::vector<Expr> factors;
};
Split split(const Expr& e) {
  Split s;
  if (is_exactly_a<GiNaC::mul>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const Expr factor = e.op(i);
      if (is_exactly_a<GiNaC::numeric>(factor)) {
        s.coefficient *= GiNaC::ex_to<GiNaC::numeric>(factor);
      } else {
        s.factors.push_back(factor);
      }
    }
  } else if (is_exactly_a<GiNaC::numeric>(e)) {
    s.coefficient = GiNaC::ex_to<GiNaC::numeric>(e);
  } else {
    s.factors.push_back(e);
  }
  return s;
}

class Printer {
 public:
  // SymPy's notation: the text one with ** for powers, Abs, pi, and the names of
  // symbolic/canonical_text.hpp's sympy_name.
  enum class Style { text, latex, sympy };
  explicit Printer(Style style) : latex_(style == Style::latex), sympy_(style == Style::sympy) {}

  // e inside something of precedence `level` (0: alone).
  std::string print(const Expr& e, unsigned level) {
    if (is_exactly_a<GiNaC::numeric>(e)) return number(GiNaC::ex_to<GiNaC::numeric>(e), level);
    if (is_power_of_sum(e) && sign_of(e) < 0) {
      // −(b − a)^3 for (a − b)^3: a negative term
      const std::string text = "-" + power(e);
      return kAdd <= level ? open() + text + close() : text;
    }
    const auto key = std::make_pair(node(e), level);
    if (const auto found = memo_.find(key); found != memo_.end()) return found->second;
    std::string text = body(e);
    if (precedence(e) <= level) text = open() + text + close();
    memo_.emplace(key, text);
    return text;
  }

  // How many nodes the memos hold.
  std::size_t nodes_kept() const { return keep_.size(); }

  // The sign GiNaC chose for e, against the canonical one: −1 for a sum whose first term in the
  // canonical order has a negative number, and for an odd power of such a sum; else 1.
  int sign_of(const Expr& e) {
    if (is_exactly_a<GiNaC::add>(e))
      return parts(e).terms.front().coefficient.is_negative() ? -1 : 1;
    if (is_power_of_sum(e) && is_odd(e.op(1))) return sign_of(e.op(0));
    return 1;
  }

 private:
  struct Term {
    std::string rest;
    GiNaC::numeric coefficient;
  };
  // A sum's constant and its other terms in the canonical order, each as its number times the
  // canonical text of the rest (the signs of sums inside the rest moved into the number).
  struct Parts {
    GiNaC::numeric constant = 0;
    std::vector<Term> terms;
  };

  // The node of e, kept alive: GiNaC makes a sum's terms and a product's factors on request, and a
  // temporary's address could otherwise come back as another expression's in the memos.
  const GiNaC::basic* node(const Expr& e) {
    const GiNaC::basic* n = &GiNaC::ex_to<GiNaC::basic>(e);
    if (kept_.insert(n).second) keep_.push_back(e);
    return n;
  }

  // How many primes end the name of a symbol in e (2 at most): 1 for a rate q', 2 for an
  // acceleration q'' (symbolic/coordinates.hpp names them so); remembered for each node.
  int derivative_order(const Expr& e) {
    if (GiNaC::is_a<GiNaC::symbol>(e)) {
      const std::string& name = GiNaC::ex_to<GiNaC::symbol>(e).get_name();
      int primes = 0;
      while (primes < 2 && name.size() > std::size_t(primes) &&
             name[name.size() - 1 - std::size_t(primes)] == '\'') {
        ++primes;
      }
      return primes;
    }
    if (e.nops() == 0) return 0;
    const GiNaC::basic* key = node(e);
    if (const auto found = orders_.find(key); found != orders_.end()) return found->second;
    int order = 0;
    for (std::size_t i = 0; i < e.nops(); ++i) order = std::max(order, derivative_order(e.op(i)));
    orders_.emplace(key, order);
    return order;
  }

  // Where a factor goes in a product, as a book writes it: sums, then parameters and coordinates,
  // then functions (sin θ), then what has rates, then what has accelerations:
  // (m1 + m2) l1² cos θ1 θ̇1 θ̈2.
  int factor_rank(const Expr& f) {
    if (const int order = derivative_order(f); order > 0) return 2 + order;
    if (is_exactly_a<GiNaC::add>(f)) return 0;
    const Expr base = is_exactly_a<GiNaC::power>(f) ? f.op(0) : f;
    return is_exactly_a<GiNaC::function>(base) ? 2 : 1;
  }

  std::string open() const { return latex_ ? "\\left(" : "("; }
  std::string close() const { return latex_ ? "\\right)" : ")"; }

  static unsigned precedence(const Expr& e) {
    if (is_exactly_a<GiNaC::add>(e)) return kAdd;
    if (is_exactly_a<GiNaC::mul>(e)) return kMul;
    if (is_exactly_a<GiNaC::power>(e)) return is_half(e.op(1)) ? kAtom : kPower;
    return kAtom;
  }

  // GiNaC's own text of an atom (a number, a symbol, a constant).
  std::string atom(const Expr& e) const {
    if (sympy_ && GiNaC::is_a<GiNaC::symbol>(e)) {
      return sympy_name(GiNaC::ex_to<GiNaC::symbol>(e).get_name());
    }
    if (sympy_ && e.is_equal(GiNaC::Pi)) return "pi";
    std::ostringstream out;
    if (latex_) out << GiNaC::latex;
    out << e;
    return out.str();
  }

  // A number, parenthesised inside a product or a power when negative or not an integer.
  std::string number(const GiNaC::numeric& n, unsigned level) const {
    const std::string text = atom(n);
    const bool wrap = level >= kMul && (n.is_negative() || !n.is_integer());
    return wrap ? open() + text + close() : text;
  }

  // The magnitude of a coefficient before its factors: "1/2*", "3*", "(0.5)*" (LaTeX: a space).
  std::string magnitude(const GiNaC::numeric& a) const {
    if (a.is_equal(1)) return "";
    const std::string text = a.is_rational() ? atom(a) : open() + atom(a) + close();
    return text + (latex_ ? " " : "*");
  }

  std::string body(const Expr& e) {
    if (is_exactly_a<GiNaC::add>(e)) return sum(parts(e), false);
    if (is_exactly_a<GiNaC::mul>(e)) return product(e);
    if (is_exactly_a<GiNaC::power>(e)) return power(e);
    if (is_exactly_a<GiNaC::function>(e)) return function(e);
    return atom(e);
  }

  const Parts& parts(const Expr& e) {
    const GiNaC::basic* key = node(e);
    if (const auto found = parts_.find(key); found != parts_.end()) return *found->second;
    auto p = std::make_unique<Parts>();
    for (std::size_t i = 0; i < e.nops(); ++i) {
      const Split s = split(e.op(i));
      if (s.factors.empty()) {
        p->constant += s.coefficient;
        continue;
      }
      const auto [text, sign] = rest(s.factors);
      p->terms.push_back({text, s.coefficient * sign});
    }
    std::sort(p->terms.begin(), p->terms.end(), [](const Term& a, const Term& b) {
      if (a.rest != b.rest) return a.rest < b.rest;
      return a.coefficient.compare(b.coefficient) < 0;
    });
    return *parts_.emplace(key, std::move(p)).first->second;
  }

  // Constant first, then the terms; all of them negated when `negate`.
  std::string sum(const Parts& p, bool negate) const {
    const int s = negate ? -1 : 1;
    std::string text = p.constant.is_zero() ? "" : atom(p.constant * s);
    for (const Term& t : p.terms) {
      const GiNaC::numeric c = t.coefficient * s;
      if (c.is_negative()) {
        text += "-";
      } else if (!text.empty()) {
        text += "+";
      }
      text += magnitude(GiNaC::abs(c)) + t.rest;
    }
    return text;
  }

  // A factor in its canonical sign, and that sign: a sum (or the base of an integer power of one)
  // whose first term is negative is printed negated.
  std::pair<std::string, int> factor(const Expr& f) {
    if (is_exactly_a<GiNaC::add>(f) && sign_of(f) < 0) {
      return {open() + sum(parts(f), true) + close(), -1};
    }
    if (is_power_of_sum(f) && sign_of(f.op(0)) < 0) return {power(f), sign_of(f)};
    return {print(f, kMul), 1};
  }

  // Factors sorted by their own text, joined by * (LaTeX: a space), and the product of their
  // signs.
  std::pair<std::string, int> factors_text(const std::vector<Expr>& factors) {
    std::vector<std::pair<int, std::string>> texts;
    int sign = 1;
    for (const Expr& f : factors) {
      auto [text, s] = factor(f);
      texts.emplace_back(factor_rank(f), std::move(text));
      sign *= s;
    }
    std::sort(texts.begin(), texts.end());
    std::string text;
    for (const auto& [rank, t] : texts) text += (text.empty() ? "" : (latex_ ? " " : "*")) + t;
    return {text, sign};
  }

  // The factors of a term without its number: one factor alone, several as a product (LaTeX: a
  // fraction when some have negative exponents); and the sign taken out of them.
  std::pair<std::string, int> rest(const std::vector<Expr>& factors) {
    if (factors.size() == 1 && !is_exactly_a<GiNaC::add>(factors.front()) &&
        !is_power_of_sum(factors.front()) &&
        !(latex_ && is_exactly_a<GiNaC::power>(factors.front()))) {
      return {print(factors.front(), kAdd), 1};
    }
    if (!latex_) return factors_text(factors);
    std::vector<Expr> above, below;
    for (const Expr& f : factors) {
      if (is_exactly_a<GiNaC::power>(f) && is_negative_number(f.op(1))) {
        below.push_back(GiNaC::pow(f.op(0), -f.op(1)));
      } else {
        above.push_back(f);
      }
    }
    auto [top, top_sign] = factors_text(above);
    if (below.empty()) return {top, top_sign};
    const auto [bottom, bottom_sign] = factors_text(below);
    return {"\\frac{" + (above.empty() ? std::string("1") : top) + "}{" + bottom + "}",
            top_sign * bottom_sign};
  }

  std::string product(const Expr& e) {
    const Split s = split(e);
    const auto [text, sign] = rest(s.factors);
    const GiNaC::numeric c = s.coefficient * sign;
    return (c.is_negative() ? "-" : "") + magnitude(GiNaC::abs(c)) + text;
  }

  // base^exponent; the base of an integer power of a sum in its canonical sign (the sign this
  // takes out, sign_of(e), is the caller's).
  std::string power(const Expr& e) {
    const Expr base = e.op(0), exponent = e.op(1);
    if (is_half(exponent)) {
      return latex_ ? "\\sqrt{" + print(base, 0) + "}" : "sqrt(" + print(base, 0) + ")";
    }
    const bool turned = is_power_of_sum(e) && sign_of(base) < 0;
    const std::string base_text =
        turned ? open() + sum(parts(base), true) + close() : print(base, kPower);
    if (!latex_) return base_text + (sympy_ ? "**" : "^") + print(exponent, kPower);
    if (is_negative_number(exponent)) {
      if (exponent.is_equal(-1)) {
        return "\\frac{1}{" + (turned ? sum(parts(base), true) : print(base, 0)) + "}";
      }
      return "\\frac{1}{" + base_text + "^{" + print(-exponent, 0) + "}}";
    }
    // \sin^{2}\theta, as the book writes a power of a function
    if (is_exactly_a<GiNaC::function>(base) && exponent.info(GiNaC::info_flags::posint) &&
        GiNaC::ex_to<GiNaC::function>(base).get_name() != "abs") {
      return command(GiNaC::ex_to<GiNaC::function>(base).get_name()) + "^{" + print(exponent, 0) +
             "}" + argument_part(base);
    }
    return base_text + "^{" + print(exponent, 0) + "}";
  }

  std::string function(const Expr& e) {
    const std::string name = GiNaC::ex_to<GiNaC::function>(e).get_name();
    if (latex_ && name != "abs") return command(name) + argument_part(e);
    std::string arguments;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      arguments += (i ? "," : "") + print(e.op(i), 0);
    }
    if (sympy_ && name == "abs") return "Abs(" + arguments + ")";
    if (!latex_) return name + "(" + arguments + ")";
    return "\\left|" + arguments + "\\right|";
  }

  // \sin, \cos, …, or \operatorname{name}.
  static std::string command(const std::string& name) {
    static const std::map<std::string, std::string> named = {
        {"sin", "\\sin"},     {"cos", "\\cos"},     {"tan", "\\tan"},    {"exp", "\\exp"},
        {"log", "\\ln"},      {"sinh", "\\sinh"},   {"cosh", "\\cosh"},  {"tanh", "\\tanh"},
        {"asin", "\\arcsin"}, {"acos", "\\arccos"}, {"atan", "\\arctan"}};
    const auto found = named.find(name);
    return found != named.end() ? found->second : "\\operatorname{" + name + "}";
  }

  // A function's arguments in LaTeX: a lone symbol as the book writes it (\sin\theta), anything
  // else in parentheses.
  std::string argument_part(const Expr& f) {
    if (f.nops() == 1 && GiNaC::is_a<GiNaC::symbol>(f.op(0))) {
      const std::string a = print(f.op(0), 0);
      return (a.starts_with("\\") ? "" : " ") + a;
    }
    std::string arguments;
    for (std::size_t i = 0; i < f.nops(); ++i) arguments += (i ? "," : "") + print(f.op(i), 0);
    return "\\left(" + arguments + "\\right)";
  }

  bool latex_, sympy_;
  std::map<std::pair<const GiNaC::basic*, unsigned>, std::string> memo_;
  std::map<const GiNaC::basic*, std::unique_ptr<Parts>> parts_;
  std::unordered_map<const GiNaC::basic*, int> orders_;
  std::vector<Expr> keep_;
  std::unordered_set<const GiNaC::basic*> kept_;
};

// The text printer, its memos kept from one expression to the next (the parts of the
// expressions printed one after another are mostly the same nodes); a new one when they hold
// too many.
Printer& text_printer() {
  constexpr std::size_t kNodesKept = 1 << 20;
  thread_local std::unique_ptr<Printer> printer;
  if (!printer || printer->nodes_kept() > kNodesKept) {
    printer = std::make_unique<Printer>(Printer::Style::text);
  }
  return *printer;
}

}  // namespace

std::string canonical_text(const Expr& e) {
  // the texts printed so far (the canonical order compares texts, again and again): equal
  // expressions by GiNaC's hash and equality; dropped when they grow past a bound
  constexpr std::size_t kKept = 100000;
  thread_local std::unordered_map<Expr, std::string, ExprHash, GiNaC::ex_is_equal> printed;
  if (const auto found = printed.find(e); found != printed.end()) return found->second;
  if (printed.size() >= kKept) printed.clear();
  return printed.emplace(e, text_printer().print(e, 0)).first->second;
}

std::string canonical_sympy(const Expr& e) {
  return Printer(Printer::Style::sympy).print(e, 0);
}

std::string sympy_name(const std::string& name) {
  if (name.ends_with("''")) return name.substr(0, name.size() - 2) + "_dd";
  if (name.ends_with("'")) return name.substr(0, name.size() - 1) + "_d";
  // lambda(c) → lambda_c
  if (name.starts_with("lambda(") && name.ends_with(")")) {
    return "lambda_" + name.substr(7, name.size() - 8);
  }
  return name;
}

std::string canonical_latex(const Expr& e) {
  return Printer(Printer::Style::latex).print(e, 0);
}

bool canonical_less(const Expr& a, const Expr& b) {
  return canonical_text(a) < canonical_text(b);
}

int canonical_sign(const Expr& e) {
  return text_printer().sign_of(e);
}

namespace {

// Whether base^exponent is a denominator, or has one inside.
bool power_has_denominator(const Expr& base, const Expr& exponent) {
  if (!GiNaC::is_a<GiNaC::numeric>(base) && !exponent.info(GiNaC::info_flags::nonnegint)) {
    return true;
  }
  return has_denominator(base) || has_denominator(exponent);
}

}  // namespace

bool has_denominator(const Expr& e) {
  if (is_exactly_a<GiNaC::power>(e)) return power_has_denominator(e.op(0), e.op(1));
  // a sum's terms c·t and a product's factors t^c as GiNaC keeps them (c a number)
  if (is_exactly_a<GiNaC::add>(e)) {
    for (const GiNaC::expair& term : expairs(e)) {
      if (has_denominator(term.rest)) return true;
    }
    return false;
  }
  if (is_exactly_a<GiNaC::mul>(e)) {
    for (const GiNaC::expair& factor : expairs(e)) {
      if (power_has_denominator(factor.rest, factor.coeff)) return true;
    }
    return false;
  }
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_denominator(e.op(i))) return true;
  }
  return false;
}

// GiNaC's normal form n/d is unique up to the sign of both, which GiNaC fixes by a leading
// coefficient in its own variable order: here by the canonical order instead.
Expr canonical_normal(const Expr& e) {
  // a polynomial (sines and cosines counted as symbols) is its own normal form
  if (!has_denominator(e)) return e;
  const Expr fraction = GiNaC::numer_denom(GiNaC::normal(e));
  const Expr numerator = fraction.op(0), denominator = fraction.op(1);
  if (!is_exactly_a<GiNaC::add>(denominator)) return numerator / denominator;
  const int sign = canonical_sign(denominator);
  return (sign * numerator) / (sign * denominator);
}

}  // namespace unidyn
