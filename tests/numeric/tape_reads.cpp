// Which inputs a tape reads (numeric/tape_reads.hpp), against the outputs themselves: an input is
// read exactly when changing it changes some output (for expressions with no cancellation), seen
// here by evaluating the tape with that input moved.
#include "unidyn/numeric/tape_reads.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace unidyn {
namespace {

// Whether moving input i (from a generic point) changes any output.
bool output_moves_with(const Tape& tape, std::size_t i) {
  std::vector<double> at;
  for (std::size_t k = 0; k < tape.input_count(); ++k) at.push_back(0.31 + 0.17 * double(k));
  const std::vector<double> before = tape.evaluate(at);
  at[i] += 0.37;
  const std::vector<double> after = tape.evaluate(at);
  return before != after;
}

TEST(TapeReads, TheInputsThatMoveTheOutputs) {
  const GiNaC::realsymbol t("t"), x("x"), y("y"), z("z"), w("w"), u("u");
  const std::vector<GiNaC::ex> inputs{t, x, y, z, w, u};
  const struct {
    std::vector<GiNaC::ex> outputs;
    std::vector<bool> read;
  } cases[] = {
      // sums, products, quotients, powers and functions of some inputs
      {{x * y + GiNaC::sin(z), GiNaC::exp(w) / (1 + x * x)}, {0, 1, 1, 1, 1, 0}},
      // sine and cosine of one argument, evaluated together (sincos: two destinations), one of
      // them needed only
      {{GiNaC::sin(z) * GiNaC::cos(z) + GiNaC::cos(z), t}, {1, 0, 0, 1, 0, 0}},
      {{GiNaC::atan2(y, u), GiNaC::sqrt(1 + w * w)}, {0, 0, 1, 0, 1, 1}},
      // constants only, and no output
      {{GiNaC::ex(3) * GiNaC::Pi}, {0, 0, 0, 0, 0, 0}},
      {{}, {0, 0, 0, 0, 0, 0}},
  };
  for (const auto& c : cases) {
    const Tape tape = Tape::compile(c.outputs, inputs);
    const std::vector<bool> read = inputs_read(tape);
    ASSERT_EQ(read.size(), inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      EXPECT_EQ(read[i], c.read[i]) << "input " << inputs[i] << " of " << c.outputs.size();
      EXPECT_EQ(read[i], output_moves_with(tape, i)) << "input " << inputs[i];
    }
  }
}

// A long program whose registers are reused: inputs read only early, or only through
// temporaries that are overwritten later, are still found.
TEST(TapeReads, ThroughReusedRegisters) {
  std::vector<GiNaC::realsymbol> q;
  std::vector<GiNaC::ex> inputs;
  for (int i = 0; i < 12; ++i) {
    q.emplace_back("q" + std::to_string(i));
    inputs.push_back(q.back());
  }
  GiNaC::ex chain = 1;
  for (int i = 0; i < 12; i += 2) chain = GiNaC::sin(chain * q[static_cast<std::size_t>(i)] + 1);
  const Tape tape = Tape::compile({chain, GiNaC::cos(q[11])}, inputs);
  const std::vector<bool> read = inputs_read(tape);
  for (std::size_t i = 0; i < q.size(); ++i) {
    EXPECT_EQ(read[i], i % 2 == 0 || i == 11) << q[i];
    EXPECT_EQ(read[i], output_moves_with(tape, i)) << q[i];
  }
}

}  // namespace
}  // namespace unidyn
