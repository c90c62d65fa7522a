// Whether each force or moment given without a potential has one (equations/potential_check.hpp),
// in words, for `unidyn derive`.
#pragma once

#include <string>
#include <vector>

#include "unidyn/model/system.hpp"

namespace unidyn {

// One line per `force:` or `moment:` element: "force (line 12) is conservative: U = -x1*x2", or
// "... is not conservative: dPhi_x/dy - dPhi_y/dx = ..." (or "depends on der(x)").
std::vector<std::string> potential_lines(const System& system);

}  // namespace unidyn
