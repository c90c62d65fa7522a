// Tapes printed as C++: the same operations in the same order, constants as exact hexadecimal
// literals, so the compiled function gives the tape's results bit for bit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <span>
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

// One instruction as a C++ statement, its registers named by `reg` (r12 or r[12]).
template <class Register>
void write_instruction(std::ostream& os, const TapeInstruction& i, const Register& reg) {
  const std::string x = reg(i.a), y = reg(i.b);
  if (i.op == TapeOp::sincos) {
    os << "  { const double x = " << x << "; " << reg(i.dst) << " = __builtin_sin(x); " << y
       << " = __builtin_cos(x); }\n";
  } else {
    os << "  " << reg(i.dst) << " = "
       << detail::tape_operation(i.op, x, y, detail::TapeLanguage::native) << ";\n";
  }
}

}  // namespace

std::string tape_source(const Tape& tape, std::string_view name) {
  std::ostringstream os;
  const std::size_t inputs = tape.input_count(), constants = tape.constant_count();
  const std::span<const TapeInstruction> program = tape.instructions();
  // A long tape is cut into parts, each a function of its own over an array of registers: GCC's
  // register allocation grows faster than linearly with a function's length (pendulum-20's 14 000
  // instructions in one function: 6.7 s of compilation, half of it assigning registers).
  constexpr std::size_t part_length = 1500;
  if (program.size() > 2 * part_length) {
    const auto reg = [](std::uint32_t r) { return "r[" + std::to_string(r) + "]"; };
    std::size_t parts = 0;
    for (std::size_t first = 0; first < program.size(); first += part_length, ++parts) {
      os << "__attribute__((noinline)) static void " << name << "_part" << parts
         << "(double* r) {\n";
      const std::size_t last = std::min(program.size(), first + part_length);
      for (std::size_t k = first; k < last; ++k) write_instruction(os, program[k], reg);
      os << "}\n";
    }
    os << "extern \"C\" void " << name << "(const double* in, double* out) {\n";
    os << "  double r[" << tape.register_count() << "];\n";
    for (std::size_t r = 0; r < inputs; ++r) os << "  r[" << r << "] = in[" << r << "];\n";
    for (std::size_t r = inputs; r < inputs + constants; ++r) {
      os << "  r[" << r << "] = " << literal(tape.constants()[r - inputs]) << ";\n";
    }
    for (std::size_t k = 0; k < parts; ++k) os << "  " << name << "_part" << k << "(r);\n";
    for (std::size_t k = 0; k < tape.output_count(); ++k) {
      os << "  out[" << k << "] = r[" << tape.output_registers()[k] << "];\n";
    }
    os << "}\n";
    return os.str();
  }
  os << "extern \"C\" void " << name << "(const double* in, double* out) {\n";
  // registers: inputs, constants, then temporaries (reused as in the tape)
  for (std::size_t r = 0; r < tape.register_count(); ++r) {
    os << "  double r" << r;
    if (r < inputs) os << " = in[" << r << "]";
    if (r >= inputs && r < inputs + constants) os << " = " << literal(tape.constants()[r - inputs]);
    os << ";\n";
  }
  os << "  (void)in;\n";
  const auto reg = [](std::uint32_t r) { return "r" + std::to_string(r); };
  for (const TapeInstruction& i : program) write_instruction(os, i, reg);
  for (std::size_t k = 0; k < tape.output_count(); ++k) {
    os << "  out[" << k << "] = r" << tape.output_registers()[k] << ";\n";
  }
  os << "}\n";
  return os.str();
}

}  // namespace unidyn
