// Text, LaTeX and JSON forms of the derived equations.
#include "unidyn/io/equation_report.hpp"

#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

namespace unidyn {
namespace {

std::vector<Expr> accelerations(const System& system) {
  std::vector<Expr> symbols;
  for (const auto& q : system.coordinates()) symbols.push_back(q.acceleration);
  return symbols;
}

// Σ_k λ_k a_k^i: the constraint forces in row i.
Expr constraint_terms(const System& system, const EquationsOfMotion& eq, std::size_t i) {
  Expr sum = 0;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    sum += system.constraints[k].multiplier * eq.constraint_matrix(k, i);
  }
  return sum;
}

// Σ c_k m_k over the monomials m_k in `symbols`, each coefficient c_k simplified by itself (an
// expression as a whole took half a minute on the bicycle).
Expr simplified_by_monomials(const Expr& e, const std::vector<Expr>& symbols) {
  std::vector<Expr> terms;
  for (const GroupedTerm& t : group_by_monomials(e, symbols, simplify)) {
    terms.push_back(t.coefficient * t.monomial);
  }
  return sum_of(terms);
}

std::vector<Expr> rates(const System& system) {
  std::vector<Expr> symbols;
  for (const auto& q : system.coordinates()) symbols.push_back(q.rate);
  return symbols;
}

// One Lagrange row as (left side Σ M q̈, right side f + Σ λ a): each M_ij simplified, and each
// coefficient of a product of rates and multipliers on the right.
std::pair<Expr, Expr> lagrange_row(const System& system, const EquationsOfMotion& eq,
                                   std::size_t i) {
  const auto& q = system.coordinates();
  std::vector<Expr> left;
  for (std::size_t j = 0; j < q.size(); ++j) {
    left.push_back(simplify(eq.mass_matrix(i, j)) * q[j].acceleration);
  }
  std::vector<Expr> symbols = rates(system);
  for (const auto& c : system.constraints) symbols.push_back(c.multiplier);
  return {sum_of(left),
          simplified_by_monomials(eq.forcing[i] + constraint_terms(system, eq, i), symbols)};
}

// Everything lagrange_row, T, U and the constraints simplify, simplified at once (the work shared
// among processes, the results remembered for them).
void simplify_lagrange_rows(const System& system, const EquationsOfMotion& eq) {
  std::vector<Expr> all = eq.mass_matrix.data;
  std::vector<Expr> symbols = rates(system);
  for (const auto& c : system.constraints) {
    symbols.push_back(c.multiplier);
    all.push_back(c.expression);
  }
  const auto coefficients = [&all](const Expr& e, const std::vector<Expr>& in) {
    for (const GroupedTerm& t : group_by_monomials(e, in, as_it_is)) all.push_back(t.coefficient);
  };
  for (std::size_t i = 0; i < system.coordinates().size(); ++i) {
    coefficients(eq.forcing[i] + constraint_terms(system, eq, i), symbols);
  }
  coefficients(eq.kinetic_energy, rates(system));
  all.push_back(eq.potential_energy);
  simplify_all(all);
}

// A vector as "[x, y, z]" in text or LaTeX.
std::string render_vector(const VectorExpr& v, bool latex) {
  std::string text = latex ? "\\begin{bmatrix}" : "[";
  for (int k = 0; k < 3; ++k) {
    text += (k ? (latex ? " \\\\ " : ", ") : "") + (latex ? to_latex(v[k]) : to_text(v[k]));
  }
  return text + (latex ? "\\end{bmatrix}" : "]");
}

// A JSON string literal.
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out + "\"";
}

std::string render(const Expr& e, EquationFormat format) {
  return format == EquationFormat::latex ? to_latex(e) : to_text(e);
}

}  // namespace

void write_lagrange(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                    EquationFormat format) {
  const auto& q = system.coordinates();
  const auto& constraints = system.constraints;
  if (format == EquationFormat::json) {
    write_lagrange_json(out, system, eq);
    return;
  }
  simplify_lagrange_rows(system, eq);

  if (format == EquationFormat::latex) {
    out << "% " << system.name << ": Lagrange's equations, M q'' = f + A^T lambda\n";
    out << "\\[\n\\begin{aligned}\n";
    for (std::size_t i = 0; i < q.size(); ++i) {
      const auto [lhs, rhs] = lagrange_row(system, eq, i);
      out << "  " << to_latex(lhs) << " &= " << to_latex(rhs) << " \\\\\n";
    }
    for (const auto& c : constraints) {
      out << "  " << to_latex(simplify(c.expression)) << " &= 0"
          << (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") << " \\\\\n";
    }
    out << "  T &= " << to_latex(simplified_by_monomials(eq.kinetic_energy, rates(system)))
        << " \\\\\n";
    out << "  U &= " << to_latex(simplify(eq.potential_energy)) << "\n\\end{aligned}\n\\]\n";
    return;
  }

  out << system.name << ": Lagrange's equations"
      << (constraints.empty() ? "" : ", M q'' = f + A^T lambda (one multiplier per constraint)")
      << "\n";
  out << "  T = " << render(simplified_by_monomials(eq.kinetic_energy, rates(system)), format)
      << "\n";
  out << "  U = " << render(simplify(eq.potential_energy), format) << "\n";
  for (std::size_t i = 0; i < q.size(); ++i) {
    const auto [lhs, rhs] = lagrange_row(system, eq, i);
    out << "  [" << q[i].name << "]  " << to_text(lhs) << " = " << to_text(rhs) << "\n";
  }
  for (const auto& c : constraints) {
    out << "  constraint " << c.name << " ("
        << (c.kind == Constraint::Kind::position ? "position" : "velocity")
        << (c.unilateral ? ", unilateral" : "") << "): " << to_text(simplify(c.expression))
        << " = 0, multiplier " << c.multiplier << "\n";
  }
}

void write_second_form(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                       const SecondForm& form, EquationFormat format) {
  const auto& q = system.coordinates();
  // each moving particle's and body's partial velocities for coordinate A: label, LaTeX, vector
  struct Partial {
    std::string label, latex;
    VectorExpr v;
  };
  const auto partials = [&](std::size_t A) {
    std::vector<Partial> list;
    const auto add = [&](const std::string& name, const char* member, const std::string& symbol,
                         const VectorExpr& v) {
      if (v[0].is_zero() && v[1].is_zero() && v[2].is_zero()) return;
      list.push_back({name + member, symbol + "_{\\mathrm{" + name + "}}", v});
    };
    for (std::size_t p = 0; p < system.particles.size(); ++p) {
      add(system.particles[p].name, ".velocity", "\\mathbf{v}", form.particle_velocity[A][p]);
    }
    for (std::size_t b = 0; b < system.bodies.size(); ++b) {
      add(system.bodies[b].name, ".velocity", "\\bar{\\mathbf{v}}", form.center_velocity[A][b]);
      add(system.bodies[b].name, ".omega", "\\boldsymbol{\\omega}", form.angular_velocity[A][b]);
    }
    return list;
  };
  const auto lhs = [&](std::size_t A) {
    return collect_in(form.inertia_terms[A], accelerations(system));
  };
  const auto rhs = [&](std::size_t A) {
    return simplify(form.generalized_force[A] + constraint_terms(system, eq, A));
  };
  if (format == EquationFormat::json) {
    out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"second-form\",\n";
    out << "  \"equations\": [";
    for (std::size_t A = 0; A < q.size(); ++A) {
      out << (A ? ",\n    " : "\n    ") << "{\"coordinate\": " << quoted(q[A].name)
          << ", \"partial_velocities\": {";
      const auto list = partials(A);
      for (std::size_t i = 0; i < list.size(); ++i) {
        out << (i ? ", " : "") << quoted(list[i].label) << ": [";
        for (int k = 0; k < 3; ++k) out << (k ? ", " : "") << quoted(to_text(list[i].v[k]));
        out << "]";
      }
      out << "}, \"inertia_terms\": " << quoted(to_text(lhs(A)))
          << ", \"generalized_force\": " << quoted(to_text(rhs(A))) << "}";
    }
    out << "\n  ]\n}\n";
    return;
  }
  const bool latex = format == EquationFormat::latex;
  out << (latex ? "% " : "") << system.name
      << ": Lagrange's equations, second form (10.16): d/dt(dT/du'^A) - dT/du^A = Phi_A"
      << (system.constraints.empty() ? "" : " + sum_k lambda_k a_k^A")
      << ", Phi_A = sum F . dv/du'^A + M . domega/du'^A\n";
  if (latex) out << "\\[\n\\begin{aligned}\n";
  for (std::size_t A = 0; A < q.size(); ++A) {
    for (const Partial& partial : partials(A)) {
      if (latex) {
        out << "  \\frac{\\partial " << partial.latex << "}{\\partial " << to_latex(q[A].rate)
            << "} &= " << render_vector(partial.v, true) << " \\\\\n";
      } else {
        out << "  [" << q[A].name << "]  d(" << partial.label << ")/d(" << q[A].name
            << "') = " << render_vector(partial.v, false) << "\n";
      }
    }
    if (latex) {
      out << "  " << to_latex(lhs(A)) << " &= " << to_latex(rhs(A)) << " \\\\\n";
    } else {
      out << "  [" << q[A].name << "]  " << to_text(lhs(A)) << " = " << to_text(rhs(A)) << "\n";
    }
  }
  if (latex) out << "\\end{aligned}\n\\]\n";
}

void write_newton(std::ostream& out, const System& system, const NewtonEquations& newton,
                  EquationFormat format) {
  const char* axes[] = {"E1", "E2", "E3"};
  if (format == EquationFormat::json) {
    out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"newton-euler\",\n";
    // a vector as a JSON array of component strings, after a key
    const auto field = [&](const char* key, const VectorExpr& v) {
      out << ", " << quoted(key) << ": [";
      for (int k = 0; k < 3; ++k) out << (k ? ", " : "") << quoted(to_text(simplify(v[k])));
      out << "]";
    };
    out << "  \"particles\": [";
    for (std::size_t p = 0; p < system.particles.size(); ++p) {
      const ParticleBalance& b = newton.particles[p];
      out << (p ? ",\n    " : "\n    ") << "{\"name\": " << quoted(system.particles[p].name);
      field("mass_times_acceleration", b.mass_times_acceleration);
      field("applied_force", b.applied_force);
      out << "}";
    }
    out << "\n  ],\n  \"bodies\": [";
    for (std::size_t i = 0; i < system.bodies.size(); ++i) {
      const BodyBalance& b = newton.bodies[i];
      out << (i ? ",\n    " : "\n    ") << "{\"name\": " << quoted(system.bodies[i].name);
      field("mass_times_acceleration", b.mass_times_acceleration);
      field("applied_force", b.applied_force);
      field("momentum_rate", b.momentum_rate);
      field("applied_moment", b.applied_moment);
      out << "}";
    }
    out << "\n  ]\n}\n";
    return;
  }
  const bool latex = format == EquationFormat::latex;
  out << (latex ? "% " : "") << system.name
      << ": Newton's second law m a = F + R for each particle, Euler's laws m a = F + R and"
         " dH/dt = M + M_R (about the centre of mass) for each body (R, M_R: constraint force and"
         " moment)\n";
  if (latex) out << "\\[\n\\begin{aligned}\n";
  // One balance law, component by component: lhs_k = rhs_k + <unknown>_k
  const auto write_balance = [&](const std::string& label, const VectorExpr& lhs_vector,
                                 const VectorExpr& rhs_vector, const std::string& unknown) {
    for (int k = 0; k < 3; ++k) {
      const Expr lhs = collect_in(lhs_vector[k], accelerations(system));
      const Expr rhs = simplify(rhs_vector[k]);
      if (latex) {
        // R_{P,1}, M^{R}_{B.H,1}: the unknown's name upright, its subscripts after it
        const std::string symbol = unknown == "M_R" ? "M^{R}" : unknown;
        out << "  " << to_latex(lhs) << " &= " << to_latex(rhs) << " + " << symbol << "_{\\mathrm{"
            << label << "}," << k + 1 << "} \\\\\n";
      } else {
        out << "  [" << label << "." << axes[k] << "]  " << to_text(lhs) << " = " << to_text(rhs)
            << " + " << unknown << "_" << label << "." << axes[k] << "\n";
      }
    }
  };
  for (std::size_t p = 0; p < system.particles.size(); ++p) {
    const ParticleBalance& b = newton.particles[p];
    write_balance(system.particles[p].name, b.mass_times_acceleration, b.applied_force, "R");
  }
  for (std::size_t i = 0; i < system.bodies.size(); ++i) {
    const BodyBalance& b = newton.bodies[i];
    write_balance(system.bodies[i].name, b.mass_times_acceleration, b.applied_force, "R");
    write_balance(system.bodies[i].name + ".H", b.momentum_rate, b.applied_moment, "M_R");
  }
  if (latex) out << "\\end{aligned}\n\\]\n";
}

}  // namespace unidyn
