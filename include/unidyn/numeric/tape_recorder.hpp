// A scalar that records: an algorithm written as a template over its scalar (the tree's
// articulated-body algorithm, tree/articulated_body.hpp) runs once on Recorded values and leaves
// its operations as a Tape — generated code with the model's numbers folded in, as RobCoGen and
// SD-FAST generate a robot's dynamics, with no symbolic expression formed.
//
// A Recorded is a constant (a plain number: the model's masses, axes, offsets) or a value in a
// TapeRecorder (an input, or the result of an operation on one). An operation on constants is
// done at once; one on recorded values appends an instruction, except where the result is known
// without it: x + 0, x − 0, x · 1, x · 0 (= 0), x · (−1) (= −x), x / 1, −(−x), and an operation
// recorded before on the same operands (value numbering; + and × in either order); a recorded −u
// read by +, −, × or ÷ is taken into it (a + (−u) = a − u, (−u) · c = u · (−c), …). These are
// exact in IEEE arithmetic for finite x — x · 0 = 0 assumes x finite, so a recorded tape is for
// finite inputs (its caller checks them). The recorder's tape then goes through the passes of
// Tape::compile (sin and cos fused, dead code removed, registers reused), so it evaluates and
// becomes native code as any other tape.
//
// A value is never branched on: comparisons are not defined. An algorithm that must check a value
// (a pivot > 0) records it as an output instead (TapeRecorder::watch) for its caller to check.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <unordered_map>
#include <vector>

#include "unidyn/numeric/tape.hpp"

namespace unidyn {

class TapeRecorder;

class Recorded {
 public:
  Recorded() = default;
  Recorded(double constant) : constant_(constant) {}  // NOLINT: numbers are constants
  Recorded(int constant) : constant_(constant) {}     // NOLINT

  bool is_constant() const { return recorder_ == nullptr; }
  // The number of a constant (0 for a recorded value).
  double constant() const { return constant_; }
  // The recorder of a recorded value (null for a constant).
  TapeRecorder* recorder() const { return recorder_; }

  Recorded& operator+=(const Recorded& b);
  Recorded& operator-=(const Recorded& b);
  Recorded& operator*=(const Recorded& b);
  Recorded& operator/=(const Recorded& b);

 private:
  friend class TapeRecorder;
  TapeRecorder* recorder_ = nullptr;
  bool input_ = false;  // an input (index: its position) or a temporary (index: its number)
  std::uint32_t index_ = 0;
  double constant_ = 0;
};

Recorded operator+(const Recorded& a, const Recorded& b);
Recorded operator-(const Recorded& a, const Recorded& b);
Recorded operator*(const Recorded& a, const Recorded& b);
Recorded operator/(const Recorded& a, const Recorded& b);
Recorded operator-(const Recorded& a);
Recorded sin(const Recorded& x);
Recorded cos(const Recorded& x);
Recorded sqrt(const Recorded& x);

class TapeRecorder {
 public:
  // A recorder of functions of `inputs` inputs, named as a tape's (listing()).
  explicit TapeRecorder(std::vector<std::string> input_names);
  ~TapeRecorder();
  TapeRecorder(const TapeRecorder&) = delete;
  TapeRecorder& operator=(const TapeRecorder&) = delete;

  Recorded input(std::size_t k);
  // op applied to a (and b for a binary one), folded or recorded as the header says.
  Recorded apply(TapeOp op, const Recorded& a, const Recorded& b = Recorded());
  // A tape's operations replayed on recorded inputs: its outputs as Recorded values (a tape of
  // the model's forces becomes part of the recorded function).
  std::vector<Recorded> replay(const Tape& tape, std::span<const Recorded> inputs);
  // Keep x for the caller to check: watched values are the tape's last outputs, in order. A
  // constant is kept as it is.
  void watch(const Recorded& x) { watched_.push_back(x); }

  // The tape of `outputs`, then the watched values.
  Tape finish(const std::vector<Recorded>& outputs) const;

 private:
  struct Program;
  Recorded constant_or_value(std::uint32_t kind, std::uint32_t index);
  // u where x is a recorded −u, else none.
  std::optional<Recorded> negated(const Recorded& x);
  std::vector<std::string> input_names_;
  std::unique_ptr<Program> program_;
  std::vector<Recorded> watched_;
};

}  // namespace unidyn

// Recorded as an Eigen scalar (fixed-size matrices of it: no vectorisation, no comparisons).
namespace Eigen {
template <>
struct NumTraits<unidyn::Recorded> : NumTraits<double> {
  using Real = unidyn::Recorded;
  using NonInteger = unidyn::Recorded;
  using Nested = unidyn::Recorded;
  using Literal = unidyn::Recorded;
  enum {
    IsComplex = 0,
    IsInteger = 0,
    IsSigned = 1,
    RequireInitialization = 1,
    ReadCost = 1,
    AddCost = 1,
    MulCost = 1
  };
};
}  // namespace Eigen
