// Tapes printed as C++: the same operations in the same order, constants as exact hexadecimal
// literals, so the compiled function gives the tape's results bit for bit.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "tape_language.hpp"
#include "unidyn/numeric/native_code.hpp"

namespace unidyn {
namespace {

// A double as an exact C++ literal (hexadecimal floating point), infinities and NaN included.
std::string literal(double value) {
  if (std::isnan(value)) return "__builtin_nan(\"\")";
  if (std::isinf(value)) return value > 0 ? "__builtin_inf()" : "(-__builtin_inf())";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", value);
  return buffer;
}

}  // namespace

std::string tape_source(const Tape& tape, std::string_view name) {
  std::ostringstream os;
  const std::size_t inputs = tape.input_count(), constants = tape.constant_count();
  os << "extern \"C\" void " << name << "(const double* in, double* out) {\n";
  // registers: inputs, constants, then temporaries (reused as in the tape)
  for (std::size_t r = 0; r < tape.register_count(); ++r) {
    os << "  double r" << r;
    if (r < inputs) os << " = in[" << r << "]";
    if (r >= inputs && r < inputs + constants) os << " = " << literal(tape.constants()[r - inputs]);
    os << ";\n";
  }
  os << "  (void)in;\n";
  for (const TapeInstruction& i : tape.instructions()) {
    const std::string x = "r" + std::to_string(i.a), y = "r" + std::to_string(i.b);
    if (i.op == TapeOp::sincos) {
      os << "  { const double x = " << x << "; r" << i.dst << " = std::sin(x); " << y
         << " = std::cos(x); }\n";
    } else {
      os << "  r" << i.dst << " = " << detail::tape_operation(i.op, x, y, detail::TapeLanguage::cpp)
         << ";\n";
    }
  }
  for (std::size_t k = 0; k < tape.output_count(); ++k) {
    os << "  out[" << k << "] = r" << tape.output_registers()[k] << ";\n";
  }
  os << "}\n";
  return os.str();
}

}  // namespace unidyn
