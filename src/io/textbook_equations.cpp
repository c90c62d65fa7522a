// Lagrange's equations in the book's form.
#include "unidyn/io/textbook_equations.hpp"

#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

namespace unidyn {
namespace {

// Each grouped term's text, coefficient × monomial.
std::vector<std::string> texts(const std::vector<GroupedTerm>& terms, bool latex) {
  std::vector<std::string> out;
  for (const GroupedTerm& t : terms) {
    const Expr product = t.coefficient * t.monomial;
    out.push_back(latex ? to_latex(product) : to_text(product));
  }
  return out;
}

}  // namespace

void write_textbook_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                             EquationFormat format) {
  const bool latex = format == EquationFormat::latex;
  const auto& q = system.coordinates();
  std::vector<Expr> rates, accelerations;
  for (const auto& c : q) {
    rates.push_back(c.rate);
    accelerations.push_back(c.acceleration);
  }
  const std::string T = join_terms(texts(group_by_monomials(eq.kinetic_energy, rates), latex));
  const Expr U = textbook_simplify(eq.potential_energy);
  const std::string U_text = latex ? to_latex(U) : to_text(U);
  const bool constrained = !system.constraints.empty();
  out << (latex ? "% " : "") << system.name << ": Lagrange's equations"
      << (constrained ? ", the constraint forces sum_k lambda_k a_k on the right" : "") << "\n";
  if (latex) out << "\\begin{aligned}\n";
  out << (latex ? "  T &= " : "  T = ") << T << (latex ? " \\\\\n" : "\n");
  out << (latex ? "  U &= " : "  U = ") << U_text << (latex ? " \\\\\n" : "\n");
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
    const std::vector<GroupedTerm> right_terms = group_by_monomials(right, multipliers);
    const std::string lhs = join_terms(texts(left, latex));
    const std::string rhs = join_terms(texts(right_terms, latex));
    if (latex) {
      out << "  " << lhs << " &= " << rhs << " \\\\\n";
    } else {
      out << "  [" << q[i].name << "]  " << lhs << " = " << rhs << "\n";
    }
  }
  for (const auto& c : system.constraints) {
    const Expr psi = textbook_simplify(c.expression);
    if (latex) {
      out << "  " << to_latex(psi) << " &= 0"
          << (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") << " \\\\\n";
    } else {
      out << "  constraint " << c.name << " ("
          << (c.kind == Constraint::Kind::position ? "position" : "velocity")
          << (c.unilateral ? ", unilateral" : "") << "): " << to_text(psi) << " = 0, multiplier "
          << to_text(c.multiplier) << "\n";
    }
  }
  if (latex) out << "\\end{aligned}\n";
}

}  // namespace unidyn
