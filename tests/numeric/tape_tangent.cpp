// Forward-mode derivatives of a tape (Tape::evaluate_tangent) against GiNaC's symbolic derivatives.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/random_expressions.hpp"
#include "unidyn/numeric/tape.hpp"

namespace unidyn {
namespace {

using GiNaC::ex;

// Σ_i ∂e/∂x_i · direction_i at the point, by GiNaC: symbolic derivatives, then evalf.
double ginac_tangent(const ex& e, const std::vector<ex>& inputs, const std::vector<double>& point,
                     const std::vector<double>& direction) {
  GiNaC::exmap at;
  for (std::size_t i = 0; i < inputs.size(); ++i) at[inputs[i]] = point[i];
  ex sum = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    sum += e.diff(GiNaC::ex_to<GiNaC::symbol>(inputs[i])) * direction[i];
  }
  const ex v = GiNaC::evalf(sum.subs(at));
  if (!GiNaC::is_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real()) return NAN;
  return GiNaC::ex_to<GiNaC::numeric>(v).to_double();
}

// Each operation the tape knows, by itself and composed.
TEST(TapeTangent, EveryOperationMatchesItsSymbolicDerivative) {
  const GiNaC::realsymbol x("x"), y("y");
  const std::vector<ex> inputs{x, y};
  const std::vector<ex> outputs{x + y,
                                x - 3 * y,
                                x * y,
                                x / y,
                                -x,
                                1 / x,
                                GiNaC::sqrt(x),
                                GiNaC::pow(x, y),
                                GiNaC::pow(x, 7),
                                GiNaC::pow(x, GiNaC::numeric(5, 3)),
                                GiNaC::sin(x * y),
                                GiNaC::cos(x) * GiNaC::sin(x),
                                GiNaC::tan(x),
                                GiNaC::asin(x / 2),
                                GiNaC::acos(x / 2),
                                GiNaC::atan(x),
                                GiNaC::atan2(x, y),
                                GiNaC::sinh(x),
                                GiNaC::cosh(x),
                                GiNaC::tanh(x),
                                GiNaC::exp(x * y),
                                GiNaC::log(x),
                                GiNaC::abs(x - y)};
  const Tape tape = Tape::compile(outputs, inputs);
  TapeWorkspace workspace;
  const std::vector<double> point{0.7, 1.3}, direction{0.4, -1.1};
  std::vector<double> values(outputs.size()), tangents(outputs.size());
  tape.evaluate_tangent(point, direction, values, tangents, workspace);
  const std::vector<double> plain = tape.evaluate(point);
  for (std::size_t k = 0; k < outputs.size(); ++k) {
    EXPECT_EQ(values[k], plain[k]) << outputs[k];  // the values are evaluate()'s, bit for bit
    const double want = ginac_tangent(outputs[k], inputs, point, direction);
    EXPECT_NEAR(tangents[k], want, 1e-13 * (1 + std::fabs(want))) << outputs[k];
  }
}

// 1 000 random expressions of the book's kinds, along random directions.
TEST(TapeTangent, RandomExpressionsMatchTheirSymbolicDerivatives) {
  using test::L;
  using test::m;
  using test::q1;
  using test::q2;
  using test::u;
  const std::vector<ex> inputs{q1, q2, u, m, L};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> value(0.2, 1.4), slope(-1.0, 1.0);
  int compared = 0;
  for (int k = 0; k < 1000; ++k) {
    const ex e = test::random_expression(rng, 3);
    std::vector<double> point, direction;
    for (std::size_t i = 0; i < inputs.size(); ++i) {
      point.push_back(value(rng));
      direction.push_back(slope(rng));
    }
    const double want = ginac_tangent(e, inputs, point, direction);
    if (!std::isfinite(want) || std::fabs(want) > 1e8) continue;  // complex, or ill-conditioned
    const Tape tape = Tape::compile({e}, inputs);
    TapeWorkspace workspace;
    double out = 0, tangent = 0;
    tape.evaluate_tangent(point, direction, std::span(&out, 1), std::span(&tangent, 1), workspace);
    EXPECT_NEAR(tangent, want, 1e-9 * (1 + std::fabs(want))) << e;
    ++compared;
  }
  EXPECT_GT(compared, 700);  // most of them real at the point
}

// Sizes are checked.
TEST(TapeTangent, WrongSizesRefused) {
  const GiNaC::realsymbol x("x");
  const Tape tape = Tape::compile({GiNaC::sin(x)}, {ex(x)});
  TapeWorkspace workspace;
  std::vector<double> in{1.0}, dir{1.0, 2.0}, out(1), dout(1);
  EXPECT_THROW(tape.evaluate_tangent(in, dir, out, dout, workspace), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
