// Which inputs a tape's outputs depend on (backward liveness over its instructions).
#include "unidyn/numeric/tape_reads.hpp"

#include "tape_program.hpp"

namespace unidyn {

std::vector<bool> inputs_read(const Tape& tape) {
  std::vector<bool> live(tape.register_count(), false);
  for (const std::uint32_t r : tape.output_registers()) live[r] = true;
  const auto instructions = tape.instructions();
  for (auto k = instructions.size(); k-- > 0;) {
    const TapeInstruction& ins = instructions[k];
    const bool second = ins.op == TapeOp::sincos;              // b is its second destination
    if (!live[ins.dst] && !(second && live[ins.b])) continue;  // dead: reads nothing needed
    live[ins.dst] = false;
    if (second) live[ins.b] = false;
    live[ins.a] = true;
    if (detail::is_binary(ins.op)) live[ins.b] = true;
  }
  live.resize(tape.input_count());
  return live;
}

}  // namespace unidyn
