// A tape instruction's operation as an expression of C, Python or MATLAB, or of the native code's
// C++ (native_source.cpp): the exported functions (code_export.cpp) and the native code print the
// same operations. The native code calls GCC's and Clang's builtins (__builtin_sin: the C
// library's sin, as std::sin is), so its source needs no header: <cmath> alone took 0.16 s of each
// compilation.
#pragma once

#include <string>

#include "unidyn/numeric/tape.hpp"

namespace unidyn::detail {

enum class TapeLanguage { native, c, python, matlab };

// The expression of a single-result operation on x = r[a] and y = r[b], as the tape's execute()
// computes it (sincos has two results: the caller writes it).
std::string tape_operation(TapeOp op, const std::string& x, const std::string& y,
                           TapeLanguage language);

// sin or cos as called in the language (__builtin_sin, sin, math.sin).
std::string tape_function(const char* name, TapeLanguage language);

}  // namespace unidyn::detail
