// Recorded scalars and their recorder (include/unidyn/numeric/tape_recorder.hpp).
#include "unidyn/numeric/tape_recorder.hpp"

#include <bit>
#include <optional>
#include <stdexcept>

#include "tape_execute.hpp"
#include "tape_program.hpp"

namespace unidyn {

using detail::Node;
using detail::Value;

// The instructions recorded so far, on virtual registers, with the constants they read.
struct TapeRecorder::Program {
  std::vector<Node> nodes;
  std::uint32_t temp_count = 0;
  std::vector<double> constants;
  std::unordered_map<std::uint64_t, std::uint32_t> constant_index;  // by the number's bits
  std::map<std::tuple<TapeOp, Value, Value>, std::uint32_t> numbering;
};

namespace {

// The value a recorded scalar names (a constant interned by the caller).
bool is_number(const Recorded& x, double number) {
  return x.is_constant() && x.constant() == number;
}

// An operation on numbers, as a tape does it.
double computed(TapeOp op, double x, double y) {
  double r[3] = {x, y, 0.0};
  detail::execute(TapeInstruction{op, 2, 0, 1}, r);
  return r[2];
}

bool is_unary(TapeOp op) {
  return !detail::is_binary(op);
}

}  // namespace

TapeRecorder::TapeRecorder(std::vector<std::string> input_names)
    : input_names_(std::move(input_names)), program_(std::make_unique<Program>()) {}

TapeRecorder::~TapeRecorder() = default;

Recorded TapeRecorder::input(std::size_t k) {
  if (k >= input_names_.size()) throw std::out_of_range("TapeRecorder::input: no such input");
  Recorded x;
  x.recorder_ = this;
  x.input_ = true;
  x.index_ = static_cast<std::uint32_t>(k);
  return x;
}

Recorded TapeRecorder::apply(TapeOp op, const Recorded& a, const Recorded& b) {
  const bool unary = is_unary(op);
  if (op == TapeOp::sincos) throw std::invalid_argument("TapeRecorder: record sin and cos apart");
  // numbers: done now
  if (a.is_constant() && (unary || b.is_constant())) {
    return Recorded(computed(op, a.constant(), unary ? 0.0 : b.constant()));
  }
  // results known without an instruction (exact for finite values), and negations taken into
  // the operation that reads them (exact: IEEE rounding is symmetric about 0)
  const std::optional<Recorded> minus_a = negated(a), minus_b = unary ? std::nullopt : negated(b);
  switch (op) {
    case TapeOp::add:
      if (is_number(a, 0)) return b;
      if (is_number(b, 0)) return a;
      if (minus_b) return apply(TapeOp::sub, a, *minus_b);  // a + (−v) = a − v
      if (minus_a) return apply(TapeOp::sub, b, *minus_a);  // (−u) + b = b − u
      break;
    case TapeOp::sub:
      if (is_number(b, 0)) return a;
      if (is_number(a, 0)) return apply(TapeOp::neg, b);
      if (minus_b) return apply(TapeOp::add, a, *minus_b);  // a − (−v) = a + v
      break;
    case TapeOp::mul:
      if (is_number(a, 0) || is_number(b, 0)) return Recorded(0.0);
      if (is_number(a, 1)) return b;
      if (is_number(b, 1)) return a;
      if (is_number(a, -1)) return apply(TapeOp::neg, b);
      if (is_number(b, -1)) return apply(TapeOp::neg, a);
      if (minus_a && minus_b) return apply(TapeOp::mul, *minus_a, *minus_b);  // (−u)(−v) = u v
      if (minus_a && b.is_constant()) return apply(TapeOp::mul, *minus_a, -b.constant());
      if (minus_b && a.is_constant()) return apply(TapeOp::mul, -a.constant(), *minus_b);
      break;
    case TapeOp::div:
      if (is_number(b, 1)) return a;
      if (minus_a && b.is_constant()) return apply(TapeOp::div, *minus_a, -b.constant());
      break;
    case TapeOp::neg:
      if (minus_a) return *minus_a;  // −(−x) = x
      break;
    default:
      break;
  }
  // an instruction, unless the same one was recorded before
  const auto value_of = [&](const Recorded& x) {
    if (x.is_constant()) {
      const auto bits = std::bit_cast<std::uint64_t>(x.constant());
      const auto [found, fresh] = program_->constant_index.emplace(
          bits, static_cast<std::uint32_t>(program_->constants.size()));
      if (fresh) program_->constants.push_back(x.constant());
      return Value{Value::Kind::constant, found->second};
    }
    if (x.recorder_ != this)
      throw std::invalid_argument("TapeRecorder: a value of another recorder");
    return Value{x.input_ ? Value::Kind::input : Value::Kind::temp, x.index_};
  };
  Value va = value_of(a), vb = unary ? va : value_of(b);
  if ((op == TapeOp::add || op == TapeOp::mul) && vb < va) std::swap(va, vb);
  const auto key = std::make_tuple(op, va, vb);
  std::uint32_t temp = program_->temp_count;
  if (const auto found = program_->numbering.find(key); found != program_->numbering.end()) {
    temp = found->second;
  } else {
    program_->nodes.push_back(Node{op, va, vb, temp});
    program_->numbering.emplace(key, temp);
    ++program_->temp_count;
  }
  return constant_or_value(static_cast<std::uint32_t>(Value::Kind::temp), temp);
}

std::optional<Recorded> TapeRecorder::negated(const Recorded& x) {
  if (x.is_constant() || x.input_) return std::nullopt;
  const Node& n = program_->nodes[x.index_];
  if (n.op != TapeOp::neg) return std::nullopt;
  return constant_or_value(static_cast<std::uint32_t>(n.a.kind), n.a.index);
}

Recorded TapeRecorder::constant_or_value(std::uint32_t kind, std::uint32_t index) {
  switch (static_cast<Value::Kind>(kind)) {
    case Value::Kind::constant:
      return Recorded(program_->constants[index]);
    case Value::Kind::input:
      return input(index);
    case Value::Kind::temp:
      break;
  }
  Recorded x;
  x.recorder_ = this;
  x.index_ = index;
  return x;
}

std::vector<Recorded> TapeRecorder::replay(const Tape& tape, std::span<const Recorded> inputs) {
  if (inputs.size() != tape.input_count()) {
    throw std::invalid_argument("TapeRecorder::replay: wrong number of inputs");
  }
  std::vector<Recorded> r(tape.register_count());
  std::copy(inputs.begin(), inputs.end(), r.begin());
  for (std::size_t k = 0; k < tape.constant_count(); ++k) {
    r[tape.input_count() + k] = Recorded(tape.constants()[k]);
  }
  for (const TapeInstruction& i : tape.instructions()) {
    if (i.op == TapeOp::sincos) {
      const Recorded x = r[i.a];
      r[i.dst] = apply(TapeOp::sin, x);
      r[i.b] = apply(TapeOp::cos, x);
      continue;
    }
    r[i.dst] = apply(i.op, r[i.a], r[i.b]);
  }
  std::vector<Recorded> outputs;
  for (const std::uint32_t k : tape.output_registers()) outputs.push_back(r[k]);
  return outputs;
}

Tape TapeRecorder::finish(const std::vector<Recorded>& outputs) const {
  // the program is copied: the recorder can go on (a constant output is interned in the copy)
  Program program = *program_;
  std::vector<Value> values;
  for (const std::vector<Recorded>* list : {&outputs, &watched_}) {
    for (const Recorded& x : *list) {
      if (!x.is_constant()) {
        values.push_back(Value{x.input_ ? Value::Kind::input : Value::Kind::temp, x.index_});
        continue;
      }
      values.push_back(
          Value{Value::Kind::constant, static_cast<std::uint32_t>(program.constants.size())});
      program.constants.push_back(x.constant());
    }
  }
  detail::fuse_sincos(program.nodes);
  detail::remove_dead(program.nodes, values, program.temp_count);
  detail::Program finished = detail::allocate_registers(input_names_.size(), program.constants,
                                                        program.nodes, values, program.temp_count);
  Tape tape;
  tape.input_names_ = input_names_;
  tape.constants_ = std::move(finished.constants);
  tape.instructions_ = std::move(finished.instructions);
  tape.output_registers_ = std::move(finished.outputs);
  tape.register_count_ = finished.register_count;
  return tape;
}

Recorded& Recorded::operator+=(const Recorded& b) {
  return *this = *this + b;
}
Recorded& Recorded::operator-=(const Recorded& b) {
  return *this = *this - b;
}
Recorded& Recorded::operator*=(const Recorded& b) {
  return *this = *this * b;
}
Recorded& Recorded::operator/=(const Recorded& b) {
  return *this = *this / b;
}

namespace {

// A binary operation: recorded by either operand's recorder, or done on two numbers.
Recorded binary(TapeOp op, const Recorded& a, const Recorded& b) {
  TapeRecorder* recorder = a.recorder() ? a.recorder() : b.recorder();
  if (!recorder) return Recorded(computed(op, a.constant(), b.constant()));
  return recorder->apply(op, a, b);
}

Recorded unary(TapeOp op, const Recorded& x) {
  if (!x.recorder()) return Recorded(computed(op, x.constant(), 0.0));
  return x.recorder()->apply(op, x);
}

}  // namespace

Recorded operator+(const Recorded& a, const Recorded& b) {
  return binary(TapeOp::add, a, b);
}
Recorded operator-(const Recorded& a, const Recorded& b) {
  return binary(TapeOp::sub, a, b);
}
Recorded operator*(const Recorded& a, const Recorded& b) {
  return binary(TapeOp::mul, a, b);
}
Recorded operator/(const Recorded& a, const Recorded& b) {
  return binary(TapeOp::div, a, b);
}
Recorded operator-(const Recorded& a) {
  return unary(TapeOp::neg, a);
}
Recorded sin(const Recorded& x) {
  return unary(TapeOp::sin, x);
}
Recorded cos(const Recorded& x) {
  return unary(TapeOp::cos, x);
}
Recorded sqrt(const Recorded& x) {
  return unary(TapeOp::sqrt, x);
}

}  // namespace unidyn
