// The integrability of the velocity constraints, in words.
#include "unidyn/io/integrability_text.hpp"

#include "unidyn/kinematics/integrability.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

std::vector<std::string> integrability_lines(const System& system) {
  std::vector<std::string> lines;
  std::vector<std::size_t> velocity;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    if (system.constraints[k].kind != Constraint::Kind::velocity) continue;
    velocity.push_back(k);
    const Integrability i = constraint_integrability(system, k);
    lines.push_back("constraint " + system.constraints[k].name + " is " +
                    (i.integrable ? "integrable (Jacobi (1.21))"
                                  : "not integrable: " + i.witness + " = " + to_text(i.value)));
  }
  if (velocity.size() < 2) return lines;
  try {
    const Integrability i = set_integrability(system, velocity);
    lines.push_back("the velocity constraints together are " +
                    (i.integrable ? std::string("integrable (Frobenius (8.18))")
                                  : "not integrable: " + i.witness + " = " + to_text(i.value)));
  } catch (const std::invalid_argument& e) {
    lines.push_back(std::string("the velocity constraints together: ") + e.what());
  }
  return lines;
}

}  // namespace unidyn
