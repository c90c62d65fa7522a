// Lagrange's equations in the book's form.
#include "unidyn/io/textbook_equations.hpp"

#include <cctype>

#include "unidyn/equations/covariant_form.hpp"
#include "unidyn/io/phase_timings.hpp"
#include "unidyn/symbolic/common_subexpressions.hpp"
#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"
#include "unidyn/symbolic/zero_test.hpp"

namespace unidyn {
namespace {

// The terms of a printed sum: split at each + or − outside parentheses and braces (the first
// sign kept with its term).
std::vector<std::string> top_level_terms(const std::string& text) {
  std::vector<std::string> terms;
  int depth = 0;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '(' || c == '{' || c == '[') ++depth;
    if (c == ')' || c == '}' || c == ']') --depth;
    // not the sign of an exponent (x^-1, 1e-10)
    const bool exponent = text[i - (i > 0 ? 1 : 0)] == '^' ||
                          (i > 1 && text[i - 1] == 'e' && std::isdigit(text[i - 2]) != 0);
    if (depth == 0 && i > start && (c == '+' || c == '-') && !exponent) {
      terms.push_back(text.substr(start, i - start));
      start = c == '+' ? i + 1 : i;
    }
  }
  terms.push_back(text.substr(start));
  return terms;
}

// Each grouped term's text, coefficient × monomial; the terms free of the grouping symbols (the
// potential's and the applied forces') one by one.
std::vector<std::string> texts(const std::vector<GroupedTerm>& terms, bool latex) {
  std::vector<std::string> out;
  for (const GroupedTerm& t : terms) {
    const Expr product = t.coefficient * t.monomial;
    const std::string text = latex ? to_latex(product) : to_text(product);
    if (!t.monomial.is_equal(1) || !GiNaC::is_exactly_a<GiNaC::add>(t.coefficient)) {
      out.push_back(text);
      continue;
    }
    for (std::string& term : top_level_terms(text)) out.push_back(std::move(term));
  }
  return out;
}

}  // namespace

// One LaTeX equation of align: `lead`, the terms broken into lines of about 160 characters (each
// line after the first indented by \quad and not numbered), then `tail` ("= 0 \label{..}").
std::string latex_equation(const std::string& lead, const std::vector<std::string>& terms,
                           const std::string& tail) {
  std::string text = "  & " + lead, line;
  for (std::size_t k = 0; k < terms.size(); ++k) {
    std::string piece = terms[k];
    if (k > 0) piece = piece.starts_with("-") ? " - " + piece.substr(1) : " + " + piece;
    if (k > 0 && line.size() + piece.size() > 160) {
      text += line + " \\nonumber \\\\\n  &\\quad";
      line.clear();
    }
    line += piece;
  }
  return text + line + tail;
}

void write_textbook_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                             EquationFormat format, bool intermediates) {
  const bool latex = format == EquationFormat::latex;
  const auto& q = system.coordinates();
  std::vector<Expr> rates, accelerations, multipliers;
  for (const auto& c : q) {
    rates.push_back(c.rate);
    accelerations.push_back(c.acceleration);
  }
  for (const auto& c : system.constraints) multipliers.push_back(c.multiplier);
  // every grouped term: T, U, each equation's left and right side (Σ_j M_ij q̈^j and −f_i by
  // products of rates = Σ_k λ_k a_k^i), each constraint; those free of M first
  const std::size_t n = q.size();
  std::vector<GroupedTerm> U{{eq.potential_energy, 1}}, psi;
  for (const auto& c : system.constraints) psi.push_back({c.expression, 1});
  std::vector<std::vector<GroupedTerm>> right(n);
  for (std::size_t i = 0; i < n; ++i) {
    Expr sum = 0;
    for (std::size_t k = 0; k < system.constraints.size(); ++k) {
      sum += multipliers[k] * eq.constraint_matrix(k, i);
    }
    right[i] = group_by_monomials(sum, multipliers, as_it_is);
  }
  // M entry by entry, M_ji taken from M_ij where they are equal (M is symmetric); simplified
  // together with the coefficients free of M (so that the processes share more work at once)
  std::vector<bool> mirrored(n * n, false);
  std::vector<Expr> entries;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      mirrored[i * n + j] =
          j < i && vanishes_identically(eq.mass_matrix(i, j) - eq.mass_matrix(j, i)) == true;
      if (!mirrored[i * n + j]) entries.push_back(eq.mass_matrix(i, j));
    }
  }
  for (const auto* group : {&U, &psi}) {
    for (const GroupedTerm& t : *group) entries.push_back(t.coefficient);
  }
  for (const auto& group : right) {
    for (const GroupedTerm& t : group) entries.push_back(t.coefficient);
  }
  const std::vector<Expr> short_entries = textbook_simplify_all(entries);
  ExprMatrix M(n, n);
  for (std::size_t i = 0, k = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j)
      M(i, j) = mirrored[i * n + j] ? M(j, i) : short_entries[k++];
  }

  // T and the convective terms read off the short M by the covariant form (4.30) where exact
  // evaluation shows them equal to the derived ones; else dug out of the derived expressions
  end_phase("print: mass matrix, U, constraint terms");
  const std::optional<Expr> quadratic = quadratic_kinetic_energy(system, eq, M);
  const std::vector<std::optional<Expr>> convective = covariant_convective_terms(system, eq, M);
  end_phase("print: convective terms (4.25)");
  std::vector<GroupedTerm> T =
      group_by_monomials(quadratic.value_or(eq.kinetic_energy), rates, as_it_is);
  end_phase("print: T grouped");
  // each equation's left side: its row of M (simplified already), then −f_i's terms
  std::vector<std::vector<GroupedTerm>> left(n), forcing(n);
  for (std::size_t i = 0; i < n; ++i) {
    // −f_i = c_i + ∂U/∂q^i − Φ_i
    const Expr minus_forcing =
        convective[i]
            ? *convective[i] + derivative(eq.potential_energy, q[i].value) - eq.generalized_force[i]
            : -eq.forcing[i];
    forcing[i] = group_by_monomials(minus_forcing, rates, as_it_is);
  }
  end_phase("print: equations, grouped");
  // every coefficient in the book's form at once (M's and those free of M remembered from
  // above), the vanishing ones dropped
  std::vector<std::vector<GroupedTerm>*> groups{&T, &U, &psi};
  for (auto* sides : {&forcing, &right}) {
    for (auto& group : *sides) groups.push_back(&group);
  }
  std::vector<Expr> coefficients;
  for (const auto* group : groups) {
    for (const GroupedTerm& t : *group) coefficients.push_back(t.coefficient);
  }
  const std::vector<Expr> short_coefficients = textbook_simplify_all(coefficients);
  std::size_t next = 0;
  for (auto* group : groups) {
    for (GroupedTerm& t : *group) t.coefficient = short_coefficients[next++];
    // (U and the constraints keep their one term, 0 or not)
    if (group == &U || group == &psi) continue;
    std::erase_if(*group, [](const GroupedTerm& t) { return t.coefficient.is_zero(); });
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (!M(i, j).is_zero()) left[i].push_back({M(i, j), accelerations[j]});
    }
    left[i].insert(left[i].end(), forcing[i].begin(), forcing[i].end());
  }
  end_phase("print: coefficients (simplified)");
  // --form zees: the coefficients' repeated subexpressions named z1, z2, …
  std::vector<GroupedTerm*> all;
  for (auto* group : {&T, &U, &psi}) {
    for (GroupedTerm& t : *group) all.push_back(&t);
  }
  for (auto* sides : {&left, &right}) {
    for (auto& group : *sides) {
      for (GroupedTerm& t : group) all.push_back(&t);
    }
  }
  Intermediates z;
  if (intermediates) {
    std::vector<Expr> printed;
    for (const GroupedTerm* t : all) printed.push_back(t->coefficient);
    z = common_subexpressions(printed);
    for (std::size_t k = 0; k < all.size(); ++k) all[k]->coefficient = z.expressions[k];
  }
  const std::string U_text =
      latex ? to_latex(U.front().coefficient) : to_text(U.front().coefficient);
  const bool constrained = !system.constraints.empty();
  out << (latex ? "% " : "") << system.name << ": Lagrange's equations"
      << (constrained ? ", the constraint forces sum_k lambda_k a_k on the right" : "")
      << (intermediates ? ", with intermediate quantities z" : "") << "\n";
  // the lines of align, each labelled (eq:<coordinate> or eq:<constraint>)
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < z.names.size(); ++k) {
    if (latex) {
      lines.push_back("  & " + to_latex(z.names[k]) + " = " + to_latex(z.values[k]) +
                      " \\nonumber");
    } else {
      out << "  " << z.names[k] << " = " << to_text(z.values[k]) << "\n";
    }
  }
  if (latex) {
    lines.push_back(latex_equation("T = ", texts(T, true), " \\nonumber"));
    lines.push_back("  & U = " + U_text + " \\nonumber");
  } else {
    out << "  T = " << join_terms(texts(T, false)) << "\n";
    out << "  U = " << U_text << "\n";
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::string rhs = join_terms(texts(right[i], latex));
    if (latex) {
      lines.push_back(
          latex_equation("", texts(left[i], true), " = " + rhs + " \\label{eq:" + q[i].name + "}"));
    } else {
      out << "  [" << q[i].name << "]  " << join_terms(texts(left[i], false)) << " = " << rhs
          << "\n";
    }
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    if (latex) {
      lines.push_back("  & " + to_latex(psi[k].coefficient) + " = 0" +
                      (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") +
                      " \\label{eq:" + c.name + "}");
    } else {
      out << "  constraint " << c.name << " (" << constraint_kind_text(c)
          << "): " << to_text(psi[k].coefficient) << " = 0, multiplier " << to_text(c.multiplier)
          << "\n";
    }
  }
  if (latex) {
    out << "\\begin{align}\n";
    for (std::size_t k = 0; k < lines.size(); ++k) {
      out << lines[k] << (k + 1 < lines.size() ? " \\\\\n" : "\n");
    }
    out << "\\end{align}\n";
  }
  end_phase("print: written");
}

}  // namespace unidyn
