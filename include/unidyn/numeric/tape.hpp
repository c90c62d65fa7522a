// Instruction tape: symbolic expressions compiled to a flat, register-based program of double
// operations, evaluated in one loop (the numeric layer's interpreter of derived equations).
//
// A Tape is immutable once compiled; the registers it evaluates in live in a separate
// TapeWorkspace (model/data separation as in Pinocchio), so one tape can be evaluated by many
// threads, each with its own workspace, and one workspace can serve several tapes.
//
// Compilation eliminates common subexpressions across all outputs (GiNaC structural equality),
// folds constant subexpressions, flattens n-ary sums and products, turns integer and half-integer
// powers into multiplications, square roots and reciprocals, and evaluates sin and cos of one
// argument together. Registers are reused once their value is dead. Terms and factors are taken
// in an order of their structure, not GiNaC's (which varies from run to run with load addresses),
// so that equal expressions give the same tape, and the same roundings, in every run.
#pragma once

#include <ginac/ginac.h>

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace unidyn {

// One operation of a tape. Registers hold doubles.
enum class TapeOp : std::uint8_t {
  add,     // r[dst] = r[a] + r[b]
  sub,     // r[dst] = r[a] - r[b]
  mul,     // r[dst] = r[a] * r[b]
  div,     // r[dst] = r[a] / r[b]
  neg,     // r[dst] = -r[a]
  recip,   // r[dst] = 1 / r[a]
  sqrt,    // r[dst] = √r[a]
  pow,     // r[dst] = r[a] ^ r[b]
  sin,     // r[dst] = sin r[a]
  cos,     // r[dst] = cos r[a]
  sincos,  // r[dst] = sin r[a], r[b] = cos r[a]  (b is a second destination)
  tan,
  asin,
  acos,
  atan,
  atan2,  // r[dst] = atan2(r[a], r[b]), i.e. the angle of the point (x, y) = (r[b], r[a])
  sinh,
  cosh,
  tanh,
  exp,
  log,
  abs,
  sign,  // -1, 0, +1 (GiNaC's csgn on reals)
  step,  // Heaviside: 0 for x < 0, 1/2 at 0 (as GiNaC's step), 1 for x > 0
};

// One instruction: opcode, destination register and up to two operand registers.
struct TapeInstruction {
  TapeOp op;
  std::uint32_t dst;
  std::uint32_t a;
  std::uint32_t b;
};

class Tape;

// The registers a tape is evaluated in. Grows to fit the largest tape it has evaluated; never
// shrinks, so evaluation allocates nothing once it has seen its tape.
class TapeWorkspace {
 public:
  TapeWorkspace() = default;
  explicit TapeWorkspace(const Tape& tape) { reserve(tape); }

  // Make room for `tape`'s registers (allocates only if there is not enough yet).
  void reserve(const Tape& tape);
  std::size_t capacity() const { return registers_.size(); }

 private:
  friend class Tape;
  std::vector<double> registers_;
  std::vector<double> tangents_;  // forward-mode derivatives of the registers (evaluate_tangent)
};

class Tape {
 public:
  // An empty tape: no inputs, no outputs.
  Tape() = default;

  // Compile `outputs` as functions of `inputs` (evaluation takes the inputs in this order). Throws
  // std::invalid_argument naming the offending subexpression for anything unsupported: a symbol
  // not among the inputs, a complex number, an unevaluated derivative, a function outside
  // sin cos tan asin acos atan atan2 sinh cosh tanh exp log abs csgn step (sqrt is a power), a
  // constant other than Pi, or any other GiNaC object (matrices, relations, lists, series...).
  // The inputs are held as expressions so that symbols of a derived class (GiNaC::realsymbol) keep
  // their identity: copying one into a GiNaC::symbol makes a different symbol to GiNaC, whose hash
  // and comparison include the dynamic type.
  static Tape compile(const std::vector<GiNaC::ex>& outputs, const std::vector<GiNaC::ex>& inputs);
  template <class Symbol>
  requires std::derived_from<Symbol, GiNaC::symbol>
  static Tape compile(const std::vector<GiNaC::ex>& outputs, const std::vector<Symbol>& inputs) {
    return compile(outputs, std::vector<GiNaC::ex>(inputs.begin(), inputs.end()));
  }

  std::size_t input_count() const { return input_names_.size(); }
  const std::string& input_name(std::size_t k) const { return input_names_.at(k); }
  std::size_t output_count() const { return output_registers_.size(); }
  std::size_t instruction_count() const { return instructions_.size(); }
  // Registers for inputs, constants and temporaries: the doubles a workspace needs.
  std::size_t register_count() const { return register_count_; }
  std::size_t constant_count() const { return constants_.size(); }

  // outputs[k] = value of output k at `inputs`. Sizes must equal input_count() and output_count()
  // (std::invalid_argument otherwise). Allocates only if `workspace` is too small for this tape.
  void evaluate(std::span<const double> inputs, std::span<double> outputs,
                TapeWorkspace& workspace) const;
  // Convenience form that allocates its result and a workspace.
  std::vector<double> evaluate(std::span<const double> inputs) const;
  // The outputs and their derivatives along `direction` (forward mode, exact to round-off):
  // d_outputs[k] = Σ_i ∂output_k/∂input_i · direction[i]. Where an operation has no derivative
  // (|x| at 0, sign, step) it counts as 0; √x at 0 and log 0 give infinities, as they would.
  void evaluate_tangent(std::span<const double> inputs, std::span<const double> direction,
                        std::span<double> outputs, std::span<double> d_outputs,
                        TapeWorkspace& workspace) const;

  // Human-readable program: inputs, constants, one instruction per line, outputs.
  std::string listing() const;

  std::span<const TapeInstruction> instructions() const { return instructions_; }
  // The constants' values (registers [input_count, input_count + constant_count)) and the
  // register each output is read from: with instructions(), the whole program (for native code).
  std::span<const double> constants() const { return constants_; }
  std::span<const std::uint32_t> output_registers() const { return output_registers_; }

 private:
  friend class TapeRecorder;  // the other writer of programs (numeric/tape_recorder.hpp)
  std::vector<std::string> input_names_;       // registers [0, input_count)
  std::vector<double> constants_;              // registers [input_count, input_count + constants)
  std::vector<TapeInstruction> instructions_;  // temporaries after the constants
  std::vector<std::uint32_t> output_registers_;
  std::size_t register_count_ = 0;
};

}  // namespace unidyn
