// Partial derivatives by the rules of the calculus, without GiNaC's exception per function.
#include "unidyn/symbolic/derivative.hpp"

#include "unidyn/symbolic/trig_functions.hpp"

#include <vector>

namespace unidyn {
namespace {

using GiNaC::is_exactly_a;

// The nonzero partial derivatives of an expression: (index of the variable, ∂e/∂x_index), in
// increasing index.
using Partials = std::vector<std::pair<std::size_t, Expr>>;

// (a + b)' = a' + b': each variable's terms in the order of e's, the zero sums dropped
Partials sum_partials(const std::vector<std::vector<Expr>>& terms) {
  Partials partials;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    if (terms[k].empty()) continue;
    Expr d = sum_of(terms[k]);
    if (!d.is_zero()) partials.emplace_back(k, std::move(d));
  }
  return partials;
}

// ∂e/∂x_k for every k at once: one walk through e, each of its sums and products taken apart once
// (GiNaC rebuilds a sum's term each time it is asked for one).
Partials partials(const Expr& e, const std::vector<Expr>& xs) {
  // ∂x/∂x = 1; numbers and other symbols are constant
  if (is_exactly_a<GiNaC::numeric>(e)) return {};
  if (GiNaC::is_a<GiNaC::symbol>(e)) {
    for (std::size_t k = 0; k < xs.size(); ++k) {
      if (e.is_equal(xs[k])) return {{k, 1}};
    }
    return {};
  }
  // (a + b)' = a' + b'
  if (is_exactly_a<GiNaC::add>(e)) {
    std::vector<std::vector<Expr>> terms(xs.size());
    for (std::size_t i = 0; i < e.nops(); ++i) {
      for (auto& [k, d] : partials(e.op(i), xs)) terms[k].push_back(std::move(d));
    }
    return sum_partials(terms);
  }
  // (a b c)' = a' b c + a b' c + a b c'
  if (is_exactly_a<GiNaC::mul>(e)) {
    std::vector<Expr> factors(e.begin(), e.end());
    std::vector<std::vector<Expr>> terms(xs.size());
    for (std::size_t i = 0; i < factors.size(); ++i) {
      const Partials p = partials(factors[i], xs);
      if (p.empty()) continue;
      const Expr factor = factors[i];
      for (const auto& [k, d] : p) {
        factors[i] = d;
        terms[k].push_back(GiNaC::dynallocate<GiNaC::mul>(factors));
      }
      factors[i] = factor;
    }
    return sum_partials(terms);
  }
  // the chain rule through f(u): f'(u) ∂u/∂x_k
  const auto chain = [&](const Expr& u, const auto& f_prime) {
    Partials p = partials(u, xs);
    if (p.empty()) return p;
    const Expr f = f_prime();
    for (auto& [k, d] : p) d = f * d;
    return p;
  };
  // (b^n)' = n b^(n−1) b' for a number n
  if (is_exactly_a<GiNaC::power>(e) && is_exactly_a<GiNaC::numeric>(e.op(1))) {
    const Expr b = e.op(0), n = e.op(1);
    return chain(b, [&] { return n * GiNaC::pow(b, n - 1); });
  }
  // sin(u)' = cos(u) u', cos(u)' = −sin(u) u'
  const Expr u = e.nops() == 1 ? e.op(0) : Expr(0);
  if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e)) return chain(u, [&] { return cosine_of(u); });
  if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) return chain(u, [&] { return -sine_of(u); });
  // anything else by GiNaC
  Partials p;
  for (std::size_t k = 0; k < xs.size(); ++k) {
    if (Expr d = e.diff(GiNaC::ex_to<GiNaC::symbol>(xs[k])); !d.is_zero())
      p.emplace_back(k, std::move(d));
  }
  return p;
}

}  // namespace

Expr derivative(const Expr& e, const GiNaC::symbol& x) {
  const Partials p = partials(e, {Expr(x)});
  return p.empty() ? Expr(0) : p.front().second;
}

std::vector<Expr> gradient(const Expr& e, const std::vector<Expr>& xs) {
  std::vector<Expr> g(xs.size(), 0);
  for (auto& [k, d] : partials(e, xs)) g[k] = std::move(d);
  return g;
}

}  // namespace unidyn
