// Text, LaTeX and JSON forms of the derived equations.
#include "unidyn/io/equation_report.hpp"

#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

std::vector<Expr> accelerations(const System& system) {
  std::vector<Expr> symbols;
  for (const auto& q : system.coordinates()) symbols.push_back(q.acceleration);
  return symbols;
}

// One Lagrange row as (left side Σ M q̈, right side f + Σ λ a).
std::pair<Expr, Expr> lagrange_row(const System& system, const EquationsOfMotion& eq,
                                   std::size_t i) {
  const auto& q = system.coordinates();
  Expr lhs = 0;
  for (std::size_t j = 0; j < q.size(); ++j) lhs += eq.mass_matrix(i, j) * q[j].acceleration;
  Expr rhs = eq.forcing[i];
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    rhs += system.constraints[k].multiplier * eq.constraint_matrix(k, i);
  }
  return {collect_in(lhs, accelerations(system)), simplify(rhs)};
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
    out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"lagrange\",\n";
    out << "  \"coordinates\": [";
    for (std::size_t i = 0; i < q.size(); ++i) out << (i ? ", " : "") << quoted(q[i].name);
    out << "],\n  \"kinetic_energy\": " << quoted(to_text(simplify(eq.kinetic_energy)));
    out << ",\n  \"potential_energy\": " << quoted(to_text(simplify(eq.potential_energy)));
    out << ",\n  \"mass_matrix\": [";
    for (std::size_t i = 0; i < q.size(); ++i) {
      out << (i ? ", " : "") << "[";
      for (std::size_t j = 0; j < q.size(); ++j) {
        out << (j ? ", " : "") << quoted(to_text(simplify(eq.mass_matrix(i, j))));
      }
      out << "]";
    }
    out << "],\n  \"forcing\": [";
    for (std::size_t i = 0; i < q.size(); ++i) {
      out << (i ? ", " : "") << quoted(to_text(simplify(eq.forcing[i])));
    }
    out << "],\n  \"constraints\": [";
    for (std::size_t k = 0; k < constraints.size(); ++k) {
      out << (k ? ", " : "") << "{\"name\": " << quoted(constraints[k].name)
          << ", \"multiplier\": " << quoted(to_text(constraints[k].multiplier)) << ", \"row\": [";
      for (std::size_t j = 0; j < q.size(); ++j) {
        out << (j ? ", " : "") << quoted(to_text(simplify(eq.constraint_matrix(k, j))));
      }
      out << "], \"velocity_term\": " << quoted(to_text(simplify(eq.constraint_velocity_term[k])))
          << ", \"acceleration_bias\": " << quoted(to_text(simplify(eq.constraint_bias[k]))) << "}";
    }
    out << "]\n}\n";
    return;
  }

  if (format == EquationFormat::latex) {
    out << "% " << system.name << ": Lagrange's equations, M q'' = f + A^T lambda\n";
    out << "\\begin{aligned}\n";
    for (std::size_t i = 0; i < q.size(); ++i) {
      const auto [lhs, rhs] = lagrange_row(system, eq, i);
      out << "  " << to_latex(lhs) << " &= " << to_latex(rhs) << " \\\\\n";
    }
    for (const auto& c : constraints) {
      out << "  " << to_latex(simplify(c.expression)) << " &= 0"
          << (c.kind == Constraint::Kind::velocity ? " \\quad\\text{(velocity)}" : "") << " \\\\\n";
    }
    out << "  T &= " << to_latex(simplify(eq.kinetic_energy)) << " \\\\\n";
    out << "  U &= " << to_latex(simplify(eq.potential_energy)) << "\n\\end{aligned}\n";
    return;
  }

  out << system.name << ": Lagrange's equations"
      << (constraints.empty() ? "" : ", M q'' = f + A^T lambda (one multiplier per constraint)")
      << "\n";
  out << "  T = " << render(simplify(eq.kinetic_energy), format) << "\n";
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

void write_newton(std::ostream& out, const System& system, const NewtonEquations& newton,
                  EquationFormat format) {
  const char* axes[] = {"E1", "E2", "E3"};
  if (format == EquationFormat::json) {
    out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"newton-euler\",\n";
    out << "  \"particles\": [";
    for (std::size_t p = 0; p < system.particles.size(); ++p) {
      const ParticleBalance& b = newton.particles[p];
      out << (p ? ",\n    " : "\n    ") << "{\"name\": " << quoted(system.particles[p].name)
          << ", \"mass_times_acceleration\": [";
      for (int k = 0; k < 3; ++k) {
        out << (k ? ", " : "") << quoted(to_text(simplify(b.mass_times_acceleration[k])));
      }
      out << "], \"applied_force\": [";
      for (int k = 0; k < 3; ++k)
        out << (k ? ", " : "") << quoted(to_text(simplify(b.applied_force[k])));
      out << "]}";
    }
    out << "\n  ]\n}\n";
    return;
  }
  const bool latex = format == EquationFormat::latex;
  out << (latex ? "% " : "") << system.name
      << ": Newton's second law m a = F + R for each particle, Euler's laws m a = F + R and"
         " dH/dt = M + M_R (about the centre of mass) for each body (R, M_R: constraint force and"
         " moment)\n";
  if (latex) out << "\\begin{aligned}\n";
  // One balance law, component by component: lhs_k = rhs_k + <unknown>_k
  const auto write_balance = [&](const std::string& label, const VectorExpr& lhs_vector,
                                 const VectorExpr& rhs_vector, const std::string& unknown) {
    for (int k = 0; k < 3; ++k) {
      const Expr lhs = collect_in(lhs_vector[k], accelerations(system));
      const Expr rhs = simplify(rhs_vector[k]);
      if (latex) {
        out << "  " << to_latex(lhs) << " &= " << to_latex(rhs) << " + " << unknown << "_{" << label
            << "," << k + 1 << "} \\\\\n";
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
  if (latex) out << "\\end{aligned}\n";
}

}  // namespace unidyn
