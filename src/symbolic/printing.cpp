// Simplification for display and printing.
#include "unidyn/symbolic/printing.hpp"

#include <sstream>

namespace unidyn {
namespace {

// Every distinct x appearing as sin(x) or cos(x).
GiNaC::exset trig_arguments(const Expr& e) {
  GiNaC::exset found;
  GiNaC::exset arguments;
  e.find(GiNaC::sin(GiNaC::wild()), found);
  e.find(GiNaC::cos(GiNaC::wild()), found);
  for (const auto& f : found) arguments.insert(f.op(0));
  return arguments;
}

// An expanded p, polynomial in v, with every v^k (k ≥ 2) replaced by v^(k−2) (1 − w²): its
// remainder modulo v² + w² − 1. Anything not polynomial in v is left as it is.
Expr reduce_modulo_unit_circle(const Expr& p, const GiNaC::symbol& v, const GiNaC::symbol& w) {
  if (!p.is_polynomial(v)) return p;
  Expr result = p;
  for (int k = p.degree(v); k >= 2; --k) {
    const Expr a = result.coeff(v, k);
    result = (result - a * GiNaC::pow(v, k) + a * GiNaC::pow(v, k - 2) * (1 - GiNaC::pow(w, 2)))
                 .expand();
  }
  return result;
}

// The smallest of e and its rewrites with sin²x → 1 − cos²x and cos²x → 1 − sin²x. Done on
// polynomials in s = sin x, c = cos x (numerator and denominator separately), so that the result
// does not depend on the order GiNaC happens to keep terms in.
Expr reduce_pythagorean(const Expr& e, const Expr& x) {
  const GiNaC::symbol s("s"), c("c");
  const GiNaC::exmap to_symbols{{GiNaC::sin(x), s}, {GiNaC::cos(x), c}};
  const GiNaC::exmap back{{s, GiNaC::sin(x)}, {c, GiNaC::cos(x)}};
  const Expr fraction = GiNaC::numer_denom(e.subs(to_symbols));
  const Expr numerator = fraction.op(0).expand(), denominator = fraction.op(1).expand();
  Expr best = e;
  for (const auto& [v, w] : {std::pair{s, c}, std::pair{c, s}}) {
    const Expr candidate =
        (reduce_modulo_unit_circle(numerator, v, w) / reduce_modulo_unit_circle(denominator, v, w))
            .subs(back)
            .expand();
    if (expression_size(candidate) < expression_size(best)) best = candidate;
  }
  return best;
}

}  // namespace

std::size_t expression_size(const Expr& e) {
  std::size_t size = 1;
  for (std::size_t i = 0; i < e.nops(); ++i) size += expression_size(e.op(i));
  return size;
}

Expr simplify(const Expr& e) {
  Expr result = e.expand();
  // A rational function is brought to one fraction only when that is smaller.
  const Expr normal = GiNaC::normal(result);
  if (expression_size(normal) < expression_size(result)) result = normal.expand();
  // Until nothing shrinks: reducing in one angle can expose a reduction in another.
  for (bool shrinking = true; shrinking;) {
    shrinking = false;
    for (const auto& x : trig_arguments(result)) {
      const Expr reduced = reduce_pythagorean(result, x);
      if (expression_size(reduced) < expression_size(result)) {
        result = reduced;
        shrinking = true;
      }
    }
  }
  return result;
}

Expr collect_in(const Expr& e, const std::vector<Expr>& symbols) {
  GiNaC::lst list;
  for (const auto& s : symbols) list.append(s);
  return GiNaC::collect(simplify(e), list);
}

std::string to_text(const Expr& e) {
  std::ostringstream out;
  out << e;
  return out.str();
}

std::string to_latex(const Expr& e) {
  std::ostringstream out;
  out << GiNaC::latex << e;
  return out.str();
}

}  // namespace unidyn
