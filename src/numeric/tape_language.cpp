// Tape operations printed in C, Python and MATLAB, and for the native code.
#include "tape_language.hpp"

namespace unidyn::detail {
namespace {

// sign and Heaviside step (0, 1/2 at 0, 1) of x.
std::string sign_of(const std::string& x, TapeLanguage language) {
  switch (language) {
    case TapeLanguage::python:
      return "(1.0 if " + x + " > 0.0 else (-1.0 if " + x + " < 0.0 else 0.0))";
    case TapeLanguage::matlab:
      return "sign(" + x + ")";
    default:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? -1.0 : 0.0))";
  }
}
std::string step_of(const std::string& x, TapeLanguage language) {
  switch (language) {
    case TapeLanguage::python:
      return "(1.0 if " + x + " > 0.0 else (0.0 if " + x + " < 0.0 else 0.5))";
    case TapeLanguage::matlab:
      return "((" + x + " > 0) + 0.5 * (" + x + " == 0))";
    default:
      return "(" + x + " > 0.0 ? 1.0 : (" + x + " < 0.0 ? 0.0 : 0.5))";
  }
}

}  // namespace

std::string tape_function(const char* name, TapeLanguage language) {
  switch (language) {
    case TapeLanguage::native:
      return std::string("__builtin_") + name;
    case TapeLanguage::python:
      return std::string("math.") + name;
    default:
      return name;
  }
}

std::string tape_operation(TapeOp op, const std::string& x, const std::string& y,
                           TapeLanguage language) {
  const auto call = [&](const char* name) { return tape_function(name, language) + "(" + x + ")"; };
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
      return call("sqrt");
    case TapeOp::pow:
      if (language == TapeLanguage::matlab) return "power(" + x + ", " + y + ")";
      return tape_function("pow", language) + "(" + x + ", " + y + ")";
    case TapeOp::sin:
      return call("sin");
    case TapeOp::cos:
      return call("cos");
    case TapeOp::sincos:
      break;
    case TapeOp::tan:
      return call("tan");
    case TapeOp::asin:
      return call("asin");
    case TapeOp::acos:
      return call("acos");
    case TapeOp::atan:
      return call("atan");
    case TapeOp::atan2:
      return tape_function("atan2", language) + "(" + x + ", " + y + ")";
    case TapeOp::sinh:
      return call("sinh");
    case TapeOp::cosh:
      return call("cosh");
    case TapeOp::tanh:
      return call("tanh");
    case TapeOp::exp:
      return call("exp");
    case TapeOp::log:
      return call("log");
    case TapeOp::abs:
      if (language == TapeLanguage::python || language == TapeLanguage::matlab) {
        return "abs(" + x + ")";
      }
      return tape_function("fabs", language) + "(" + x + ")";
    case TapeOp::sign:
      return sign_of(x, language);
    case TapeOp::step:
      return step_of(x, language);
  }
  return {};
}

}  // namespace unidyn::detail
