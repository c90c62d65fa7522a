// A tape instruction's operation as an expression of C++, C, Python or MATLAB: the native code
// (native_source.cpp) and the exported functions (code_export.cpp) print the same operations.
#pragma once

#include <string>

#include "unidyn/numeric/tape.hpp"

namespace unidyn::detail {

enum class TapeLanguage { cpp, c, python, matlab };

// The expression of a single-result operation on x = r[a] and y = r[b], as the tape's execute()
// computes it (sincos has two results: the caller writes it).
std::string tape_operation(TapeOp op, const std::string& x, const std::string& y,
                           TapeLanguage language);

// sin or cos as called in the language (std::sin, sin, math.sin).
std::string tape_function(const char* name, TapeLanguage language);

}  // namespace unidyn::detail
