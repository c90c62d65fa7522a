// Partial derivatives by the rules of the calculus, without GiNaC's exception per function.
#include "unidyn/symbolic/derivative.hpp"

#include <vector>

namespace unidyn {

using GiNaC::is_exactly_a;

Expr derivative(const Expr& e, const GiNaC::symbol& x) {
  // ∂x/∂x = 1; numbers and other symbols are constant
  if (is_exactly_a<GiNaC::numeric>(e)) return 0;
  if (GiNaC::is_a<GiNaC::symbol>(e)) return e.is_equal(x) ? 1 : 0;
  // (a + b)' = a' + b'
  if (is_exactly_a<GiNaC::add>(e)) {
    std::vector<Expr> terms;
    for (std::size_t i = 0; i < e.nops(); ++i) {
      Expr d = derivative(e.op(i), x);
      if (!d.is_zero()) terms.push_back(std::move(d));
    }
    return sum_of(terms);
  }
  // (a b c)' = a' b c + a b' c + a b c'
  if (is_exactly_a<GiNaC::mul>(e)) {
    std::vector<Expr> factors(e.begin(), e.end()), terms;
    for (std::size_t i = 0; i < factors.size(); ++i) {
      Expr d = derivative(factors[i], x);
      if (d.is_zero()) continue;
      const Expr factor = factors[i];
      factors[i] = d;
      terms.push_back(GiNaC::dynallocate<GiNaC::mul>(factors));
      factors[i] = factor;
    }
    return sum_of(terms);
  }
  // (b^n)' = n b^(n−1) b' for a number n
  if (is_exactly_a<GiNaC::power>(e) && is_exactly_a<GiNaC::numeric>(e.op(1))) {
    const Expr d = derivative(e.op(0), x);
    if (d.is_zero()) return 0;
    return e.op(1) * GiNaC::pow(e.op(0), e.op(1) - 1) * d;
  }
  // sin(u)' = cos(u) u', cos(u)' = −sin(u) u'
  if (GiNaC::is_the_function<GiNaC::sin_SERIAL>(e)) {
    const Expr d = derivative(e.op(0), x);
    return d.is_zero() ? Expr(0) : GiNaC::cos(e.op(0)) * d;
  }
  if (GiNaC::is_the_function<GiNaC::cos_SERIAL>(e)) {
    const Expr d = derivative(e.op(0), x);
    return d.is_zero() ? Expr(0) : -GiNaC::sin(e.op(0)) * d;
  }
  return e.diff(x);
}

}  // namespace unidyn
