// Angle sums and homogenisation in sines and cosines.
#include "unidyn/symbolic/trig_identities.hpp"

#include <algorithm>
#include <array>
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

// A term of the sum being combined: its canonical text (found when first asked for) and the
// order it came in (two terms of one text, should GiNaC keep them apart, stay two).
struct Term {
  Expr term;
  std::size_t arrival;
  std::optional<std::string> text;

  const std::string& canonical() {
    if (!text) text = canonical_text(term);
    return *text;
  }
};

// One way to read a term as σ R f(A) g(B), R = |n| K with the term's number n and its other
// factors K, f and g each the sine or the cosine of A and of B (A before B in the canonical order).
struct Reading {
  Term* term;
  std::size_t order;  // among the term's readings
  bool sine_a, sine_b;
  int sign;
  Expr rest, a, b;
};
// What two readings must share to combine: R, A and B.
using Shared = std::array<Expr, 3>;
struct SharedHash {
  std::size_t operator()(const Shared& s) const {
    return s[0].gethash() ^ (s[1].gethash() * 31) ^ (s[2].gethash() * 961);
  }
};
struct SharedEqual {
  bool operator()(const Shared& x, const Shared& y) const {
    return x[0].is_equal(y[0]) && x[1].is_equal(y[1]) && x[2].is_equal(y[2]);
  }
};
// Their texts: the order in which pairs are taken.
using ReadingKey = std::tuple<std::string, std::string, std::string>;

// The term's number and its other factors.
std::pair<GiNaC::numeric, std::vector<Expr>> number_and_factors(const Expr& term) {
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
  return {number, factors};
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

// Whether two readings (of one key) combine into one term:
//   σ1 R cos A cos B + σ2 R sin A sin B = σ1 R cos(A − B) (σ1 = σ2) or σ1 R cos(A + B)
//   σ1 R sin A cos B + σ2 R cos A sin B = σ1 R sin(A + B) (σ1 = σ2) or σ1 R sin(A − B)
bool combine(const Reading& r1, const Reading& r2) {
  if (r1.term == r2.term) return false;
  return (!r1.sine_a && !r1.sine_b && r2.sine_a && r2.sine_b) ||
         (r1.sine_a && !r1.sine_b && !r2.sine_a && r2.sine_b);
}
// The term they combine into.
Expr combined(const Reading& r1, const Reading& r2) {
  const bool same = r1.sign == r2.sign;
  if (!r1.sine_a) return r1.sign * r1.rest * cosine(same ? r1.a - r1.b : r1.a + r1.b);
  return r1.sign * r1.rest * sine(same ? r1.a + r1.b : r1.a - r1.b);
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

// An expanded sum combined pair by pair. Each term's readings are found once, when it enters,
// and grouped by what they share; the groups holding a pair that combines are kept in the order
// of their texts: the next pair is the first pair of the first such group (its readings in the
// order of their terms' texts), as a search of the whole sum in the canonical order would find it.
// Texts are made only for those groups and their terms (most groups hold one reading).
class AngleSums {
 public:
  explicit AngleSums(const Expr& x) : x_(x) {
    for (const Expr& t : terms_of(x_)) enter(t);
  }
  const Expr& sum() const { return x_; }
  std::size_t size() const { return terms_.size(); }

  // Combines the first pair; false when none is left.
  bool step() {
    if (combining_.empty()) return false;
    std::vector<Reading> group = groups_.at(combining_.begin()->second).readings;
    std::sort(group.begin(), group.end(), [](const Reading& r1, const Reading& r2) {
      return std::forward_as_tuple(r1.term->canonical(), r1.term->arrival, r1.order) <
             std::forward_as_tuple(r2.term->canonical(), r2.term->arrival, r2.order);
    });
    for (const Reading& r1 : group) {
      for (const Reading& r2 : group) {
        if (combine(r1, r2)) return replace(r1.term->term, r2.term->term, combined(r1, r2));
      }
    }
    return false;  // (a group is kept apart only with a pair)
  }

 private:
  struct Group {
    std::vector<Reading> readings;
    std::optional<std::pair<ReadingKey, std::size_t>> key;  // texts, then the group's arrival
  };
  // a term and what its readings share
  struct Entry {
    Term term;
    std::vector<Shared> shared;
  };

  // The sum with t1 and t2 replaced by c; the terms that left and came in updated (GiNaC adds c
  // to a term of its kind, if any: then the terms are compared).
  bool replace(Expr t1, Expr t2, const Expr& c) {
    std::vector<Expr> sum{c};
    for (const auto& [t, entry] : terms_) {
      if (!t.is_equal(t1) && !t.is_equal(t2)) sum.push_back(t);
    }
    x_ = sum_of(sum);
    if (is_exactly_a<GiNaC::add>(x_) && x_.nops() + 1 == terms_.size()) {
      leave(t1);
      leave(t2);
      enter(c);
      return true;
    }
    const std::vector<Expr> now = terms_of(x_);
    const std::unordered_set<Expr, ExprHash, GiNaC::ex_is_equal> kept(now.begin(), now.end());
    std::vector<Expr> left;
    for (const auto& [t, entry] : terms_) {
      if (kept.count(t) == 0) left.push_back(t);
    }
    for (const Expr& t : left) leave(t);
    for (const Expr& t : now) {
      if (terms_.count(t) == 0) enter(t);
    }
    return true;
  }

  void enter(const Expr& t) {
    Entry& entry = terms_.emplace(t, Entry{Term{t, arrivals_++, std::nullopt}, {}}).first->second;
    const auto [number, factors] = number_and_factors(t);
    for (std::size_t i = 0; i < factors.size(); ++i) {
      for (std::size_t j = 0; j < factors.size(); ++j) {
        const Expr &f = factors[i], &g = factors[j];
        if (i == j || !(is_sine(f) || is_cosine(f)) || !(is_sine(g) || is_cosine(g))) continue;
        if (!(argument_text(f.op(0)) < argument_text(g.op(0)))) continue;
        Expr rest = GiNaC::abs(number);
        for (std::size_t k = 0; k < factors.size(); ++k) {
          if (k != i && k != j) rest *= factors[k];
        }
        const Shared shared{rest, f.op(0), g.op(0)};
        groups_[shared].readings.push_back(Reading{&entry.term, entry.shared.size(), is_sine(f),
                                                   is_sine(g), number.is_negative() ? -1 : 1, rest,
                                                   f.op(0), g.op(0)});
        entry.shared.push_back(shared);
        review(shared);
      }
    }
  }

  void leave(const Expr& t) {
    const Entry& entry = terms_.at(t);
    for (const Shared& shared : entry.shared) {
      const auto group = groups_.find(shared);
      if (group == groups_.end()) continue;  // (left with an earlier reading of the term)
      std::vector<Reading>& readings = group->second.readings;
      readings.erase(std::remove_if(readings.begin(), readings.end(),
                                    [&](const Reading& r) { return r.term == &entry.term; }),
                     readings.end());
      review(shared);
    }
    terms_.erase(t);
  }

  // Whether the group still holds a pair that combines; an empty group goes.
  void review(const Shared& shared) {
    const auto found = groups_.find(shared);
    Group& group = found->second;
    const auto& rs = group.readings;
    const bool pair = std::any_of(rs.begin(), rs.end(), [&](const Reading& r1) {
      return std::any_of(rs.begin(), rs.end(), [&](const Reading& r2) { return combine(r1, r2); });
    });
    if (pair && !group.key) {
      group.key.emplace(
          ReadingKey{canonical_text(shared[0]), argument_text(shared[1]), argument_text(shared[2])},
          group_arrivals_++);
      combining_.emplace(*group.key, shared);
    } else if (!pair && group.key) {
      combining_.erase(*group.key);
      group.key.reset();
    }
    if (rs.empty()) groups_.erase(found);
  }

  // The canonical text of a sine's or cosine's argument (few, met often).
  const std::string& argument_text(const Expr& x) {
    const auto found = argument_texts_.find(x);
    if (found != argument_texts_.end()) return found->second;
    return argument_texts_.emplace(x, canonical_text(x)).first->second;
  }

  Expr x_;
  std::size_t arrivals_ = 0, group_arrivals_ = 0;
  std::unordered_map<Expr, Entry, ExprHash, GiNaC::ex_is_equal> terms_;
  std::unordered_map<Shared, Group, SharedHash, SharedEqual> groups_;
  std::map<std::pair<ReadingKey, std::size_t>, Shared> combining_;
  std::unordered_map<Expr, std::string, ExprHash, GiNaC::ex_is_equal> argument_texts_;
};

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
  const Expr x = expand_within_budget(e, "simplifying");
  if (!is_exactly_a<GiNaC::add>(x) || x.nops() > kMaxCombinedTerms) return x;
  AngleSums sums(x);
  while (sums.size() >= 2 && sums.step()) {
  }
  return sums.sum();
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
