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
    const PotentialCheck check = potential_check(system, k);
    std::string line = element.label;
    if (element.where.line > 0) line += " (line " + std::to_string(element.where.line) + ")";
    if (!check.conservative) {
      line += " is not conservative: " + check.witness;
      if (!check.value.is_zero()) line += " = " + to_text(check.value);
    } else if (check.potential) {
      line += " is conservative: U = " + to_text(*check.potential);
    } else {
      line += " is conservative (its curl is 0; U, not a polynomial, is not integrated)";
    }
    lines.push_back(line);
  }
  return lines;
}

}  // namespace unidyn
