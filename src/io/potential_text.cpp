// Whether the forces given without a potential have one, in words.
#include "unidyn/io/potential_text.hpp"

#include "unidyn/equations/potential_check.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {

std::vector<std::string> potential_lines(const System& system) {
  std::vector<std::string> lines;
  for (std::size_t k = 0; k < system.forces.size(); ++k) {
    const ForceElement& element = system.forces[k];
    if (element.kind != ForceElement::Kind::force && element.kind != ForceElement::Kind::moment) {
      continue;
    }
    std::string line = element.label;
    if (element.where.line > 0) line += " (line " + std::to_string(element.where.line) + ")";
    if (element.potential_proven) {
      lines.push_back(line + " is conservative: U = " + to_text(element.potential) +
                      " (in the energy and in -dU/dq)");
      continue;
    }
    const PotentialCheck check = potential_check(system, k);
    if (!check.conservative) {
      line += " is not conservative: " + check.witness;
      if (!check.value.is_zero()) line += " = " + to_text(check.value);
    } else if (check.potential) {
      line += " is conservative: U = " + to_text(*check.potential);
    } else {
      line +=
          " is conservative (its curl is 0) but U, not a polynomial, is not integrated: it "
          "stays a generalised force, outside the energy";
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace unidyn
