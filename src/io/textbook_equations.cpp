// Lagrange's equations in the book's form.
#include "unidyn/io/textbook_equations.hpp"

#include <cctype>

#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

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
                             EquationFormat format) {
  const bool latex = format == EquationFormat::latex;
  const auto& q = system.coordinates();
  std::vector<Expr> rates, accelerations;
  for (const auto& c : q) {
    rates.push_back(c.rate);
    accelerations.push_back(c.acceleration);
  }
  const auto T_terms = texts(group_by_monomials(eq.kinetic_energy, rates), latex);
  const Expr U = textbook_simplify(eq.potential_energy);
  const std::string U_text = latex ? to_latex(U) : to_text(U);
  const bool constrained = !system.constraints.empty();
  out << (latex ? "% " : "") << system.name << ": Lagrange's equations"
      << (constrained ? ", the constraint forces sum_k lambda_k a_k on the right" : "") << "\n";
  // the lines of align, each labelled (eq:<coordinate> or eq:<constraint>)
  std::vector<std::string> lines;
  if (latex) {
    lines.push_back(latex_equation("T = ", T_terms, " \\nonumber"));
    lines.push_back("  & U = " + U_text + " \\nonumber");
  } else {
    out << "  T = " << join_terms(T_terms) << "\n";
    out << "  U = " << U_text << "\n";
  }
  for (std::size_t i = 0; i < q.size(); ++i) {
    // Σ_j M_ij q̈^j, then −f_i by products of rates
    std::vector<GroupedTerm> left;
    for (std::size_t j = 0; j < q.size(); ++j) {
      const Expr m = textbook_simplify(eq.mass_matrix(i, j));
      if (!m.is_zero()) left.push_back({m, accelerations[j]});
    }
    for (GroupedTerm& t : group_by_monomials(-eq.forcing[i], rates)) left.push_back(t);
    // Σ_k λ_k a_k^i, by multiplier
    Expr right = 0;
    std::vector<Expr> multipliers;
    for (std::size_t k = 0; k < system.constraints.size(); ++k) {
      right += system.constraints[k].multiplier * eq.constraint_matrix(k, i);
      multipliers.push_back(system.constraints[k].multiplier);
    }
    const std::string rhs = join_terms(texts(group_by_monomials(right, multipliers), latex));
    if (latex) {
      lines.push_back(
          latex_equation("", texts(left, true), " = " + rhs + " \\label{eq:" + q[i].name + "}"));
    } else {
      out << "  [" << q[i].name << "]  " << join_terms(texts(left, false)) << " = " << rhs << "\n";
    }
  }
  for (const auto& c : system.constraints) {
    const Expr psi = textbook_simplify(c.expression);
    if (latex) {
      lines.push_back("  & " + to_latex(psi) + " = 0" +
                      (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") +
                      " \\label{eq:" + c.name + "}");
    } else {
      out << "  constraint " << c.name << " ("
          << (c.kind == Constraint::Kind::position ? "position" : "velocity")
          << (c.unilateral ? ", unilateral" : "") << "): " << to_text(psi) << " = 0, multiplier "
          << to_text(c.multiplier) << "\n";
    }
  }
  if (latex) {
    out << "\\begin{align}\n";
    for (std::size_t k = 0; k < lines.size(); ++k) {
      out << lines[k] << (k + 1 < lines.size() ? " \\\\\n" : "\n");
    }
    out << "\\end{align}\n";
  }
}

}  // namespace unidyn
