// The degrees of an expression in several symbols in one walk.
#include "unidyn/symbolic/polynomial_degrees.hpp"

#include <algorithm>
#include <set>
#include <unordered_map>

#include "unidyn/symbolic/expairs.hpp"

namespace unidyn {

using GiNaC::is_exactly_a;

PolynomialDegrees::PolynomialDegrees(const std::vector<Expr>& xs) : xs_(xs) {
  for (std::size_t k = 0; k < xs.size(); ++k) index_.emplace(xs[k], k);
}

std::vector<std::optional<int>> polynomial_degrees(const Expr& p, const std::vector<Expr>& xs) {
  return PolynomialDegrees(xs)(p);
}

std::vector<std::optional<int>> PolynomialDegrees::operator()(const Expr& p) const {
  const std::vector<Expr>& xs = xs_;
  const auto& index = index_;
  std::vector<int> degree(xs.size(), 0);
  std::vector<bool> polynomial(xs.size(), true);
  std::vector<int> term_degree(xs.size());
  // the indices of the symbols in an expression, once each
  std::set<std::size_t> present;
  const auto find_symbols = [&](const Expr& e) {
    const auto walk = [&](const Expr& x, const auto& self) -> void {
      if (GiNaC::is_a<GiNaC::symbol>(x)) {
        if (const auto found = index.find(x); found != index.end()) present.insert(found->second);
        return;
      }
      for (std::size_t i = 0; i < x.nops(); ++i) self(x.op(i), self);
    };
    walk(e, walk);
  };
  // the degree of a sum: the highest of its terms'; of a product: the sum of its factors' (read
  // as GiNaC keeps them: a term c·t as t, a factor as base^exponent)
  const auto add_term = [&](const Expr& term) {
    std::fill(term_degree.begin(), term_degree.end(), 0);
    const auto add_factor = [&](const Expr& base, const Expr& exponent) {
      if (is_exactly_a<GiNaC::numeric>(base)) return;
      // x or x^n, n an integer
      if (const auto found = index.find(base);
          found != index.end() && exponent.info(GiNaC::info_flags::integer)) {
        const int n = static_cast<int>(GiNaC::ex_to<GiNaC::numeric>(exponent).to_int());
        if (n < 0) polynomial[found->second] = false;
        term_degree[found->second] += n;
        return;
      }
      // another symbol, to a numeric power: none of the x_k
      if (GiNaC::is_a<GiNaC::symbol>(base) && is_exactly_a<GiNaC::numeric>(exponent) &&
          index.find(base) == index.end()) {
        return;
      }
      // anything else: by GiNaC, for the symbols in it
      const Expr f = exponent.is_equal(1) ? base : GiNaC::pow(base, exponent);
      present.clear();
      find_symbols(f);
      for (const std::size_t k : present) {
        if (!polynomial[k]) continue;
        if (f.is_polynomial(xs[k])) {
          term_degree[k] += f.degree(xs[k]);
        } else {
          polynomial[k] = false;
        }
      }
    };
    if (is_exactly_a<GiNaC::mul>(term)) {
      for (const GiNaC::expair& factor : expairs(term)) add_factor(factor.rest, factor.coeff);
    } else if (is_exactly_a<GiNaC::power>(term)) {
      add_factor(term.op(0), term.op(1));
    } else {
      add_factor(term, 1);
    }
    for (std::size_t k = 0; k < xs.size(); ++k) degree[k] = std::max(degree[k], term_degree[k]);
  };
  if (is_exactly_a<GiNaC::add>(p)) {
    for (const GiNaC::expair& term : expairs(p)) add_term(term.rest);
    // (the sum's number term: degree 0 in every x_k)
  } else {
    add_term(p);
  }
  std::vector<std::optional<int>> degrees;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    degrees.push_back(polynomial[k] ? std::optional<int>(degree[k]) : std::nullopt);
  }
  return degrees;
}

}  // namespace unidyn
