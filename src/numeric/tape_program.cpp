// The passes that finish a tape's program (tape_program.hpp).
#include "tape_program.hpp"

#include <algorithm>
#include <map>

namespace unidyn::detail {

namespace {

// Pass 4: constants renumbered to those still used, temporaries mapped to physical registers
// that are reused once their last reader has run.
class RegisterAllocator {
 public:
  RegisterAllocator(std::size_t input_count, const std::vector<double>& constants,
                    const std::vector<Node>& nodes, const std::vector<Value>& outputs,
                    std::uint32_t temp_count)
      : input_count_(static_cast<std::uint32_t>(input_count)),
        constant_slot_(constants.size(), kNone),
        temp_slot_(temp_count, kNone),
        last_use_(temp_count, kNone) {
    collect_constants(constants, nodes, outputs);
    find_last_uses(nodes, outputs);
    next_ = input_count_ + static_cast<std::uint32_t>(program_.constants.size());
    for (std::size_t i = 0; i < nodes.size(); ++i) lower(nodes[i], i);
    for (const Value& v : outputs) program_.outputs.push_back(slot(v));
    program_.register_count = next_;
  }

  Program take() { return std::move(program_); }

 private:
  // Keep the constants some instruction or output reads, in first-use order.
  void collect_constants(const std::vector<double>& constants, const std::vector<Node>& nodes,
                         const std::vector<Value>& outputs) {
    const auto use = [&](Value v) {
      if (v.kind != Value::Kind::constant || constant_slot_[v.index] != kNone) return;
      constant_slot_[v.index] =
          input_count_ + static_cast<std::uint32_t>(program_.constants.size());
      program_.constants.push_back(constants[v.index]);
    };
    for (const Node& n : nodes) {
      use(n.a);
      use(n.b);
    }
    for (const Value& v : outputs) use(v);
  }

  // Index of the last instruction reading each temporary; outputs live to the end.
  void find_last_uses(const std::vector<Node>& nodes, const std::vector<Value>& outputs) {
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (const Value& v : {nodes[i].a, nodes[i].b})
        if (v.kind == Value::Kind::temp) last_use_[v.index] = static_cast<std::uint32_t>(i);
    }
    for (const Value& v : outputs)
      if (v.kind == Value::Kind::temp) last_use_[v.index] = kForever;
  }

  // Read operands, release the registers they die in, then give the results registers.
  void lower(const Node& n, std::size_t i) {
    const std::uint32_t a = slot(n.a), b = slot(n.b);
    release_if_last(n.a, i);
    if (n.b != n.a) release_if_last(n.b, i);
    const std::uint32_t dst = acquire(n.dst);
    const std::uint32_t dst2 = n.dst2 == kNone ? kNone : acquire(n.dst2);
    if (last_use_[n.dst] == kNone) free_.push_back(dst);
    if (dst2 != kNone && last_use_[n.dst2] == kNone) free_.push_back(dst2);
    program_.instructions.push_back(TapeInstruction{n.op, dst, a, dst2 == kNone ? b : dst2});
  }

  void release_if_last(Value v, std::size_t i) {
    if (v.kind == Value::Kind::temp && last_use_[v.index] == i)
      free_.push_back(temp_slot_[v.index]);
  }

  std::uint32_t acquire(std::uint32_t temp) {
    std::uint32_t r = next_;
    if (free_.empty()) {
      ++next_;
    } else {
      r = free_.back();
      free_.pop_back();
    }
    temp_slot_[temp] = r;
    return r;
  }

  std::uint32_t slot(Value v) const {
    switch (v.kind) {
      case Value::Kind::input:
        return v.index;
      case Value::Kind::constant:
        return constant_slot_[v.index];
      case Value::Kind::temp:
        return temp_slot_[v.index];
    }
    return kNone;
  }

  static constexpr std::uint32_t kForever = kNone - 1;
  std::uint32_t input_count_;
  std::vector<std::uint32_t> constant_slot_, temp_slot_, last_use_, free_;
  std::uint32_t next_ = 0;
  Program program_;
};
}  // namespace

// Pass 2: sin(a) and cos(a) become one sincos at the earlier of the two places.
void fuse_sincos(std::vector<Node>& nodes) {
  std::map<Value, std::size_t> sines, cosines;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    if (nodes[i].op == TapeOp::sin) sines.emplace(nodes[i].a, i);
    if (nodes[i].op == TapeOp::cos) cosines.emplace(nodes[i].a, i);
  }
  std::vector<bool> removed(nodes.size(), false);
  for (const auto& [argument, s] : sines) {
    const auto c = cosines.find(argument);
    if (c == cosines.end()) continue;
    const Node fused{TapeOp::sincos, argument, argument, nodes[s].dst, nodes[c->second].dst};
    nodes[std::min(s, c->second)] = fused;
    removed[std::max(s, c->second)] = true;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (!removed[i]) nodes[kept++] = nodes[i];
  nodes.resize(kept);
}

// Pass 3: drop instructions none of whose results reach an output.
void remove_dead(std::vector<Node>& nodes, const std::vector<Value>& outputs,
                 std::uint32_t temp_count) {
  std::vector<bool> live(temp_count, false);
  const auto mark = [&](Value v) {
    if (v.kind == Value::Kind::temp) live[v.index] = true;
  };
  for (const Value& v : outputs) mark(v);
  std::vector<bool> keep(nodes.size(), false);
  for (std::size_t i = nodes.size(); i-- > 0;) {
    const Node& n = nodes[i];
    keep[i] = live[n.dst] || (n.dst2 != kNone && live[n.dst2]);
    if (!keep[i]) continue;
    mark(n.a);
    mark(n.b);
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (keep[i]) nodes[kept++] = nodes[i];
  nodes.resize(kept);
}

Program allocate_registers(std::size_t input_count, const std::vector<double>& constants,
                           const std::vector<Node>& nodes, const std::vector<Value>& outputs,
                           std::uint32_t temp_count) {
  RegisterAllocator allocator(input_count, constants, nodes, outputs, temp_count);
  return allocator.take();
}

}  // namespace unidyn::detail
