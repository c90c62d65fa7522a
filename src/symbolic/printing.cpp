// Simplification for display and printing.
#include "unidyn/symbolic/printing.hpp"

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expairs.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/polynomial_degrees.hpp"
#include "unidyn/symbolic/process_map.hpp"
#include "unidyn/symbolic/trig_functions.hpp"
#include "unidyn/symbolic/trig_identities.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>
#include <unordered_set>

namespace unidyn {
namespace {

Expr simplify_uncached(const Expr& e);

// Expressions in the canonical order (symbolic/canonical_text.hpp), not GiNaC's, which changes
// from run to run: what is made from them in turn (symbols, reductions, ties) is then the same.
struct CanonicalLess {
  bool operator()(const Expr& a, const Expr& b) const { return canonical_less(a, b); }
};

// An expression and its size (expression_size), measured once.
struct Sized {
  Expr e;
  std::size_t size;
  explicit Sized(const Expr& x) : e(x), size(expression_size(x)) {}
};

// Of two equal expressions, whether `candidate` is the better: smaller, or as small and first in
// the canonical order (so that the choice never depends on GiNaC's order).
bool better(const Sized& candidate, const Sized& best) {
  if (candidate.size != best.size) return candidate.size < best.size;
  // (one expression is not better than itself: nothing to print)
  return !candidate.e.is_equal(best.e) && canonical_less(candidate.e, best.e);
}

// Substitutions of symbols and of whole sines and cosines, none a pattern with wildcards: the
// map is looked up at each node (GiNaC otherwise tries to match every key at every node).
constexpr unsigned kPlain = GiNaC::subs_options::no_pattern;

// Pairs (v, w) of the sine and cosine symbols of one argument, v the one reduced.
using UnitCircles = std::vector<std::pair<GiNaC::symbol, GiNaC::symbol>>;

// An expanded p with every v^k (k ≥ 2) of each pair (v, w) replaced by v^(k mod 2) (1 − w²)^⌊k/2⌋:
// its remainder modulo the v² + w² − 1, unique for each polynomial (each is monic in its v). A
// pair in whose v p is not a polynomial is left as it is.
Expr reduce_modulo_unit_circles(const Expr& p, const UnitCircles& pairs) {
  UnitCircles reduced;
  std::vector<Expr> vs;
  for (const auto& pair : pairs) vs.push_back(pair.first);
  const std::vector<std::optional<int>> degrees = polynomial_degrees(p, vs);
  vs.clear();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (degrees[k].value_or(0) < 2) continue;
    reduced.push_back(pairs[k]);
    vs.push_back(pairs[k].first);
  }
  if (reduced.empty()) return p;
  // each term t v^k … as the expanded t v^(k mod 2) (1 − w²)^⌊k/2⌋ … = Σ_i C(⌊k/2⌋, i) (−1)^i
  // t v^(k mod 2) w^(2i) …: monomials times monomials, already expanded (what GiNaC's expand of
  // the products would give, without its walk through the whole sum)
  std::vector<Expr> terms;
  const PolynomialDegrees degrees_in_vs(vs);
  const auto reduce_term = [&](const Expr& term) {
    const std::vector<std::optional<int>> term_degrees = degrees_in_vs(term);
    // past the budget: the products as they are, for the expansion to refuse
    double count = 1;
    for (const auto& k : term_degrees) count *= k.value_or(0) / 2 + 1;
    if (count > kMaxExpandedTerms) {
      Expr product = term;
      for (std::size_t i = 0; i < reduced.size(); ++i) {
        const int k = term_degrees[i].value_or(0);
        product = product / GiNaC::pow(reduced[i].first, k - k % 2) *
                  GiNaC::pow(1 - GiNaC::pow(reduced[i].second, 2), k / 2);
      }
      terms.push_back(expand_within_budget(product, "simplifying"));
      return;
    }
    // the pairs to reduce in this term (v^k, k ≥ 2), and the term with each such v^k lowered to
    // v^(k mod 2); a term without any passes as it is
    std::vector<std::size_t> in_term;
    GiNaC::exvector lowering{term};
    for (std::size_t i = 0; i < reduced.size(); ++i) {
      const int k = term_degrees[i].value_or(0);
      if (k < 2) continue;
      in_term.push_back(i);
      lowering.push_back(GiNaC::pow(reduced[i].first, -(k - k % 2)));
    }
    if (in_term.empty()) {
      terms.push_back(term);
      return;
    }
    const Expr lowered = GiNaC::dynallocate<GiNaC::mul>(lowering);
    // every choice of r_i ∈ [0, j_i], j_i = ⌊k_i/2⌋: the lowered term × Π (−1)^r_i C(j_i, r_i)
    // w_i^(2 r_i), each made as one product (GiNaC merges the factors at once)
    std::vector<int> r(in_term.size(), 0);
    for (;;) {
      GiNaC::numeric number = 1;
      GiNaC::exvector factors{lowered};
      for (std::size_t a = 0; a < in_term.size(); ++a) {
        const int j = term_degrees[in_term[a]].value_or(0) / 2;
        number = number * GiNaC::binomial(GiNaC::numeric(j), GiNaC::numeric(r[a]));
        if (r[a] % 2 != 0) number = -number;
        if (r[a] > 0) factors.push_back(GiNaC::pow(reduced[in_term[a]].second, 2 * r[a]));
      }
      factors.push_back(number);
      terms.push_back(GiNaC::dynallocate<GiNaC::mul>(factors));
      // the next choice, the last pair's r turning fastest
      std::size_t a = in_term.size();
      while (a > 0 && r[a - 1] == term_degrees[in_term[a - 1]].value_or(0) / 2) r[--a] = 0;
      if (a == 0) break;
      ++r[a - 1];
    }
  };
  if (GiNaC::is_exactly_a<GiNaC::add>(p)) {
    for (std::size_t i = 0; i < p.nops(); ++i) reduce_term(p.op(i));
  } else {
    reduce_term(p);
  }
  return sum_of(terms);
}

// A fixed remainder of p modulo s² + c² − 1 for every trigonometric argument (the sines' squares
// eliminated): polynomials in the sines and cosines that are equal get one form.
Expr canonical_trig_form(const Expr& p) {
  const std::vector<Expr> arguments = trig_arguments(p);
  GiNaC::exmap to_symbols, back;
  std::vector<std::pair<GiNaC::symbol, GiNaC::symbol>> sc;
  for (const Expr& x : arguments) {
    sc.emplace_back();
    to_symbols[sine_of(x)] = sc.back().first;
    to_symbols[cosine_of(x)] = sc.back().second;
    back[sc.back().first] = sine_of(x);
    back[sc.back().second] = cosine_of(x);
  }
  Expr reduced = expand_within_budget(p.subs(to_symbols, kPlain), "simplifying");
  reduced = reduce_modulo_unit_circles(reduced, sc);
  return expand_within_budget(reduced.subs(back, kPlain), "simplifying");
}

// Replaces each radical b^(p/q) by r^p with one symbol r = b^(1/q) per base in its canonical form
// (so √u and 1/√u of one u, written two ways, become r and 1/r), recording r → b^(1/q) in `back`:
// the reduction modulo s² + c² − 1 then sees polynomials.
Expr hide_radicals(const Expr& e, GiNaC::exmap& back) {
  // the radicals: powers to rational exponents that are not integers, found by one walk
  std::set<Expr, CanonicalLess> found;
  const auto find = [&found](const auto& self, const Expr& x) -> void {
    if (GiNaC::is_exactly_a<GiNaC::power>(x) && x.op(1).info(GiNaC::info_flags::rational) &&
        !x.op(1).info(GiNaC::info_flags::integer)) {
      found.insert(x);
    }
    for (std::size_t i = 0; i < x.nops(); ++i) self(self, x.op(i));
  };
  find(find, e);
  std::map<Expr, GiNaC::symbol, CanonicalLess> roots;
  GiNaC::exmap hide;
  for (const Expr& power : found) {
    const GiNaC::numeric r = GiNaC::ex_to<GiNaC::numeric>(power.op(1));
    const Expr root = GiNaC::pow(canonical_trig_form(power.op(0)), GiNaC::numeric(1) / r.denom());
    auto it = roots.find(root);
    if (it == roots.end()) {
      it = roots.emplace(root, GiNaC::symbol()).first;
      back[it->second] = root;
    }
    hide[power] = GiNaC::pow(it->second, r.numer());
  }
  return hide.empty() ? e : e.subs(hide);
}

// Whether every number in e is an integer.
bool integer_numbers(const Expr& e) {
  if (GiNaC::is_exactly_a<GiNaC::numeric>(e)) return e.info(GiNaC::info_flags::integer);
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (!integer_numbers(e.op(i))) return false;
  }
  return true;
}

// Simplifies what sits inside: function arguments and the bases of non-integer powers (so that
// √(r² cos²θ + r² sin²θ) becomes √(r²)).
struct SimplifyInside : GiNaC::map_function {
  Expr operator()(const Expr& e) override {
    if (e.nops() == 0) return e;
    if (GiNaC::is_a<GiNaC::power>(e) && !e.op(1).info(GiNaC::info_flags::integer)) {
      return GiNaC::pow(simplify(e.op(0)), e.op(1));
    }
    if (GiNaC::is_a<GiNaC::function>(e)) {
      return e.map([](const Expr& argument) { return simplify(argument); });
    }
    // a sum or a product made anew only where a part changed (GiNaC's map makes them anew)
    const bool sum = GiNaC::is_exactly_a<GiNaC::add>(e);
    if (!sum && !GiNaC::is_exactly_a<GiNaC::mul>(e)) return e.map(*this);
    std::vector<Expr> parts(e.begin(), e.end());
    bool changed = false;
    for (Expr& part : parts) {
      Expr inside = (*this)(part);
      changed = changed || !GiNaC::are_ex_trivially_equal(inside, part);
      part = std::move(inside);
    }
    if (!changed) return e;
    return sum ? sum_of(parts) : Expr(GiNaC::dynallocate<GiNaC::mul>(parts));
  }
};

}  // namespace

namespace {

// The size of a factor base^exponent of a product: a power node over its base and exponent (one
// node, a number), or the base alone.
std::size_t factor_size(const Expr& base, const Expr& exponent) {
  return exponent.is_equal(1) ? expression_size(base) : 2 + expression_size(base);
}

// The size of the product of `factors` (pairs base^exponent as GiNaC keeps them) and the number
// c: a node over its factors and, unless c is ±1, c; a lone factor times ±1 is that factor.
std::size_t product_size(const GiNaC::epvector& factors, const GiNaC::numeric& c) {
  const bool unit = GiNaC::abs(c).is_equal(1);
  std::size_t size = unit ? 1 : 2, only = 0;
  for (const GiNaC::expair& f : factors) {
    only = factor_size(f.rest, f.coeff);
    size += only;
  }
  return factors.size() == 1 && unit ? only : size;
}

}  // namespace

std::size_t expression_size(const Expr& e) {
  // a sign is not a node: −x counts as x, −(a − b) c as (b − a) c (GiNaC picks the sign of a sum
  // by its own order of terms, which moves with the memory layout); sums and products read as
  // GiNaC keeps them (a term c·t, a factor t^c), not made anew by op()
  if (GiNaC::is_exactly_a<GiNaC::mul>(e)) {
    return product_size(expairs(e), GiNaC::ex_to<GiNaC::numeric>(overall_coefficient(e)));
  }
  if (GiNaC::is_exactly_a<GiNaC::add>(e)) {
    // the sum's node, each term c·t (t alone when c is 1), and its number term
    std::size_t size = overall_coefficient(e).is_zero() ? 1 : 2;
    for (const GiNaC::expair& term : expairs(e)) {
      const GiNaC::numeric& c = GiNaC::ex_to<GiNaC::numeric>(term.coeff);
      if (c.is_equal(1)) {
        size += expression_size(term.rest);
      } else if (GiNaC::is_exactly_a<GiNaC::mul>(term.rest)) {
        size += product_size(expairs(term.rest),
                             c * GiNaC::ex_to<GiNaC::numeric>(overall_coefficient(term.rest)));
      } else {
        size +=
            GiNaC::abs(c).is_equal(1) ? expression_size(term.rest) : 2 + expression_size(term.rest);
      }
    }
    return size;
  }
  std::size_t size = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) size += expression_size(e.op(i));
  return size;
}

namespace {

// The results kept for f: equal expressions by GiNaC's hash and equality, one table per function;
// dropped when they grow past a bound.
constexpr std::size_t kKept = 20000;
using Table = std::unordered_map<Expr, Expr, ExprHash, GiNaC::ex_is_equal>;
Table& remembered_by(Expr (*f)(const Expr&)) {
  thread_local std::map<Expr (*)(const Expr&), Table> tables;
  return tables[f];
}

}  // namespace

Expr remembered(const Expr& e, Expr (*f)(const Expr&)) {
  if (const std::optional<Expr> known = recalled(e, f)) return *known;
  const Expr result = f(e);
  remember(e, f, result);
  return result;
}

std::vector<Expr> remembered_all(const std::vector<Expr>& es, Expr (*f)(const Expr&)) {
  // the ones not met before, each once, shared among the processes; then all remembered
  std::unordered_set<Expr, ExprHash, GiNaC::ex_is_equal> met;
  std::vector<Expr> fresh;
  for (const Expr& e : es) {
    if (!recalled(e, f) && met.insert(e).second) fresh.push_back(e);
  }
  const std::vector<Expr> results = map_in_processes(fresh, f);
  for (std::size_t i = 0; i < fresh.size(); ++i) remember(fresh[i], f, results[i]);
  std::vector<Expr> out;
  for (const Expr& e : es) out.push_back(remembered(e, f));
  return out;
}

std::vector<Expr> simplify_all(const std::vector<Expr>& es) {
  return remembered_all(es, simplify_uncached);
}

void remember(const Expr& e, Expr (*f)(const Expr&), const Expr& result) {
  Table& table = remembered_by(f);
  if (table.size() >= kKept) table.clear();
  table.emplace(e, result);
}

std::optional<Expr> recalled(const Expr& e, Expr (*f)(const Expr&)) {
  const Table& table = remembered_by(f);
  if (const auto found = table.find(e); found != table.end()) return found->second;
  return std::nullopt;
}

Expr simplify(const Expr& e) {
  return remembered(e, simplify_uncached);
}

namespace {

Expr simplify_uncached(const Expr& e) {
  SimplifyInside inside;
  check_expansion_budget(e, "simplifying");
  Sized best(expand_within_budget(inside(e), "simplifying"));
  // A rational function is brought to one fraction only when that is smaller, and only when
  // normal() can afford it (a large one is left a sum of fractions)
  if (normal_affordable(best.e)) {
    if (const Expr normal = canonical_normal(best.e); !normal.is_equal(best.e)) {
      if (const Sized sized(normal); better(sized, best)) best = sized;
    }
  }
  // sin²x + cos²x = 1: with s = sin x, c = cos x for each argument, numerator and denominator are
  // polynomials in the s and c; reduced modulo s² + c² − 1 in s or in c they take a unique form,
  // so an expression that is zero becomes 0 whatever order GiNaC keeps its terms in. Each argument
  // is reduced both ways (every combination for up to two arguments reduced, one argument at a
  // time for three or four, all one way or all the other beyond) and the smallest kept.
  GiNaC::exmap radicals;
  if (const Expr hidden = hide_radicals(best.e, radicals); !radicals.empty()) best = Sized(hidden);
  const std::vector<Expr> arguments = trig_arguments(best.e);
  if (arguments.empty()) return best.e.subs(radicals, kPlain);
  std::vector<GiNaC::symbol> s, c;
  GiNaC::exmap to_symbols, back;
  for (const Expr& x : arguments) {
    s.emplace_back();
    c.emplace_back();
    to_symbols[sine_of(x)] = s.back();
    to_symbols[cosine_of(x)] = c.back();
    back[s.back()] = sine_of(x);
    back[c.back()] = cosine_of(x);
  }
  // numer_denom normalises by itself (its sign is fixed by canonical_normal below); a polynomial
  // with integer coefficients is its own numerator, over 1 (numer_denom would walk it to say so)
  const Expr in_symbols = best.e.subs(to_symbols, kPlain);
  const Expr fraction = !has_denominator(in_symbols) && integer_numbers(in_symbols)
                            ? Expr(GiNaC::lst{in_symbols, 1})
                            : GiNaC::numer_denom(in_symbols);
  const Expr numerator = expand_within_budget(fraction.op(0), "simplifying"),
             denominator = expand_within_budget(fraction.op(1), "simplifying");
  const std::size_t n = arguments.size();
  // the arguments whose sine or cosine is squared somewhere: only these are reduced (for the
  // others either way leaves the polynomials as they are), so a choice that differs from an
  // earlier one only in the others gives what that one gave and is skipped
  std::vector<Expr> sines_and_cosines(s.begin(), s.end());
  sines_and_cosines.insert(sines_and_cosines.end(), c.begin(), c.end());
  const auto in_numerator = polynomial_degrees(numerator, sines_and_cosines),
             in_denominator = polynomial_degrees(denominator, sines_and_cosines);
  const auto squared = [&](std::size_t k) {
    return in_numerator[k].value_or(0) >= 2 || in_denominator[k].value_or(0) >= 2;
  };
  std::vector<bool> reduced_argument(n);
  std::size_t idle = 0;  // the mask of the others (up to four arguments: a bit each)
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    reduced_argument[i] = squared(i) || squared(n + i);
    any = any || reduced_argument[i];
    if (!reduced_argument[i] && n <= 4) idle |= std::size_t{1} << i;
  }
  // a polynomial in which no sine or cosine is squared is its own remainder
  if (!any && denominator.is_equal(1)) return best.e.subs(radicals, kPlain);
  // (the reductions neither make nor remove a denominator inside the numerator)
  const bool polynomial = denominator.is_equal(1) && !has_denominator(numerator);
  // the reduction by one choice of sine or cosine per argument (bit i set: argument i in its
  // sine, up to four arguments; beyond, all in the sine or all in the cosine): its best form,
  // offered to `best`
  const auto reduction = [&](std::size_t mask) {
    UnitCircles pairs;
    for (std::size_t i = 0; i < n; ++i) {
      if (!reduced_argument[i]) continue;
      const bool in_sine = n <= 4 ? ((mask >> i) & 1) != 0 : mask == 1;
      pairs.emplace_back(in_sine ? s[i] : c[i], in_sine ? c[i] : s[i]);
    }
    const Expr num = reduce_modulo_unit_circles(numerator, pairs),
               den = reduce_modulo_unit_circles(denominator, pairs);
    // a polynomial's remainder is its own normal form, and expanded already (monomials in which
    // the symbols became sines and cosines); a fraction's, expanded, may be smaller
    const Expr quotient = num / den;
    const Sized reduced((polynomial                    ? num
                         : normal_affordable(quotient) ? canonical_normal(quotient)
                                                       : quotient)
                            .subs(back, kPlain));
    Sized form = reduced;
    if (!polynomial) {
      if (const Sized expanded(expand_within_budget(reduced.e, "simplifying"));
          better(expanded, reduced)) {
        form = expanded;
      }
    }
    if (better(form, best)) best = form;
    return form;
  };
  const std::size_t reduced_count =
      std::count(reduced_argument.begin(), reduced_argument.end(), true);
  if (n > 4) {
    reduction(0);
    if (any) reduction(1);
  } else if (reduced_count <= 2) {
    // every combination
    for (std::size_t mask = 0; mask < (std::size_t{1} << n); ++mask) {
      if ((mask & idle) == 0) reduction(mask);
    }
  } else {
    // three or four: from all in the cosine, each argument turned to its sine where that is
    // better (n + 1 reductions rather than 2^n)
    std::size_t mask = 0;
    Sized current = reduction(mask);
    for (std::size_t i = 0; i < n; ++i) {
      if (!reduced_argument[i]) continue;
      const std::size_t turned = mask | (std::size_t{1} << i);
      if (const Sized form = reduction(turned); better(form, current)) {
        mask = turned;
        current = form;
      }
    }
  }
  return best.e.subs(radicals, kPlain);
}

}  // namespace

Expr collect_in(const Expr& e, const std::vector<Expr>& symbols) {
  GiNaC::lst list;
  for (const auto& x : symbols) list.append(x);
  return GiNaC::collect(simplify(e), list);
}

std::string to_text(const Expr& e) {
  return canonical_text(e);
}

std::string to_latex(const Expr& e) {
  return canonical_latex(e);
}

}  // namespace unidyn
