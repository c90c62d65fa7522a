// Greedy extraction of common factors from sums (the multivariate Horner scheme).
#include "unidyn/symbolic/horner_form.hpp"

#include <map>
#include <optional>
#include <string>
#include <utility>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/expairs.hpp"

namespace unidyn {
namespace {

using GiNaC::ex_to;
using GiNaC::is_a;
using GiNaC::numeric;

// A factor base^exponent.
using Factor = std::pair<Expr, numeric>;

// A term of a sum: c Π base^exponent.
struct Term {
  numeric coefficient;
  std::vector<Factor> factors;
};

// base^n before base'^n' in GiNaC's order (within one run) of the bases, then the exponents.
struct FactorLess {
  bool operator()(const Factor& a, const Factor& b) const {
    const int c = a.first.compare(b.first);
    return c != 0 ? c < 0 : a.second < b.second;
  }
};

class HornerForm : public GiNaC::map_function {
 public:
  Expr operator()(const Expr& e) override {
    if (!is_a<GiNaC::add>(e) && !is_a<GiNaC::mul>(e) && !is_a<GiNaC::power>(e) &&
        !is_a<GiNaC::function>(e)) {
      return e;
    }
    if (const auto done = treated_.find(e); done != treated_.end()) return done->second;
    const Expr result =
        is_a<GiNaC::add>(e) ? factored(terms(e)) + overall_coefficient(e) : e.map(*this);
    treated_.emplace(e, result);
    return result;
  }

 private:
  std::map<Expr, Expr, GiNaC::ex_is_less> treated_;
  std::map<Expr, std::string, GiNaC::ex_is_less> texts_;

  // The terms of a sum (its number aside), each factor treated first.
  std::vector<Term> terms(const Expr& sum) {
    std::vector<Term> out;
    for (const GiNaC::expair& pair : expairs(sum)) {
      Term t{ex_to<numeric>(pair.coeff), {}};
      const Expr& rest = pair.rest;
      if (is_a<GiNaC::mul>(rest)) {
        t.coefficient *= ex_to<numeric>(overall_coefficient(rest));
        for (const GiNaC::expair& f : expairs(rest)) add_factor(t, f.rest, ex_to<numeric>(f.coeff));
      } else if (is_a<GiNaC::power>(rest) && is_a<numeric>(rest.op(1))) {
        add_factor(t, rest.op(0), ex_to<numeric>(rest.op(1)));
      } else {
        add_factor(t, rest, 1);
      }
      out.push_back(std::move(t));
    }
    return out;
  }

  // base^n, treated, into t. A sum at an integer power with its canonical sign
  // (canonical_text.hpp), the rest of the sign going to t's number: GiNaC writes a sum in a product
  // as a − b or as −(b − a) by its order of the moment, and the factors to take out must not follow
  // that order.
  void add_factor(Term& t, const Expr& base, const numeric& n) {
    Expr b = (*this)(base);
    if (n.is_integer() && is_a<GiNaC::add>(b) && canonical_sign(b) < 0) {
      b = -b;
      if (n.is_odd()) t.coefficient = -t.coefficient;
    }
    t.factors.emplace_back(std::move(b), n);
  }

  // Σ terms with the factor the most terms hold taken out of them, a (Σ terms/a) + Σ the others,
  // each part again: each of k terms loses a factor, k − 1 multiplications fewer.
  Expr factored(std::vector<Term> terms) {
    const std::optional<Factor> a = terms.size() < 2 ? std::nullopt : most_shared(terms);
    if (!a) return sum(terms);
    std::vector<Term> with, without;
    for (Term& t : terms) {
      auto f = t.factors.begin();
      while (f != t.factors.end() && !(f->second == a->second && f->first.is_equal(a->first))) ++f;
      if (f == t.factors.end()) {
        without.push_back(std::move(t));
        continue;
      }
      t.factors.erase(f);
      with.push_back(std::move(t));
    }
    return GiNaC::pow(a->first, a->second) * factored(std::move(with)) +
           factored(std::move(without));
  }

  // The factor the most terms hold (at least two), the first in the canonical order among equals.
  std::optional<Factor> most_shared(const std::vector<Term>& terms) {
    std::map<Factor, int, FactorLess> held;  // base^n → the terms with it
    for (const Term& t : terms) {
      for (const auto& factor : t.factors) {
        if (factor.second.is_integer()) ++held[factor];
      }
    }
    const Factor* best = nullptr;
    int most = 1;
    for (const auto& [factor, k] : held) {
      if (k < most || (k == most && (!best || !first(factor, *best)))) continue;
      best = &factor;
      most = k;
    }
    if (!best) return std::nullopt;
    return *best;
  }

  // Whether base^n comes before b in the canonical order (by the bases, then the exponents).
  bool first(const Factor& a, const Factor& b) {
    if (a.first.is_equal(b.first)) return a.second < b.second;
    return text(a.first) < text(b.first);
  }

  const std::string& text(const Expr& e) {
    auto found = texts_.find(e);
    if (found == texts_.end()) found = texts_.emplace(e, canonical_text(e)).first;
    return found->second;
  }

  static Expr sum(const std::vector<Term>& terms) {
    GiNaC::exvector out;
    for (const Term& t : terms) {
      GiNaC::exvector product{t.coefficient};
      for (const auto& [base, n] : t.factors) product.push_back(GiNaC::pow(base, n));
      out.push_back(GiNaC::mul(product));
    }
    return GiNaC::add(out);
  }
};

}  // namespace

Expr horner_form(const Expr& e) {
  return HornerForm{}(e);
}

std::vector<Expr> horner_form(const std::vector<Expr>& es) {
  HornerForm form;
  std::vector<Expr> out;
  out.reserve(es.size());
  for (const Expr& e : es) out.push_back(form(e));
  return out;
}

}  // namespace unidyn
