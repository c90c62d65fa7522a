// Bounding the size of an expansion before it is made.
#include "unidyn/symbolic/expansion_budget.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <unordered_map>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expairs.hpp"

namespace unidyn {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The monomials of degree n in k terms, C(n + k − 1, k − 1): the terms of (a sum of k)^n.
double multinomial_terms(double n, double k) {
  const double terms = std::exp(std::lgamma(n + k) - std::lgamma(n + 1) - std::lgamma(k));
  return terms < 1e15 ? std::round(terms) : terms;  // exact where a double counts exactly
}

// Terms of the expansion of each node, memoised by node (GiNaC shares equal subexpressions, so
// a tree can be far larger than the nodes it is made of); `largest` collects the bound of every
// expansion inside (a function's arguments are expanded too).
class Bound {
 public:
  double operator()(const Expr& e) {
    // an atom (a symbol, a number) is one term, not worth remembering
    if (e.nops() == 0) return 1;
    const auto* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(node); it != memo_.end()) return it->second.second;
    double terms = 1;
    if (GiNaC::is_a<GiNaC::add>(e)) {
      // the terms c·t as GiNaC keeps them (c a number), and the number term
      terms = overall_coefficient(e).is_zero() ? 0 : 1;
      for (const GiNaC::expair& term : expairs(e)) terms += (*this)(term.rest);
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
      for (const GiNaC::expair& factor : expairs(e)) terms *= power(factor.rest, factor.coeff);
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
      terms = power(e.op(0), e.op(1));
    } else {
      for (std::size_t i = 0; i < e.nops(); ++i) (*this)(e.op(i));  // a function's arguments
    }
    if (!std::isfinite(terms)) terms = kInfinity;
    largest = std::max(largest, terms);
    memo_.emplace(node, std::make_pair(e, terms));
    return terms;
  }

  double largest = 1;
  double largest_power = 1;

 private:
  // The terms of base^exponent expanded: (a sum of k terms)^n has C(n + k − 1, k − 1); any other
  // power is one term.
  double power(const Expr& base, const Expr& exponent) {
    if (exponent.is_equal(1)) return (*this)(base);
    const double k = (*this)(base);
    if (!exponent.info(GiNaC::info_flags::posint) || k <= 1) {
      (*this)(exponent);
      return 1;
    }
    const double n = GiNaC::ex_to<GiNaC::numeric>(exponent).to_double();
    double terms = multinomial_terms(n, k);
    if (!std::isfinite(terms)) terms = kInfinity;
    largest_power = std::max(largest_power, terms);
    largest = std::max(largest, terms);
    return terms;
  }

  // keyed by node, holding the node: the operands of a sum or product can be made on the fly
  // (c·x from a pair), and a freed node's address could come back for another
  std::unordered_map<const GiNaC::basic*, std::pair<Expr, double>> memo_;
};

// The terms of the numerator and the denominator normal() makes of each node, multiplied out
// before any greatest common divisor cancels. A denominator is kept as its factors — each base
// with its exponent and the terms of the base — so that fractions over the same denominator (as
// mechanics has them: every term over m1 + m2 sin²θ) add over it once, as normal() adds them over
// their least common multiple: n/d + n'/d' = (n d'/g + n' d/g) / (d d'/g). A product multiplies
// numerators and adds the factors' exponents; (n/d)^k and (n/d)^−k are powers of their sums; a
// function or a non-integer power is one term (normal() takes it for a symbol), its arguments
// looked at too. `largest` collects the most terms of any numerator or denominator. Memoised by
// node, as Bound.
class FractionBound {
 public:
  struct Factor {
    int exponent = 0;
    double terms = 1;  // of the base
  };
  struct Fraction {
    double numerator = 1;
    std::map<Expr, Factor, GiNaC::ex_is_less> denominator;
  };

  Fraction operator()(const Expr& e) {
    if (e.nops() == 0) return {};
    const auto* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(node); it != memo_.end()) return it->second.second;
    Fraction f;
    if (GiNaC::is_a<GiNaC::add>(e)) {
      f.numerator = overall_coefficient(e).is_zero() ? 0 : 1;
      for (const GiNaC::expair& term : expairs(e)) f = sum(f, (*this)(term.rest));
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
      for (const GiNaC::expair& factor : expairs(e)) {
        const Fraction g = power(factor.rest, factor.coeff);
        f.numerator *= g.numerator;
        for (const auto& [base, d] : g.denominator) {
          Factor& mine = f.denominator[base];
          mine.exponent += d.exponent;
          mine.terms = d.terms;
        }
      }
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
      f = power(e.op(0), e.op(1));
    } else {
      for (std::size_t i = 0; i < e.nops(); ++i) (*this)(e.op(i));
    }
    if (!std::isfinite(f.numerator)) f.numerator = kInfinity;
    largest = std::max({largest, f.numerator, terms_of(f.denominator)});
    memo_.emplace(node, std::make_pair(e, f));
    return f;
  }

  double largest = 1;

 private:
  using Denominator = std::map<Expr, Factor, GiNaC::ex_is_less>;

  // The terms of a denominator multiplied out, or of the part of `d` that `by` lacks.
  static double terms_of(const Denominator& d, const Denominator* by = nullptr) {
    double terms = 1;
    for (const auto& [base, factor] : d) {
      int exponent = factor.exponent;
      if (by != nullptr) {
        if (const auto it = by->find(base); it != by->end()) exponent -= it->second.exponent;
      }
      if (exponent > 0 && factor.terms > 1) terms *= multinomial_terms(exponent, factor.terms);
    }
    return std::isfinite(terms) ? terms : kInfinity;
  }

  // a + b over the least common multiple of their denominators
  static Fraction sum(const Fraction& a, const Fraction& b) {
    Fraction f;
    f.denominator = a.denominator;
    for (const auto& [base, d] : b.denominator) {
      Factor& mine = f.denominator[base];
      mine.exponent = std::max(mine.exponent, d.exponent);
      mine.terms = d.terms;
    }
    f.numerator = a.numerator * terms_of(f.denominator, &a.denominator) +
                  b.numerator * terms_of(f.denominator, &b.denominator);
    return f;
  }

  Fraction power(const Expr& base, const Expr& exponent) {
    if (exponent.is_equal(1)) return (*this)(base);
    const Fraction f = (*this)(base);
    if (!GiNaC::is_exactly_a<GiNaC::numeric>(exponent) ||
        !exponent.info(GiNaC::info_flags::integer)) {
      (*this)(exponent);
      return {};
    }
    const int k = GiNaC::ex_to<GiNaC::numeric>(exponent).to_int();
    Fraction raised;
    if (k > 0) {
      raised.numerator = f.numerator > 1 ? multinomial_terms(k, f.numerator) : 1;
      raised.denominator = f.denominator;
      for (auto& [b, d] : raised.denominator) d.exponent *= k;
      return raised;
    }
    // (n/d)^−k = d^k / n^k: the base's numerator a factor of the denominator, under its own name
    raised.numerator = multinomial_terms(-k, terms_of(f.denominator));
    if (!std::isfinite(raised.numerator)) raised.numerator = kInfinity;
    raised.denominator[base] = Factor{-k, f.numerator};
    return raised;
  }

  std::unordered_map<const GiNaC::basic*, std::pair<Expr, Fraction>> memo_;
};

// Whether base^exponent is a factor that GiNaC's expand leaves as it is: a power of a symbol, a
// number, a constant or a function (whose arguments expand leaves alone), not of a sum (which it
// multiplies out, or, for a negative exponent, expands inside) nor of anything else (left to it).
bool expanded_factor(const Expr& base, const Expr& exponent) {
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(exponent)) return false;
  return GiNaC::is_a<GiNaC::symbol>(base) || GiNaC::is_a<GiNaC::numeric>(base) ||
         GiNaC::is_a<GiNaC::constant>(base) || GiNaC::is_a<GiNaC::function>(base);
}

// Whether a term (not a sum) is a monomial of such factors.
bool expanded_term(const Expr& t) {
  if (GiNaC::is_exactly_a<GiNaC::mul>(t)) {
    for (const GiNaC::expair& p : expairs(t)) {
      if (!expanded_factor(p.rest, p.coeff)) return false;
    }
    return true;
  }
  if (GiNaC::is_exactly_a<GiNaC::power>(t)) return expanded_factor(t.op(0), t.op(1));
  return expanded_factor(t, 1);
}

}  // namespace

bool is_expanded(const Expr& e) {
  if (!GiNaC::is_exactly_a<GiNaC::add>(e)) return expanded_term(e);
  for (const GiNaC::expair& p : expairs(e)) {
    if (!expanded_term(p.rest)) return false;
  }
  return true;
}

double expanded_terms_bound(const Expr& e) {
  Bound bound;
  bound(e);
  return bound.largest;
}

double largest_power_terms(const Expr& e) {
  Bound bound;
  bound(e);
  return bound.largest_power;
}

// The expansion made one product at a time, each checked before it is made: the terms of a
// product of two expanded sums (before like terms combine) are the product of their counts, and
// a power of a sum of k terms has C(n + k − 1, k − 1). Used when the structural bound is over the
// budget; that bound is loose where like terms combine, as they do in mechanics (a product of
// sums of the same sines and cosines), so the expansion itself decides.
class CheckedExpansion {
 public:
  explicit CheckedExpansion(std::string_view what) : what_(what) {}

  Expr operator()(const Expr& e) {
    const auto* node = &GiNaC::ex_to<GiNaC::basic>(e);
    if (const auto it = memo_.find(node); it != memo_.end()) return it->second.second;
    Expr result;
    if (GiNaC::is_a<GiNaC::add>(e)) {
      GiNaC::exvector terms;
      for (const auto& term : e) terms.push_back((*this)(term));
      result = GiNaC::add(terms);
      check(terms_of(result));
    } else if (GiNaC::is_a<GiNaC::mul>(e)) {
      result = 1;
      for (const auto& factor : e) result = multiply(result, (*this)(factor));
    } else if (GiNaC::is_a<GiNaC::power>(e) && e.op(1).info(GiNaC::info_flags::posint)) {
      const Expr base = (*this)(e.op(0));
      const double k = terms_of(base);
      const double n = GiNaC::ex_to<GiNaC::numeric>(e.op(1)).to_double();
      if (k > 1) check(multinomial_terms(n, k));
      result = GiNaC::pow(base, e.op(1)).expand();
    } else if (GiNaC::is_a<GiNaC::power>(e)) {
      result = GiNaC::pow((*this)(e.op(0)), e.op(1)).expand();
    } else {
      result = e.expand();  // symbols, numbers, functions (whose arguments expand() leaves alone)
    }
    memo_.emplace(node, std::make_pair(e, result));
    return result;
  }

 private:
  static double terms_of(const Expr& e) {
    return GiNaC::is_a<GiNaC::add>(e) ? static_cast<double>(e.nops()) : 1.0;
  }

  Expr multiply(const Expr& a, const Expr& b) {
    check(terms_of(a) * terms_of(b));
    return (a * b).expand();
  }

  void check(double terms) const {
    if (!(terms > kMaxExpandedTerms)) return;
    char count[64];
    std::snprintf(count, sizeof count, "%.3g", terms);
    throw ExpressionTooLarge(
        std::string(what_) + ": an expansion would make " + count + " terms, past the budget of " +
        std::to_string(static_cast<long>(kMaxExpandedTerms)) + " (a power of a long sum?)");
  }

  std::string_view what_;
  std::unordered_map<const GiNaC::basic*, std::pair<Expr, Expr>> memo_;  // as Bound's
};

void check_expansion_budget(const Expr& e, std::string_view what) {
  if (expanded_terms_bound(e) > kMaxExpandedTerms) CheckedExpansion{what}(e);
}

Expr expand_within_budget(const Expr& e, std::string_view what) {
  // a sum of monomials is its own expansion (GiNaC's expand would walk it to give it back)
  if (is_expanded(e)) return e;
  // the structural bound is quick; when it allows, GiNaC's own expansion is safe
  if (expanded_terms_bound(e) <= kMaxExpandedTerms) return e.expand();
  return CheckedExpansion{what}(e);
}

double fraction_terms_bound(const Expr& e) {
  FractionBound bound;
  bound(e);
  return bound.largest;
}

bool normal_affordable(const Expr& e) {
  return !has_denominator(e) || fraction_terms_bound(e) <= kMaxNormalTerms;
}

Expr normal_within_budget(const Expr& e, std::string_view what) {
  check_expansion_budget(e, what);
  if (!normal_affordable(e)) {
    char count[64];
    std::snprintf(count, sizeof count, "%.3g", fraction_terms_bound(e));
    throw ExpressionTooLarge(std::string(what) + ": one fraction of it would multiply out " +
                             count + " terms, past the budget of " +
                             std::to_string(static_cast<long>(kMaxNormalTerms)) +
                             " for a common denominator (a power of a long sum in a denominator?)");
  }
  return canonical_normal(e);
}

}  // namespace unidyn
