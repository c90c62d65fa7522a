// Forward-mode differentiation of a tape: each register carries its value x and its derivative
// ẋ along one direction of the inputs, and each instruction maps (x, ẋ) by the chain rule:
//   (x ± y)˙ = ẋ ± ẏ,  (x y)˙ = ẋ y + x ẏ,  (x / y)˙ = (ẋ − (x/y) ẏ) / y,  (1/x)˙ = −ẋ / x²,
//   (√x)˙ = ẋ / (2√x),  (x^y)˙ = x^y (y ẋ / x + ẏ log x),  f(x)˙ = f′(x) ẋ for the functions.
// The derivatives are exact but for round-off: no step size, unlike differences.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "tape_execute.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {
namespace {

// The derivative of instruction i's (first) result, from the registers r before it runs and
// their derivatives d.
double tangent(const TapeInstruction& i, const double* r, const double* d) {
  const double x = r[i.a], dx = d[i.a];
  switch (i.op) {
    case TapeOp::add:
      return dx + d[i.b];
    case TapeOp::sub:
      return dx - d[i.b];
    case TapeOp::mul:
      return dx * r[i.b] + x * d[i.b];
    case TapeOp::div:
      return (dx - x / r[i.b] * d[i.b]) / r[i.b];
    case TapeOp::neg:
      return -dx;
    case TapeOp::recip:
      return -dx / (x * x);
    case TapeOp::sqrt:
      return dx / (2.0 * std::sqrt(x));
    case TapeOp::pow: {
      const double y = r[i.b], dy = d[i.b];
      // y x^(y−1) ẋ, and x^y log x ẏ only where the exponent moves (x may be ≤ 0 otherwise)
      const double base_part = dx == 0.0 ? 0.0 : y * std::pow(x, y - 1.0) * dx;
      return dy == 0.0 ? base_part : base_part + std::pow(x, y) * std::log(x) * dy;
    }
    case TapeOp::sin:
    case TapeOp::sincos:
      return std::cos(x) * dx;
    case TapeOp::cos:
      return -std::sin(x) * dx;
    case TapeOp::tan: {
      const double t = std::tan(x);
      return (1.0 + t * t) * dx;
    }
    case TapeOp::asin:
      return dx / std::sqrt(1.0 - x * x);
    case TapeOp::acos:
      return -dx / std::sqrt(1.0 - x * x);
    case TapeOp::atan:
      return dx / (1.0 + x * x);
    case TapeOp::atan2: {
      // atan2(x, y) is the angle of the point (y, x)
      const double y = r[i.b];
      return (y * dx - x * d[i.b]) / (x * x + y * y);
    }
    case TapeOp::sinh:
      return std::cosh(x) * dx;
    case TapeOp::cosh:
      return std::sinh(x) * dx;
    case TapeOp::tanh: {
      const double t = std::tanh(x);
      return (1.0 - t * t) * dx;
    }
    case TapeOp::exp:
      return std::exp(x) * dx;
    case TapeOp::log:
      return dx / x;
    case TapeOp::abs:
      return (x > 0.0 ? 1.0 : x < 0.0 ? -1.0 : 0.0) * dx;
    case TapeOp::sign:
    case TapeOp::step:
      return 0.0;
  }
  return 0.0;
}

}  // namespace

void Tape::evaluate_tangent(std::span<const double> inputs, std::span<const double> direction,
                            std::span<double> outputs, std::span<double> d_outputs,
                            TapeWorkspace& workspace) const {
  if (inputs.size() != input_count() || direction.size() != input_count() ||
      outputs.size() != output_count() || d_outputs.size() != output_count()) {
    throw std::invalid_argument("Tape::evaluate_tangent: expected " +
                                std::to_string(input_count()) + " inputs and directions and " +
                                std::to_string(output_count()) + " outputs and derivatives");
  }
  workspace.reserve(*this);
  if (workspace.tangents_.size() < register_count()) workspace.tangents_.resize(register_count());
  double* r = workspace.registers_.data();
  double* d = workspace.tangents_.data();
  // Inputs with their directions, constants with none.
  std::copy(inputs.begin(), inputs.end(), r);
  std::copy(direction.begin(), direction.end(), d);
  std::copy(constants_.begin(), constants_.end(), r + input_count());
  std::fill(d + input_count(), d + input_count() + constants_.size(), 0.0);
  // Each instruction: its derivative from the operands as they are, then its value.
  for (const TapeInstruction& i : instructions_) {
    const double dvalue = tangent(i, r, d);
    if (i.op == TapeOp::sincos) {
      const double dcos = -std::sin(r[i.a]) * d[i.a];
      d[i.b] = dcos;
    }
    d[i.dst] = dvalue;
    detail::execute(i, r);
  }
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    outputs[k] = r[output_registers_[k]];
    d_outputs[k] = d[output_registers_[k]];
  }
}

}  // namespace unidyn
