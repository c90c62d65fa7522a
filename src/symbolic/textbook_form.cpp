// Coefficients in their shortest printed form, sums grouped by monomials.
#include "unidyn/symbolic/textbook_form.hpp"

#include <algorithm>
#include <array>
#include <deque>
#include <map>
#include <numeric>

#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/common_factor.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/polynomial_degrees.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/trig_identities.hpp"

namespace unidyn {
namespace {

using GiNaC::is_exactly_a;

// Collected in the sines and cosines (Σ c_k × their monomial k), each c_k and then the whole with
// its common factor out.
Expr tidy(const Expr& e) {
  const Expr collected = collect_in_sines_and_cosines(e).value_or(e);
  // each factor of each term with its common factor out
  const auto tidy_term = [](const Expr& term) {
    if (!is_exactly_a<GiNaC::mul>(term)) return pull_common_factor(term);
    Expr product = 1;
    for (std::size_t k = 0; k < term.nops(); ++k) product *= pull_common_factor(term.op(k));
    return product;
  };
  if (!is_exactly_a<GiNaC::add>(collected)) return tidy_term(collected);
  std::vector<Expr> sum;
  for (std::size_t i = 0; i < collected.nops(); ++i) sum.push_back(tidy_term(collected.op(i)));
  return pull_common_factor(sum_of(sum));
}

}  // namespace

namespace {

Expr textbook_simplify_uncached(const Expr& e);

}  // namespace

Expr textbook_simplify(const Expr& e) {
  return remembered(e, textbook_simplify_uncached);
}

std::vector<Expr> textbook_simplify_all(const std::vector<Expr>& es) {
  return remembered_all(es, textbook_simplify_uncached);
}

namespace {

Expr textbook_simplify_uncached(const Expr& e) {
  const Expr simple = simplify(e);
  // the forms tried, and whether homogenised
  std::vector<std::pair<Expr, bool>> forms{{simple, false}};
  if (!trig_arguments(simple).empty()) {
    const Expr combined = combine_angle_sums(simple);
    const Expr homogenised = homogenize_trig(simple);
    forms.push_back({combined, false});
    forms.push_back({homogenised, true});
    // (homogenising expands first: where combining changed nothing but the expansion, the same)
    const bool changed = !combined.is_equal(expand_within_budget(simple, "simplifying"));
    forms.push_back({changed ? homogenize_trig(combined) : homogenised, true});
  }
  // the shortest print, overall and among the homogenised forms (ties: the canonical order)
  struct Best {
    Expr form;
    std::string text;
    bool held = false;
    void offer(const Expr& candidate, const std::string& t) {
      if (!held || t.size() < text.size() || (t.size() == text.size() && t < text)) {
        form = candidate;
        text = t;
        held = true;
      }
    }
  } best, homogeneous;
  // each distinct form and its tidy form, with their prints
  struct Printed {
    Expr form;
    std::string text;
  };
  std::deque<std::pair<Expr, std::array<Printed, 2>>> seen;
  const auto candidates = [&seen](const Expr& form) -> const std::array<Printed, 2>& {
    for (const auto& [earlier, printed] : seen) {
      if (earlier.is_equal(form)) return printed;
    }
    const Expr tidied = tidy(form);
    return seen
        .emplace_back(form, std::array<Printed, 2>{Printed{form, canonical_text(form)},
                                                   Printed{tidied, canonical_text(tidied)}})
        .second;
  };
  for (const auto& [form, homogenised] : forms) {
    for (const Printed& candidate : candidates(form)) {
      best.offer(candidate.form, candidate.text);
      if (homogenised) homogeneous.offer(candidate.form, candidate.text);
    }
  }
  // A sin²θ + C cos²θ reads as the book's, C + (A − C) sin²θ does not: a homogeneous form is
  // taken while it is at most 1.5 times as long as the shortest
  if (homogeneous.held && 2 * homogeneous.text.size() <= 3 * best.text.size()) {
    return homogeneous.form;
  }
  return best.form;
}

}  // namespace

Expr as_it_is(const Expr& e) {
  return e;
}

std::vector<GroupedTerm> group_by_monomials(const Expr& e, const std::vector<Expr>& symbols,
                                            Expr (*simplifier)(const Expr&)) {
  const Expr x = expand_within_budget(e, "grouping");
  std::map<std::vector<int>, std::vector<Expr>> groups;
  const PolynomialDegrees degrees_in_symbols(symbols);
  const auto add_term = [&](const Expr& term) {
    std::vector<int> exponents;
    Expr monomial = 1;
    const std::vector<std::optional<int>> degrees = degrees_in_symbols(term);
    for (std::size_t k = 0; k < symbols.size(); ++k) {
      const int d = degrees[k].value_or(0);
      exponents.push_back(d);
      if (d != 0) monomial *= GiNaC::pow(symbols[k], d);
    }
    groups[exponents].push_back(term / monomial);
  };
  if (is_exactly_a<GiNaC::add>(x)) {
    for (std::size_t i = 0; i < x.nops(); ++i) add_term(x.op(i));
  } else if (!x.is_zero()) {
    add_term(x);
  }
  std::vector<std::pair<std::vector<int>, Expr>> ordered;
  for (const auto& [exponents, terms] : groups) ordered.emplace_back(exponents, sum_of(terms));
  std::sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) {
    const int da = std::accumulate(a.first.begin(), a.first.end(), 0);
    const int db = std::accumulate(b.first.begin(), b.first.end(), 0);
    return da != db ? da > db : a.first > b.first;
  });
  std::vector<GroupedTerm> grouped;
  for (const auto& [exponents, coefficient] : ordered) {
    const Expr c = simplifier(coefficient);
    if (c.is_zero()) continue;
    Expr monomial = 1;
    for (std::size_t i = 0; i < symbols.size(); ++i)
      monomial *= GiNaC::pow(symbols[i], exponents[i]);
    grouped.push_back({c, monomial});
  }
  return grouped;
}

std::string join_terms(const std::vector<std::string>& texts) {
  if (texts.empty()) return "0";
  std::string line;
  for (const std::string& t : texts) {
    if (line.empty()) {
      line = t;
    } else if (t.starts_with("-")) {
      line += " - " + t.substr(1);
    } else {
      line += " + " + t;
    }
  }
  return line;
}

}  // namespace unidyn
