// Recorded scalars: a function run on them leaves a tape that gives what the function gives on
// doubles (computed here in plain arithmetic), with the operations the header says are known
// without an instruction left out, and repeated ones recorded once.
#include "unidyn/numeric/tape_recorder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/oracles.hpp"

namespace unidyn {
namespace {

// The function under test, for any scalar: a small mechanism-like mix of sums, products with
// model numbers (0, 1, −1 among them), a quotient, a square root and a rotation by sin and cos.
template <class S>
std::vector<S> sample_function(const S& x, const S& y) {
  using std::cos, std::sin, std::sqrt;
  const S c = cos(x), s = sin(x);
  const S turned = c * y - s * S(0.0) * y + S(1.0) * s;  // the 0 and 1 of an axis
  const S length = sqrt(x * x + y * y + S(2.0));
  return {turned / length, -(-turned) * S(-1.0) + y / S(1.0), c * y + y * c, S(3.0) * S(4.0)};
}

TEST(TapeRecorder, GivesWhatTheFunctionGivesOnDoubles) {
  TapeRecorder recorder({"x", "y"});
  const Tape tape = recorder.finish(sample_function(recorder.input(0), recorder.input(1)));
  ASSERT_EQ(tape.input_count(), 2u);
  ASSERT_EQ(tape.output_count(), 4u);
  test::Random random;
  for (int k = 0; k < 50; ++k) {
    const double x = random.uniform(-4, 4), y = random.uniform(-4, 4);
    const std::vector<double> expected = sample_function(x, y);
    const std::vector<double> out = tape.evaluate(std::vector<double>{x, y});
    for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], expected[i]) << i;
  }
}

// The folding: x·0, x·1, −(−x), x/1, x + 0 and the constant 3·4 leave no instruction; u·v and
// v·u are one product; negations go into what reads them; sin and cos of x are one sincos.
TEST(TapeRecorder, FoldsWhatIsKnownAndRecordsRepeatsOnce) {
  TapeRecorder recorder({"x", "y"});
  const Recorded x = recorder.input(0), y = recorder.input(1);
  EXPECT_TRUE((x * 0.0).is_constant());
  EXPECT_EQ((x * 0.0).constant(), 0.0);
  EXPECT_TRUE((Recorded(3.0) * 4.0).is_constant());
  EXPECT_EQ((Recorded(3.0) * 4.0).constant(), 12.0);
  const Tape identity = recorder.finish({x * 1.0 + 0.0, -(-y) / 1.0});
  EXPECT_EQ(identity.instruction_count(), 0u);  // (the two negations were recorded, then dropped)
  TapeRecorder fresh({"x", "y"});
  const Recorded u = fresh.input(0), v = fresh.input(1);
  const Tape products = fresh.finish({u * v, v * u, u * v + v * u});
  EXPECT_EQ(products.instruction_count(), 2u);  // one product, one sum
  // a negation read by +, −, × or ÷ goes into it: x + (−y), (−x)·2, x − (−y), (−x)(−y): four
  TapeRecorder signs({"x", "y"});
  const Recorded p = signs.input(0), r = signs.input(1);
  const Tape negations = signs.finish({p + (-r), (-p) * 2.0, p - (-r), (-p) * (-r)});
  EXPECT_EQ(negations.instruction_count(), 4u);
  const std::vector<double> values = negations.evaluate(std::vector<double>{0.3, 1.7});
  EXPECT_EQ(values, (std::vector<double>{0.3 + (-1.7), (-0.3) * 2.0, 0.3 - (-1.7), 0.3 * 1.7}));
  TapeRecorder trig({"x"});
  const Recorded t = trig.input(0);
  const Tape sincos = trig.finish({sin(t), cos(t)});
  ASSERT_EQ(sincos.instruction_count(), 1u);
  EXPECT_EQ(sincos.instructions()[0].op, TapeOp::sincos);
}

// A tape replayed on recorded inputs gives the tape's values; constants of the inputs fold.
TEST(TapeRecorder, ReplaysATape) {
  TapeRecorder first({"x", "y"});
  const Tape inner = first.finish(sample_function(first.input(0), first.input(1)));
  TapeRecorder recorder({"x"});
  const std::vector<Recorded> inputs{recorder.input(0), Recorded(0.5)};
  const Tape replayed = recorder.finish(recorder.replay(inner, inputs));
  for (const double x : {-2.0, 0.1, 3.0}) {
    const std::vector<double> expected = inner.evaluate(std::vector<double>{x, 0.5});
    const std::vector<double> out = replayed.evaluate(std::vector<double>{x});
    for (std::size_t i = 0; i < out.size(); ++i) EXPECT_EQ(out[i], expected[i]) << i;
  }
}

// Watched values follow the outputs; a constant one is kept as its number.
TEST(TapeRecorder, WatchedValuesAreTheLastOutputs) {
  TapeRecorder recorder({"x"});
  const Recorded x = recorder.input(0);
  recorder.watch(x * x + 1.0);
  recorder.watch(Recorded(2.0));
  const Tape tape = recorder.finish({x});
  ASSERT_EQ(tape.output_count(), 3u);
  const std::vector<double> out = tape.evaluate(std::vector<double>{3.0});
  EXPECT_EQ(out[0], 3.0);
  EXPECT_EQ(out[1], 10.0);
  EXPECT_EQ(out[2], 2.0);
}

}  // namespace
}  // namespace unidyn
