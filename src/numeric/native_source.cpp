// Tapes printed as C++: the same operations in the same order, constants as exact hexadecimal
// literals, so the compiled function gives the tape's results bit for bit.
#include <cmath>
#include <cstdio>
#include <sstream>

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

// The C++ expression of a single-result operation on x = r[a] (and r[b]); as the tape's execute().
std::string operation(TapeOp op, const std::string& x, const std::string& y) {
  switch (op) {
    case TapeOp::add:
      return x + " + " + y;
    case TapeOp::sub:
      return x + " - " + y;
    case TapeOp::mul:
      return x + " * " + y;
    case TapeOp::div:
      return x + " / " + y;
    case TapeOp::neg:
      return "-" + x;
    case TapeOp::recip:
      return "1.0 / " + x;
    case TapeOp::sqrt:
      return "std::sqrt(" + x + ")";
    case TapeOp::pow:
      return "std::pow(" + x + ", " + y + ")";
    case TapeOp::sin:
      return "std::sin(" + x + ")";
    case TapeOp::cos:
      return "std::cos(" + x + ")";
    case TapeOp::sincos:
      break;  // two results: written by the caller
    case TapeOp::tan:
      return "std::tan(" + x + ")";
    case TapeOp::asin:
      return "std::asin(" + x + ")";
    case TapeOp::acos:
      return "std::acos(" + x + ")";
    case TapeOp::atan:
      return "std::atan(" + x + ")";
    case TapeOp::atan2:
      return "std::atan2(" + x + ", " + y + ")";
    case TapeOp::sinh:
      return "std::sinh(" + x + ")";
    case TapeOp::cosh:
      return "std::cosh(" + x + ")";
    case TapeOp::tanh:
      return "std::tanh(" + x + ")";
    case TapeOp::exp:
      return "std::exp(" + x + ")";
    case TapeOp::log:
      return "std::log(" + x + ")";
    case TapeOp::abs:
      return "std::fabs(" + x + ")";
    case TapeOp::sign:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? -1.0 : 0.0))";
    case TapeOp::step:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? 0.0 : 0.5))";
  }
  return {};
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
      os << "  r" << i.dst << " = " << operation(i.op, x, y) << ";\n";
    }
  }
  for (std::size_t k = 0; k < tape.output_count(); ++k) {
    os << "  out[" << k << "] = r" << tape.output_registers()[k] << ";\n";
  }
  os << "}\n";
  return os.str();
}

}  // namespace unidyn
