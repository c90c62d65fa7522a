// Which velocity constraints are integrable, in words (`unidyn derive`, the report).
#pragma once

#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// (1.21), (8.18): one sentence per velocity constraint ("constraint pi1 is not integrable: I(x1,
// psi, phi) = -R*sin(psi)"), and one for them together when there are two or more.
std::vector<std::string> integrability_lines(const System& system);

}  // namespace unidyn
