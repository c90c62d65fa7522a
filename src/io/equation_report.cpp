// Text, LaTeX and JSON forms of the derived equations.
#include "unidyn/io/equation_report.hpp"

#include "unidyn/io/json_text.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/textbook_form.hpp"

namespace unidyn {

std::string constraint_kind_text(const Constraint& c) {
  std::string text = c.kind == Constraint::Kind::position ? "position" : "velocity";
  if (c.unilateral) text += ", unilateral";
  if (!c.off_while.empty()) text += ", off while '" + c.off_while + "' holds";
  return text;
}
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

std::vector<Expr> rates(const System& system) {
  std::vector<Expr> symbols;
  for (const auto& q : system.coordinates()) symbols.push_back(q.rate);
  return symbols;
}

// Lagrange's equations as printed in matrix form: each row's left side Σ M_ij q̈^j and right side
// f_i + Σ λ_k a_k^i, T, U and the constraints; every entry of M and every coefficient of a
// product of rates and multipliers (on the right, in T) simplified by itself (an expression as a
// whole took half a minute on the bicycle), all at once (the work shared among processes).
struct MatrixForm {
  std::vector<Expr> left, right, constraints;
  Expr T, U;
};

MatrixForm matrix_form(const System& system, const EquationsOfMotion& eq) {
  const auto& q = system.coordinates();
  const std::size_t n = q.size();
  std::vector<Expr> symbols = rates(system);
  for (const auto& c : system.constraints) symbols.push_back(c.multiplier);
  // the right sides, then T, grouped by monomials
  std::vector<std::vector<GroupedTerm>> sums;
  for (std::size_t i = 0; i < n; ++i) {
    sums.push_back(
        group_by_monomials(eq.forcing[i] + constraint_terms(system, eq, i), symbols, as_it_is));
  }
  sums.push_back(group_by_monomials(eq.kinetic_energy, rates(system), as_it_is));
  // M, the constraints, U, the coefficients: simplified at once, read back in this order
  std::vector<Expr> all = eq.mass_matrix.data;
  for (const auto& c : system.constraints) all.push_back(c.expression);
  all.push_back(eq.potential_energy);
  for (const auto& sum : sums) {
    for (const GroupedTerm& t : sum) all.push_back(t.coefficient);
  }
  const std::vector<Expr> simple = simplify_all(all);
  std::size_t k = 0;
  MatrixForm form;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Expr> left;
    for (std::size_t j = 0; j < n; ++j) left.push_back(simple[k++] * q[j].acceleration);
    form.left.push_back(sum_of(left));
  }
  for (std::size_t c = 0; c < system.constraints.size(); ++c)
    form.constraints.push_back(simple[k++]);
  form.U = simple[k++];
  for (const auto& sum : sums) {
    std::vector<Expr> terms;
    for (const GroupedTerm& t : sum) {
      if (const Expr& c = simple[k++]; !c.is_zero()) terms.push_back(c * t.monomial);
    }
    form.right.push_back(sum_of(terms));
  }
  form.T = form.right.back();
  form.right.pop_back();
  return form;
}

// A vector as "[x, y, z]" in text or LaTeX.
std::string render_vector(const VectorExpr& v, bool latex) {
  std::string text = latex ? "\\begin{bmatrix}" : "[";
  for (int k = 0; k < 3; ++k) {
    text += (k ? (latex ? " \\\\ " : ", ") : "") + (latex ? to_latex(v[k]) : to_text(v[k]));
  }
  return text + (latex ? "\\end{bmatrix}" : "]");
}

std::string render(const Expr& e, EquationFormat format) {
  return format == EquationFormat::latex ? to_latex(e) : to_text(e);
}

// Each moving particle's and body's partial velocity (and angular velocity) for coordinate A:
// label ("P1.velocity"), LaTeX, vector; those that are zero left out.
struct Partial {
  std::string label, latex;
  VectorExpr v;
};
std::vector<Partial> partial_velocities(const System& system, const SecondForm& form,
                                        std::size_t A) {
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
}

// The partial velocities of coordinate A as lines ("  [theta1]  d(P1.velocity)/d(theta1') = [..]")
// or LaTeX rows, and as a JSON object's members.
void write_partials(std::ostream& out, const System& system, const std::vector<Partial>& list,
                    std::size_t A, bool latex) {
  const auto& q = system.coordinates();
  for (const Partial& partial : list) {
    if (latex) {
      out << "  \\frac{\\partial " << partial.latex << "}{\\partial " << to_latex(q[A].rate)
          << "} &= " << render_vector(partial.v, true) << " \\\\\n";
    } else {
      out << "  [" << q[A].name << "]  d(" << partial.label << ")/d(" << q[A].name
          << "') = " << render_vector(partial.v, false) << "\n";
    }
  }
}
std::string partials_json(const std::vector<Partial>& list) {
  std::string out = "{";
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += std::string(i ? ", " : "") + quoted(list[i].label) + ": [";
    for (int k = 0; k < 3; ++k) out += std::string(k ? ", " : "") + quoted(to_text(list[i].v[k]));
    out += "]";
  }
  return out + "}";
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
  const MatrixForm form = matrix_form(system, eq);

  if (format == EquationFormat::latex) {
    out << "% " << system.name << ": Lagrange's equations, M q'' = f + A^T lambda\n";
    out << "\\[\n\\begin{aligned}\n";
    for (std::size_t i = 0; i < q.size(); ++i) {
      out << "  " << to_latex(form.left[i]) << " &= " << to_latex(form.right[i]) << " \\\\\n";
    }
    for (std::size_t k = 0; k < constraints.size(); ++k) {
      out << "  " << to_latex(form.constraints[k]) << " &= 0"
          << (constraints[k].kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "")
          << " \\\\\n";
    }
    out << "  T &= " << to_latex(form.T) << " \\\\\n";
    out << "  U &= " << to_latex(form.U) << "\n\\end{aligned}\n\\]\n";
    return;
  }

  out << system.name << ": Lagrange's equations"
      << (constraints.empty() ? "" : ", M q'' = f + A^T lambda (one multiplier per constraint)")
      << "\n";
  out << "  T = " << render(form.T, format) << "\n";
  out << "  U = " << render(form.U, format) << "\n";
  for (std::size_t i = 0; i < q.size(); ++i) {
    out << "  [" << q[i].name << "]  " << to_text(form.left[i]) << " = " << to_text(form.right[i])
        << "\n";
  }
  for (std::size_t k = 0; k < constraints.size(); ++k) {
    const Constraint& c = constraints[k];
    out << "  constraint " << c.name << " (" << constraint_kind_text(c)
        << "): " << to_text(form.constraints[k]) << " = 0, multiplier " << c.multiplier << "\n";
  }
}

void write_second_form(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                       const SecondForm& form, EquationFormat format) {
  const auto& q = system.coordinates();
  const auto partials = [&](std::size_t A) { return partial_velocities(system, form, A); };
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
          << ", \"partial_velocities\": " << partials_json(partials(A))
          << ", \"inertia_terms\": " << quoted(to_text(lhs(A)))
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
    write_partials(out, system, partials(A), A, latex);
    if (latex) {
      out << "  " << to_latex(lhs(A)) << " &= " << to_latex(rhs(A)) << " \\\\\n";
    } else {
      out << "  [" << q[A].name << "]  " << to_text(lhs(A)) << " = " << to_text(rhs(A)) << "\n";
    }
  }
  if (latex) out << "\\end{aligned}\n\\]\n";
}

void write_kane(std::ostream& out, const System& system, const EquationsOfMotion& eq,
                const SecondForm& form, EquationFormat format) {
  const auto& q = system.coordinates();
  // F_r: the active forces, the constraints' with them; F*_r = −(M q̈ + c)_r from Kane's sums
  const auto active = [&](std::size_t r) {
    return simplify(eq.applied_forcing[r] + constraint_terms(system, eq, r));
  };
  const auto inertia = [&](std::size_t r) {
    Expr sum = eq.applied_forcing[r] - eq.forcing[r];
    for (std::size_t j = 0; j < q.size(); ++j) sum += eq.mass_matrix(r, j) * q[j].acceleration;
    return collect_in(-sum, accelerations(system));
  };
  if (format == EquationFormat::json) {
    out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"kane\",\n";
    out << "  \"equations\": [";
    for (std::size_t r = 0; r < q.size(); ++r) {
      out << (r ? ",\n    " : "\n    ") << "{\"coordinate\": " << quoted(q[r].name)
          << ", \"partial_velocities\": " << partials_json(partial_velocities(system, form, r))
          << ", \"generalized_active_force\": " << quoted(to_text(active(r)))
          << ", \"generalized_inertia_force\": " << quoted(to_text(inertia(r))) << "}";
    }
    out << "\n  ]\n}\n";
    return;
  }
  const bool latex = format == EquationFormat::latex;
  out << (latex ? "% " : "") << system.name
      << ": Kane's equations (10.16): F_r + F*_r = 0 for each coordinate u^r, the generalised "
         "active force F_r = sum F . dv/du'^r + M . domega/du'^r (gravity and potentials among "
         "them: - dU/du^r)"
      << (system.constraints.empty() ? "" : " + sum_k lambda_k a_k^r")
      << ", the generalised inertia force F*_r = - sum m a . dv/du'^r - (J omega' + omega x J "
         "omega) . domega/du'^r\n";
  if (latex) out << "\\[\n\\begin{aligned}\n";
  for (std::size_t r = 0; r < q.size(); ++r) {
    write_partials(out, system, partial_velocities(system, form, r), r, latex);
    if (latex) {
      out << "  F_{" << to_latex(q[r].value) << "} &= " << to_latex(active(r)) << " \\\\\n";
      out << "  F^*_{" << to_latex(q[r].value) << "} &= " << to_latex(inertia(r)) << " \\\\\n";
      out << "  F_{" << to_latex(q[r].value) << "} + F^*_{" << to_latex(q[r].value)
          << "} &= 0 \\\\\n";
    } else {
      out << "  [" << q[r].name << "]  F = " << to_text(active(r)) << "\n";
      out << "  [" << q[r].name << "]  F* = " << to_text(inertia(r)) << "\n";
      out << "  [" << q[r].name << "]  F + F* = 0\n";
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
