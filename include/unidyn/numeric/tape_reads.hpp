// Which inputs a tape's outputs depend on, read off the program's structure.
//
// Backward liveness over the instructions: the outputs' registers are live; an instruction whose
// destination is live makes its operands live (and its destination dead above it, registers being
// reused); an input whose register is live at the top is read. An input not read cannot change
// any output, whatever its value: exact, with no numerical judgement (one that is read may still
// cancel out, as sin²x + cos²x would).
#pragma once

#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace unidyn {

// read[i]: whether any output depends on input i.
std::vector<bool> inputs_read(const Tape& tape);

}  // namespace unidyn
