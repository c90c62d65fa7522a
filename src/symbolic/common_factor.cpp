// Pulling the common monomial out of a sum.
#include "unidyn/symbolic/common_factor.hpp"

#include <map>
#include <string>
#include <vector>

#include "unidyn/symbolic/canonical_text.hpp"

namespace unidyn {
namespace {

using GiNaC::is_exactly_a;

// A term as its number and its factors base^exponent (exponent a positive number), by the
// base's canonical text.
struct Monomial {
  GiNaC::numeric number = 1;
  std::map<std::string, std::pair<Expr, GiNaC::numeric>> powers;
};
Monomial monomial_of(const Expr& term) {
  Monomial m;
  const auto take = [&m](const Expr& f) {
    if (is_exactly_a<GiNaC::numeric>(f)) {
      m.number *= GiNaC::ex_to<GiNaC::numeric>(f);
      return;
    }
    Expr base = f;
    GiNaC::numeric exponent = 1;
    if (is_exactly_a<GiNaC::power>(f)) {
      // a symbolic or negative exponent: never common
      if (!is_exactly_a<GiNaC::numeric>(f.op(1)) ||
          !GiNaC::ex_to<GiNaC::numeric>(f.op(1)).is_positive()) {
        return;
      }
      base = f.op(0);
      exponent = GiNaC::ex_to<GiNaC::numeric>(f.op(1));
    }
    m.powers[canonical_text(base)] = {base, exponent};
  };
  if (is_exactly_a<GiNaC::mul>(term)) {
    for (std::size_t i = 0; i < term.nops(); ++i) take(term.op(i));
  } else {
    take(term);
  }
  return m;
}

}  // namespace

Expr pull_common_factor(const Expr& e) {
  if (!is_exactly_a<GiNaC::add>(e)) return e;
  std::vector<Monomial> terms;
  for (std::size_t i = 0; i < e.nops(); ++i) terms.push_back(monomial_of(e.op(i)));
  // the bases in every term, at their least power
  std::map<std::string, std::pair<Expr, GiNaC::numeric>> common = terms.front().powers;
  for (const Monomial& m : terms) {
    for (auto it = common.begin(); it != common.end();) {
      const auto found = m.powers.find(it->first);
      if (found == m.powers.end()) {
        it = common.erase(it);
        continue;
      }
      if (found->second.second < it->second.second) it->second.second = found->second.second;
      ++it;
    }
  }
  // the number: gcd of the numerators over the lcm of the denominators
  bool rational = true;
  GiNaC::numeric numerators = 0, denominators = 1;
  for (const Monomial& m : terms) {
    rational = rational && m.number.is_rational();
    if (!rational) break;
    numerators = GiNaC::gcd(numerators, m.number.numer());
    denominators = GiNaC::lcm(denominators, m.number.denom());
  }
  Expr factor = rational ? Expr(numerators / denominators) : Expr(1);
  for (const auto& [text, power] : common) factor *= GiNaC::pow(power.first, power.second);
  if (factor.is_equal(1)) return e;
  std::vector<Expr> inner;
  for (std::size_t i = 0; i < e.nops(); ++i) inner.push_back(e.op(i) / factor);
  return factor * sum_of(inner);
}

}  // namespace unidyn
