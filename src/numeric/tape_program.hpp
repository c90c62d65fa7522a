// The instruction program of a tape before it is one: values on virtual registers in SSA form and
// the passes that finish it (numeric/tape.cpp's passes 2–4), shared by the two front ends that
// write programs — Tape::compile (GiNaC expressions) and TapeRecorder (operations on recorded
// scalars, numeric/tape_recorder.hpp).
#pragma once

#include <compare>
#include <cstdint>
#include <limits>
#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace unidyn::detail {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

// Whether an operation reads two operands (sincos writes its b; the others read a only).
inline bool is_binary(TapeOp op) {
  switch (op) {
    case TapeOp::add:
    case TapeOp::sub:
    case TapeOp::mul:
    case TapeOp::div:
    case TapeOp::pow:
    case TapeOp::atan2:
      return true;
    default:
      return false;
  }
}

// A value during compilation: an input, a constant or a virtual (single-assignment) temporary.
struct Value {
  enum class Kind : std::uint8_t { input, constant, temp };
  Kind kind = Kind::temp;
  std::uint32_t index = 0;

  auto operator<=>(const Value&) const = default;
};

// An instruction on virtual registers; dst2 is the cosine of a sincos, else kNone.
struct Node {
  TapeOp op;
  Value a;
  Value b;
  std::uint32_t dst;
  std::uint32_t dst2 = kNone;
};

// The program the passes produce, before it becomes a Tape.
struct Program {
  std::vector<double> constants;
  std::vector<TapeInstruction> instructions;
  std::vector<std::uint32_t> outputs;
  std::size_t register_count = 0;
};

// Pass 2: sin(a) and cos(a) become one sincos at the earlier of the two places.
void fuse_sincos(std::vector<Node>& nodes);

// Pass 3: drop instructions none of whose results reach an output.
void remove_dead(std::vector<Node>& nodes, const std::vector<Value>& outputs,
                 std::uint32_t temp_count);

// Pass 4: constants renumbered to those still used, temporaries mapped to physical registers
// that are reused once their last reader has run.
Program allocate_registers(std::size_t input_count, const std::vector<double>& constants,
                           const std::vector<Node>& nodes, const std::vector<Value>& outputs,
                           std::uint32_t temp_count);

}  // namespace unidyn::detail
