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

namespace {

// The terms of Lagrange's equations as the book writes them: T and U, each equation's left side
// (Σ_j M_ij q̈^j, then −f_i by products of rates) and right side (Σ_k λ_k a_k^i, by the
// multipliers), each constraint; the intermediate quantities z, when named.
struct LagrangeTerms {
  std::vector<GroupedTerm> T, U, psi;
  std::vector<std::vector<GroupedTerm>> left, right, forcing;
  ExprMatrix M;
  Intermediates z;
};

// U, the constraints Ψ_k and the constraint forces Σ_k λ_k a_k^i of each equation.
void constraint_terms(const System& system, const EquationsOfMotion& eq, LagrangeTerms& terms) {
  std::vector<Expr> multipliers;
  for (const auto& c : system.constraints) multipliers.push_back(c.multiplier);
  const std::size_t n = system.coordinates().size();
  terms.U = {{eq.potential_energy, 1}};
  for (const auto& c : system.constraints) terms.psi.push_back({c.expression, 1});
  terms.right.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    Expr sum = 0;
    for (std::size_t k = 0; k < system.constraints.size(); ++k) {
      sum += multipliers[k] * eq.constraint_matrix(k, i);
    }
    terms.right[i] = group_by_monomials(sum, multipliers, as_it_is);
  }
}

// M entry by entry, M_ji taken from M_ij where they are equal (M is symmetric); simplified
// together with the coefficients free of M (so that the processes share more work at once).
void short_mass_matrix(const EquationsOfMotion& eq, LagrangeTerms& terms) {
  const std::size_t n = eq.mass_matrix.rows;
  std::vector<bool> mirrored(n * n, false);
  std::vector<Expr> entries;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      mirrored[i * n + j] =
          j < i && vanishes_identically(eq.mass_matrix(i, j) - eq.mass_matrix(j, i)) == true;
      if (!mirrored[i * n + j]) entries.push_back(eq.mass_matrix(i, j));
    }
  }
  for (const auto* group : {&terms.U, &terms.psi}) {
    for (const GroupedTerm& t : *group) entries.push_back(t.coefficient);
  }
  for (const auto& group : terms.right) {
    for (const GroupedTerm& t : group) entries.push_back(t.coefficient);
  }
  const std::vector<Expr> short_entries = textbook_simplify_all(entries);
  terms.M = ExprMatrix(n, n);
  for (std::size_t i = 0, k = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      terms.M(i, j) = mirrored[i * n + j] ? terms.M(j, i) : short_entries[k++];
    }
  }
}

// T and the convective terms read off the short M by the covariant form (4.30) where exact
// evaluation shows them equal to the derived ones; else dug out of the derived expressions. Then
// −f_i = c_i + ∂U/∂q^i − Φ_i of each equation, by products of rates.
void kinetic_terms(const System& system, const EquationsOfMotion& eq, LagrangeTerms& terms) {
  const auto& q = system.coordinates();
  std::vector<Expr> rates;
  for (const auto& c : q) rates.push_back(c.rate);
  const std::optional<Expr> quadratic = quadratic_kinetic_energy(system, eq, terms.M);
  const std::vector<std::optional<Expr>> convective =
      covariant_convective_terms(system, eq, terms.M);
  end_phase("print: convective terms (4.25)");
  terms.T = group_by_monomials(quadratic.value_or(eq.kinetic_energy), rates, as_it_is);
  end_phase("print: T grouped");
  terms.forcing.resize(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    const Expr minus_forcing =
        convective[i]
            ? *convective[i] + derivative(eq.potential_energy, q[i].value) - eq.generalized_force[i]
            : -eq.forcing[i];
    terms.forcing[i] = group_by_monomials(minus_forcing, rates, as_it_is);
  }
  end_phase("print: equations, grouped");
}

// Every coefficient in the book's form at once (M's and those free of M remembered from above),
// the vanishing ones dropped; then each left side: its row of M, then −f_i's terms.
void simplify_coefficients(const System& system, LagrangeTerms& terms) {
  std::vector<std::vector<GroupedTerm>*> groups{&terms.T, &terms.U, &terms.psi};
  for (auto* sides : {&terms.forcing, &terms.right}) {
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
    if (group == &terms.U || group == &terms.psi) continue;
    std::erase_if(*group, [](const GroupedTerm& t) { return t.coefficient.is_zero(); });
  }
  const auto& q = system.coordinates();
  terms.left.resize(q.size());
  for (std::size_t i = 0; i < q.size(); ++i) {
    for (std::size_t j = 0; j < q.size(); ++j) {
      if (!terms.M(i, j).is_zero()) terms.left[i].push_back({terms.M(i, j), q[j].acceleration});
    }
    terms.left[i].insert(terms.left[i].end(), terms.forcing[i].begin(), terms.forcing[i].end());
  }
  end_phase("print: coefficients (simplified)");
}

// --form zees: the coefficients' repeated subexpressions named z1, z2, …
void name_intermediates(LagrangeTerms& terms) {
  std::vector<GroupedTerm*> all;
  for (auto* group : {&terms.T, &terms.U, &terms.psi}) {
    for (GroupedTerm& t : *group) all.push_back(&t);
  }
  for (auto* sides : {&terms.left, &terms.right}) {
    for (auto& group : *sides) {
      for (GroupedTerm& t : group) all.push_back(&t);
    }
  }
  std::vector<Expr> printed;
  for (const GroupedTerm* t : all) printed.push_back(t->coefficient);
  terms.z = common_subexpressions(printed);
  for (std::size_t k = 0; k < all.size(); ++k) all[k]->coefficient = terms.z.expressions[k];
}

// The equations as text: z, T, U, each coordinate's equation, each constraint, a line each.
void write_lagrange_text(std::ostream& out, const System& system, const LagrangeTerms& terms) {
  const auto& q = system.coordinates();
  for (std::size_t k = 0; k < terms.z.names.size(); ++k) {
    out << "  " << terms.z.names[k] << " = " << to_text(terms.z.values[k]) << "\n";
  }
  out << "  T = " << join_terms(texts(terms.T, false)) << "\n";
  out << "  U = " << to_text(terms.U.front().coefficient) << "\n";
  for (std::size_t i = 0; i < q.size(); ++i) {
    out << "  [" << q[i].name << "]  " << join_terms(texts(terms.left[i], false)) << " = "
        << join_terms(texts(terms.right[i], false)) << "\n";
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    out << "  constraint " << c.name << " (" << constraint_kind_text(c)
        << "): " << to_text(terms.psi[k].coefficient) << " = 0, multiplier "
        << to_text(c.multiplier) << "\n";
  }
}

// The equations as LaTeX: one align, a line each, labelled eq:<coordinate> or eq:<constraint>.
void write_lagrange_latex(std::ostream& out, const System& system, const LagrangeTerms& terms) {
  const auto& q = system.coordinates();
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < terms.z.names.size(); ++k) {
    lines.push_back("  & " + to_latex(terms.z.names[k]) + " = " + to_latex(terms.z.values[k]) +
                    " \\nonumber");
  }
  lines.push_back(latex_equation("T = ", texts(terms.T, true), " \\nonumber"));
  lines.push_back("  & U = " + to_latex(terms.U.front().coefficient) + " \\nonumber");
  for (std::size_t i = 0; i < q.size(); ++i) {
    const std::string rhs = join_terms(texts(terms.right[i], true));
    lines.push_back(latex_equation("", texts(terms.left[i], true),
                                   " = " + rhs + " \\label{eq:" + q[i].name + "}"));
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    lines.push_back("  & " + to_latex(terms.psi[k].coefficient) + " = 0" +
                    (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") +
                    " \\label{eq:" + c.name + "}");
  }
  out << "\\begin{align}\n";
  for (std::size_t k = 0; k < lines.size(); ++k) {
    out << lines[k] << (k + 1 < lines.size() ? " \\\\\n" : "\n");
  }
  out << "\\end{align}\n";
}

}  // namespace

void write_textbook_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                             EquationFormat format, bool intermediates) {
  const bool latex = format == EquationFormat::latex;
  // every grouped term: U, the constraints and their forces, then M (with those free of M)
  LagrangeTerms terms;
  constraint_terms(system, eq, terms);
  short_mass_matrix(eq, terms);
  end_phase("print: mass matrix, U, constraint terms");
  // T and −f_i by the covariant form (4.30), their coefficients in the book's form
  kinetic_terms(system, eq, terms);
  simplify_coefficients(system, terms);
  if (intermediates) name_intermediates(terms);
  // the heading, then the equations
  const bool constrained = !system.constraints.empty();
  out << (latex ? "% " : "") << system.name << ": Lagrange's equations"
      << (constrained ? ", the constraint forces sum_k lambda_k a_k on the right" : "")
      << (intermediates ? ", with intermediate quantities z" : "") << "\n";
  if (latex) {
    write_lagrange_latex(out, system, terms);
  } else {
    write_lagrange_text(out, system, terms);
  }
  end_phase("print: written");
}

}  // namespace unidyn
