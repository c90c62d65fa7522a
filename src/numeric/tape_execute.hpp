// One tape instruction executed on the registers: the single definition of every operation,
// shared by evaluation, constant folding (tape.cpp) and forward-mode derivatives
// (tape_tangent.cpp).
#pragma once

#include <cmath>

#include "unidyn/numeric/tape.hpp"

namespace unidyn::detail {

// Execute one instruction on the registers r. Operands are read before writing.
inline void execute(const TapeInstruction& i, double* r) {
  const double x = r[i.a];
  switch (i.op) {
    case TapeOp::add:
      r[i.dst] = x + r[i.b];
      break;
    case TapeOp::sub:
      r[i.dst] = x - r[i.b];
      break;
    case TapeOp::mul:
      r[i.dst] = x * r[i.b];
      break;
    case TapeOp::div:
      r[i.dst] = x / r[i.b];
      break;
    case TapeOp::neg:
      r[i.dst] = -x;
      break;
    case TapeOp::recip:
      r[i.dst] = 1.0 / x;
      break;
    case TapeOp::sqrt:
      r[i.dst] = std::sqrt(x);
      break;
    case TapeOp::pow:
      r[i.dst] = std::pow(x, r[i.b]);
      break;
    case TapeOp::sin:
      r[i.dst] = std::sin(x);
      break;
    case TapeOp::cos:
      r[i.dst] = std::cos(x);
      break;
    case TapeOp::sincos:
      r[i.dst] = std::sin(x);
      r[i.b] = std::cos(x);
      break;
    case TapeOp::tan:
      r[i.dst] = std::tan(x);
      break;
    case TapeOp::asin:
      r[i.dst] = std::asin(x);
      break;
    case TapeOp::acos:
      r[i.dst] = std::acos(x);
      break;
    case TapeOp::atan:
      r[i.dst] = std::atan(x);
      break;
    case TapeOp::atan2:
      r[i.dst] = std::atan2(x, r[i.b]);
      break;
    case TapeOp::sinh:
      r[i.dst] = std::sinh(x);
      break;
    case TapeOp::cosh:
      r[i.dst] = std::cosh(x);
      break;
    case TapeOp::tanh:
      r[i.dst] = std::tanh(x);
      break;
    case TapeOp::exp:
      r[i.dst] = std::exp(x);
      break;
    case TapeOp::log:
      r[i.dst] = std::log(x);
      break;
    case TapeOp::abs:
      r[i.dst] = std::fabs(x);
      break;
    case TapeOp::sign:
      r[i.dst] = x > 0.0 ? 1.0 : (x < 0.0 ? -1.0 : 0.0);
      break;
    case TapeOp::step:
      r[i.dst] = x > 0.0 ? 1.0 : (x < 0.0 ? 0.0 : 0.5);
      break;
  }
}

}  // namespace unidyn::detail
