// Lagrange's equations as JSON that SymPy and other tools read.
#include <fmt/format.h>

#include <optional>

#include "unidyn/io/equation_report.hpp"
#include "unidyn/io/json_text.hpp"
#include "unidyn/symbolic/canonical_text.hpp"
#include "unidyn/symbolic/printing.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// A simplified expression in SymPy's notation, as a JSON string.
std::string expression(const Expr& e) {
  return quoted(canonical_sympy(simplify(e)));
}

}  // namespace

void write_lagrange_json(std::ostream& out, const System& system, const EquationsOfMotion& eq) {
  const auto& q = system.coordinates();
  const GiNaC::exmap values = system.parameter_values();
  // every expression simplified at once, the work shared among processes (then remembered)
  std::vector<Expr> all{eq.kinetic_energy, eq.potential_energy};
  all.insert(all.end(), eq.mass_matrix.data.begin(), eq.mass_matrix.data.end());
  all.insert(all.end(), eq.forcing.begin(), eq.forcing.end());
  all.insert(all.end(), eq.constraint_matrix.data.begin(), eq.constraint_matrix.data.end());
  all.insert(all.end(), eq.constraint_velocity_term.begin(), eq.constraint_velocity_term.end());
  all.insert(all.end(), eq.constraint_bias.begin(), eq.constraint_bias.end());
  simplify_all(all);
  out << "{\n  \"name\": " << quoted(system.name) << ",\n  \"method\": \"lagrange\",\n"
      << "  \"notation\": \"sympy: ** for powers; the rate of q is q_d, its acceleration q_dd, the "
         "multiplier of constraint c lambda_c; M q_dd = f + A^T lambda\",\n";
  out << "  \"coordinates\": [";
  for (std::size_t i = 0; i < q.size(); ++i) {
    out << (i ? ",\n    " : "\n    ") << "{\"name\": " << quoted(q[i].name)
        << ", \"rate\": " << quoted(sympy_name(q[i].name + "'"))
        << ", \"acceleration\": " << quoted(sympy_name(q[i].name + "''"))
        << ", \"initial\": " << json_number(real_value(system.initial_values[i], values))
        << ", \"initial_rate\": " << json_number(real_value(system.initial_rates[i], values))
        << "}";
  }
  out << "\n  ],\n  \"parameters\": [";
  for (std::size_t k = 0; k < system.parameters.size(); ++k) {
    out << (k ? ", " : "") << "{\"name\": " << quoted(system.parameters[k].name)
        << ", \"value\": " << json_number(system.parameters[k].value) << "}";
  }
  out << "],\n  \"kinetic_energy\": " << expression(eq.kinetic_energy);
  out << ",\n  \"potential_energy\": " << expression(eq.potential_energy);
  out << ",\n  \"mass_matrix\": [";
  for (std::size_t i = 0; i < q.size(); ++i) {
    out << (i ? ", " : "") << "[";
    for (std::size_t j = 0; j < q.size(); ++j) {
      out << (j ? ", " : "") << expression(eq.mass_matrix(i, j));
    }
    out << "]";
  }
  out << "],\n  \"forcing\": [";
  for (std::size_t i = 0; i < q.size(); ++i) out << (i ? ", " : "") << expression(eq.forcing[i]);
  out << "],\n  \"constraints\": [";
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    out << (k ? ", " : "") << "{\"name\": " << quoted(c.name)
        << ", \"multiplier\": " << quoted(sympy_name("lambda(" + c.name + ")")) << ", \"row\": [";
    for (std::size_t j = 0; j < q.size(); ++j) {
      out << (j ? ", " : "") << expression(eq.constraint_matrix(k, j));
    }
    out << "], \"velocity_term\": " << expression(eq.constraint_velocity_term[k])
        << ", \"acceleration_bias\": " << expression(eq.constraint_bias[k]) << "}";
  }
  out << "]\n}\n";
}

}  // namespace unidyn
