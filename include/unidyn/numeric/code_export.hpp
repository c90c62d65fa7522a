// The equations of motion as a self-contained function in C, Python or MATLAB
// (`unidyn derive --format c|python|matlab`), what SymPy's codegen and MotionGenesis give.
//
// The dynamics tape (numeric/compiled_system.hpp dynamics_tape: the operations the simulation
// itself evaluates, common subexpressions shared) printed in the language, with
//   eom(t, q, qd, p)           → M (n × n), f (n), A (m × n), b (m):  M q'' = f + Aᵀ λ,  A q'' + b
//   = 0 accelerations(t, q, qd, p) → q'' (n), λ (m): the saddle-point system
//                                [M  −Aᵀ; A  0] [q''; λ] = [f; −b]
//                                by Gaussian elimination with partial pivoting (C, Python; MATLAB's
//                                \)
// p holds the parameters in the model's order; the file's header lists them with their values.
// C constants are exact hexadecimal literals, so the C function gives the tape's numbers bit for
// bit; Python's and MATLAB's are the shortest decimals that read back as the same doubles.
#pragma once

#include <string>

#include "unidyn/equations/lagrange.hpp"

namespace unidyn {

enum class CodeLanguage { c, python, matlab };

// The source of the functions for `system` with equations `eq`; `name` prefixes the C functions
// (name_eom, name_accelerations) and names the Python module's functions' docstring and the
// MATLAB function (a valid identifier: letters, digits, underscores).
std::string export_code(const System& system, const EquationsOfMotion& eq, CodeLanguage language,
                        const std::string& name);

}  // namespace unidyn
