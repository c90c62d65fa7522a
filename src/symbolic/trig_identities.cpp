// Angle sums and homogenisation in sines and cosines.
#include "unidyn/symbolic/trig_identities.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expairs.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/trig_functions.hpp"

namespace unidyn {
namespace {

using GiNaC::is_exactly_a;

constexpr std::size_t kMaxCombinedTerms = 400;

bool is_sine(const Expr& f) {
  return GiNaC::is_the_function<GiNaC::sin_SERIAL>(f);
}
bool is_cosine(const Expr& f) {
  return GiNaC::is_the_function<GiNaC::cos_SERIAL>(f);
}

// One way to read a term as σ R f(A) g(B), R = |n| K with the term's number n and its other
// factors K, f and g each the sine or the cosine of A and of B (A before B in the canonical order).
struct Reading {
  std::size_t term;
  bool sine_a, sine_b;
  int sign;
  Expr rest, a, b;
};
// What two readings must share to combine: the texts of R, A and B.
using ReadingKey = std::tuple<std::string, std::string, std::string>;
// The readings grouped by that key.
using Readings = std::map<ReadingKey, std::vector<Reading>>;

// A term's readings (its index in the sum left to be set).
std::vector<std::pair<ReadingKey, Reading>> term_readings(const Expr& term) {
  std::vector<std::pair<ReadingKey, Reading>> readings;
  GiNaC::numeric number = 1;
  std::vector<Expr> factors;
  for (std::size_t i = 0; i < (is_exactly_a<GiNaC::mul>(term) ? term.nops() : 1); ++i) {
    const Expr f = is_exactly_a<GiNaC::mul>(term) ? term.op(i) : term;
    if (is_exactly_a<GiNaC::numeric>(f)) {
      number *= GiNaC::ex_to<GiNaC::numeric>(f);
    } else {
      factors.push_back(f);
    }
  }
  for (std::size_t i = 0; i < factors.size(); ++i) {
    for (std::size_t j = 0; j < factors.size(); ++j) {
      const Expr &f = factors[i], &g = factors[j];
      if (i == j || !(is_sine(f) || is_cosine(f)) || !(is_sine(g) || is_cosine(g))) continue;
      if (!canonical_less(f.op(0), g.op(0))) continue;
      Expr rest = GiNaC::abs(number);
      for (std::size_t k = 0; k < factors.size(); ++k) {
        if (k != i && k != j) rest *= factors[k];
      }
      readings.emplace_back(
          ReadingKey{canonical_text(rest), canonical_text(f.op(0)), canonical_text(g.op(0))},
          Reading{0, is_sine(f), is_sine(g), number.is_negative() ? -1 : 1, rest, f.op(0),
                  g.op(0)});
    }
  }
  return readings;
}

// Each term of a sum that is being combined pair by pair: its canonical text and its readings,
// found once (the sum keeps all its terms but two from one step to the next).
class TermCache {
 public:
  struct Entry {
    std::string text;
    std::vector<std::pair<ReadingKey, Reading>> readings;
  };
  const Entry& operator()(const Expr& term) {
    if (const auto found = entries_.find(term); found != entries_.end()) return found->second;
    return entries_.emplace(term, Entry{canonical_text(term), term_readings(term)}).first->second;
  }

 private:
  std::unordered_map<Expr, Entry, ExprHash, GiNaC::ex_is_equal> entries_;
};

Readings readings_of(const std::vector<Expr>& terms, TermCache& cache) {
  Readings readings;
  for (std::size_t t = 0; t < terms.size(); ++t) {
    for (const auto& [key, reading] : cache(terms[t]).readings) {
      readings[key].push_back(reading);
      readings[key].back().term = t;
    }
  }
  return readings;
}

// Whether x reads better negated: −b, or a sum whose first term in the canonical order is
// negative (b − a for a − b).
bool reads_negated(const Expr& x) {
  if (is_exactly_a<GiNaC::add>(x)) return canonical_sign(x) < 0;
  if (is_exactly_a<GiNaC::mul>(x)) {
    for (std::size_t i = 0; i < x.nops(); ++i) {
      if (is_exactly_a<GiNaC::numeric>(x.op(i))) {
        return GiNaC::ex_to<GiNaC::numeric>(x.op(i)).is_negative();
      }
    }
  }
  return false;
}
// cos x and sin x with the argument's sign as it reads best: cos(−x) = cos x, sin(−x) = −sin x.
Expr cosine(const Expr& x) {
  return cosine_of(reads_negated(x) ? -x : x);
}
Expr sine(const Expr& x) {
  return reads_negated(x) ? -sine_of(-x) : sine_of(x);
}

// Two readings that combine into one term, or none:
//   σ1 R cos A cos B + σ2 R sin A sin B = σ1 R cos(A − B) (σ1 = σ2) or σ1 R cos(A + B)
//   σ1 R sin A cos B + σ2 R cos A sin B = σ1 R sin(A + B) (σ1 = σ2) or σ1 R sin(A − B)
std::optional<Expr> combined(const Reading& r1, const Reading& r2) {
  const bool same = r1.sign == r2.sign;
  const Expr sum = r1.a + r1.b, difference = r1.a - r1.b;
  if (!r1.sine_a && !r1.sine_b && r2.sine_a && r2.sine_b) {
    return r1.sign * r1.rest * cosine(same ? difference : sum);
  }
  if (r1.sine_a && !r1.sine_b && !r2.sine_a && r2.sine_b) {
    return r1.sign * r1.rest * sine(same ? sum : difference);
  }
  return std::nullopt;
}

// The first pair of terms that combine, in the order of the readings' keys: (first term, second
// term, the combined term).
std::optional<std::tuple<std::size_t, std::size_t, Expr>> first_pair(const Readings& readings) {
  for (const auto& [key, list] : readings) {
    for (const Reading& r1 : list) {
      for (const Reading& r2 : list) {
        if (r1.term == r2.term) continue;
        if (const auto c = combined(r1, r2)) return std::make_tuple(r1.term, r2.term, *c);
      }
    }
  }
  return std::nullopt;
}

std::vector<Expr> terms_of(const Expr& e) {
  std::vector<Expr> terms;
  if (is_exactly_a<GiNaC::add>(e)) {
    for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(e.op(i));
  } else {
    terms.push_back(e);
  }
  return terms;
}

// Whether e holds a sine or a cosine anywhere.
bool has_sine_or_cosine(const Expr& e) {
  if (is_sine(e) || is_cosine(e)) return true;
  for (std::size_t i = 0; i < e.nops(); ++i) {
    if (has_sine_or_cosine(e.op(i))) return true;
  }
  return false;
}

// A term as its product of sines and cosines to natural powers and the rest, or none where a
// sine or cosine sits elsewhere in it.
std::optional<std::pair<Expr, Expr>> split_trig_monomial(const Expr& term) {
  Expr monomial = 1, rest = 1;
  const auto take = [&](const Expr& f) {
    const bool power = is_exactly_a<GiNaC::power>(f);
    const Expr& base = power ? f.op(0) : f;
    if (is_sine(base) || is_cosine(base)) {
      if (power && !f.op(1).info(GiNaC::info_flags::nonnegint)) return false;
      if (has_sine_or_cosine(base.op(0))) return false;
      monomial *= f;
      return true;
    }
    if (has_sine_or_cosine(f)) return false;
    rest *= f;
    return true;
  };
  if (is_exactly_a<GiNaC::mul>(term)) {
    for (std::size_t i = 0; i < term.nops(); ++i) {
      if (!take(term.op(i))) return std::nullopt;
    }
  } else if (!take(term)) {
    return std::nullopt;
  }
  return std::make_pair(monomial, rest);
}

}  // namespace

std::optional<Expr> collect_in_sines_and_cosines(const Expr& e) {
  if (!has_sine_or_cosine(e)) return std::nullopt;
  const Expr x = expand_within_budget(e, "simplifying");
  // the coefficients of each monomial, by its canonical text
  std::map<std::string, std::pair<Expr, std::vector<Expr>>> groups;
  for (const Expr& term : terms_of(x)) {
    const auto split = split_trig_monomial(term);
    if (!split) return std::nullopt;
    auto& group =
        groups.try_emplace(canonical_text(split->first), split->first, std::vector<Expr>{})
            .first->second;
    group.second.push_back(split->second);
  }
  std::vector<Expr> sum;
  for (const auto& [text, group] : groups) sum.push_back(group.first * sum_of(group.second));
  return sum_of(sum);
}

std::vector<Expr> trig_arguments(const Expr& e) {
  // the outermost sines and the outermost cosines (GiNaC's find of sin(x) and of cos(x): not the
  // sines inside a sine's argument), each shared node walked once for each of the two searches
  const auto less = [](const Expr& a, const Expr& b) { return canonical_less(a, b); };
  std::set<Expr, decltype(less)> arguments(less);
  std::set<std::pair<const GiNaC::basic*, int>> seen;
  const auto walk = [&](const Expr& x, bool sines, bool cosines, const auto& self) -> void {
    if (x.nops() == 0) return;
    if (!seen.emplace(&GiNaC::ex_to<GiNaC::basic>(x), int(sines) + 2 * int(cosines)).second) return;
    if ((sines && is_sine(x)) || (cosines && is_cosine(x))) {
      arguments.insert(x.op(0));
      sines = sines && !is_sine(x);
      cosines = cosines && !is_cosine(x);
      if (!sines && !cosines) return;
    }
    // a sum's or product's parts as GiNaC keeps them (nodes of the expression, not made anew by
    // op(): their addresses stay theirs); their coefficients are numbers
    if (is_exactly_a<GiNaC::add>(x) || is_exactly_a<GiNaC::mul>(x)) {
      for (const GiNaC::expair& part : expairs(x)) self(part.rest, sines, cosines, self);
      return;
    }
    for (std::size_t i = 0; i < x.nops(); ++i) self(x.op(i), sines, cosines, self);
  };
  walk(e, true, true, walk);
  return {arguments.begin(), arguments.end()};
}

Expr combine_angle_sums(const Expr& e) {
  Expr x = expand_within_budget(e, "simplifying");
  TermCache cache;
  for (;;) {
    // the terms in the canonical order, so that the pair taken never depends on GiNaC's
    std::vector<std::pair<std::string, Expr>> keyed;
    for (const Expr& t : terms_of(x)) keyed.emplace_back(cache(t).text, t);
    std::stable_sort(keyed.begin(), keyed.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    std::vector<Expr> terms;
    for (const auto& [text, t] : keyed) terms.push_back(t);
    if (terms.size() < 2 || terms.size() > kMaxCombinedTerms) return x;
    const auto pair = first_pair(readings_of(terms, cache));
    if (!pair) return x;
    const auto& [first, second, term] = *pair;
    std::vector<Expr> sum{term};
    for (std::size_t t = 0; t < terms.size(); ++t) {
      if (t != first && t != second) sum.push_back(terms[t]);
    }
    x = sum_of(sum);
  }
}

namespace {

// A term of an expanded sum by the arguments x of its sines and cosines: its degree in sin x and
// cos x together, or none where they sit inside something else (a root, another function).
class TrigDegrees {
 public:
  explicit TrigDegrees(const Expr& term) {
    if (is_exactly_a<GiNaC::mul>(term)) {
      for (std::size_t i = 0; i < term.nops(); ++i) add_factor(term.op(i));
    } else {
      add_factor(term);
    }
  }

  std::optional<int> of(const Expr& x) const {
    if (elsewhere_.count(x) != 0) return std::nullopt;
    const auto found = degree_.find(x);
    return found == degree_.end() ? 0 : found->second;
  }

 private:
  void add_factor(const Expr& f) {
    // sin x, cos x and their natural powers
    const bool power = is_exactly_a<GiNaC::power>(f);
    const Expr& base = power ? f.op(0) : f;
    if ((is_sine(base) || is_cosine(base)) &&
        (!power || f.op(1).info(GiNaC::info_flags::nonnegint))) {
      degree_[base.op(0)] += power ? GiNaC::ex_to<GiNaC::numeric>(f.op(1)).to_int() : 1;
      mark_inside(base.op(0));
      return;
    }
    if (GiNaC::is_a<GiNaC::symbol>(f) || GiNaC::is_a<GiNaC::numeric>(f)) return;
    mark_inside(f);
  }

  // every sine and cosine inside e, at any depth, sits elsewhere
  void mark_inside(const Expr& e) {
    if (is_sine(e) || is_cosine(e)) elsewhere_.insert(e.op(0));
    for (std::size_t i = 0; i < e.nops(); ++i) mark_inside(e.op(i));
  }

  std::unordered_map<Expr, int, ExprHash, GiNaC::ex_is_equal> degree_;
  std::unordered_set<Expr, ExprHash, GiNaC::ex_is_equal> elsewhere_;
};

// Whether no term of the expanded x has more than one sine or cosine factor (counted with their
// powers) and none sits elsewhere: then each term's degree in every argument is 0 or 1, the top
// of its parity, and homogenising changes nothing.
bool linear_in_sines_and_cosines(const Expr& x) {
  for (const Expr& term : terms_of(x)) {
    const auto split = split_trig_monomial(term);
    if (!split) return false;
    const Expr& monomial = split->first;
    if (GiNaC::is_exactly_a<GiNaC::mul>(monomial) || GiNaC::is_exactly_a<GiNaC::power>(monomial)) {
      return false;
    }
  }
  return true;
}

}  // namespace

Expr homogenize_trig(const Expr& e) {
  Expr x = expand_within_budget(e, "simplifying");
  if (linear_in_sines_and_cosines(x)) return x;
  // the terms and their degrees in each argument's sine and cosine, found again when x changes
  std::vector<Expr> terms;
  std::vector<TrigDegrees> term_degrees;
  const auto take_terms = [&] {
    terms = terms_of(x);
    term_degrees.clear();
    for (const Expr& t : terms) term_degrees.emplace_back(t);
  };
  take_terms();
  for (const Expr& argument : trig_arguments(x)) {
    const Expr sine_x = sine_of(argument), cosine_x = cosine_of(argument);
    // each term's degree in sin x and cos x together, and the highest of each parity (none where
    // they sit inside something else: not a polynomial in them)
    std::vector<int> degrees;
    int top[2] = {-1, -1};
    for (const TrigDegrees& t : term_degrees) {
      const auto d = t.of(argument);
      if (!d) break;
      degrees.push_back(*d);
      top[*d % 2] = std::max(top[*d % 2], *d);
    }
    if (degrees.size() < terms.size()) continue;
    // each term t below the top as t (sin²x + cos²x)^m expanded: Σ C(m, i) t sin^(2i)x
    // cos^(2(m − i))x, monomials times monomials (what expanding the products gives)
    std::vector<Expr> raised;
    bool below = false;
    for (std::size_t k = 0; k < terms.size(); ++k) {
      const int m = (top[degrees[k] % 2] - degrees[k]) / 2;
      below = below || m > 0;
      GiNaC::numeric binomial = 1;  // C(m, i)
      for (int i = 0; i <= m; ++i) {
        raised.push_back(terms[k] * binomial * GiNaC::pow(sine_x, 2 * i) *
                         GiNaC::pow(cosine_x, 2 * (m - i)));
        binomial = binomial * (m - i) / (i + 1);
      }
    }
    if (!below) continue;
    x = sum_of(raised);
    take_terms();
  }
  return x;
}

}  // namespace unidyn
