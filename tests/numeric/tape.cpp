// Instruction tape: values against GiNaC's own evaluation, common subexpressions, powers,
// errors, edge cases and workspaces.
#include "unidyn/numeric/tape.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "support/oracles.hpp"

// Count heap allocations, to show that evaluation with a sized workspace makes none.
namespace {
std::atomic<long> allocation_count{0};
}  // namespace

// Every unaligned form is replaced, so that no pointer passes between these and a sanitizer's
// own operators. Kept out of line: inlined, GCC would take the free() for a mismatch with new.
[[gnu::noinline]] void* operator new(std::size_t size) {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void* operator new[](std::size_t size) {
  return operator new(size);
}
[[gnu::noinline]] void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  allocation_count.fetch_add(1, std::memory_order_relaxed);
  return std::malloc(size == 0 ? 1 : size);
}
[[gnu::noinline]] void* operator new[](std::size_t size, const std::nothrow_t& tag) noexcept {
  return operator new(size, tag);
}
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}

namespace unidyn {
namespace {

using GiNaC::ex;
using GiNaC::symbol;

ex numeric_ex(int numerator, int denominator) {
  return GiNaC::numeric(numerator, denominator);
}

// The double v as an exact GiNaC rational: v = f·2^e with f·2^53 an integer.
GiNaC::numeric exact(double v) {
  int e = 0;
  const double f = std::frexp(v, &e);
  const auto mantissa = static_cast<long>(std::ldexp(f, 53));
  return GiNaC::numeric(mantissa) * GiNaC::numeric(2).power(e - 53);
}

// GiNaC's value of e at the point: exact substitution, then evalf to 30 digits.
double ginac_value(const ex& e, const GiNaC::exmap& point) {
  GiNaC::Digits = 30;
  const ex v = e.subs(point).evalf();
  if (!GiNaC::is_exactly_a<GiNaC::numeric>(v) || !GiNaC::ex_to<GiNaC::numeric>(v).is_real())
    ADD_FAILURE() << "GiNaC did not evaluate " << e << " to a real number: " << v;
  return GiNaC::ex_to<GiNaC::numeric>(v.real_part()).to_double();
}

// |a − b| ≤ 1e-12 · max(|b|, 1): relative, with inputs and outputs of order one.
::testing::AssertionResult close(double a, double b) {
  if (std::fabs(a - b) <= 1e-12 * std::max(std::fabs(b), 1.0)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " vs GiNaC " << b << " (difference " << a - b << ")";
}

// Random inputs, each uniform in [lo, hi].
std::vector<double> random_point(test::Random& random, std::size_t n, double lo, double hi) {
  std::vector<double> x(n);
  for (double& v : x) v = random.uniform(lo, hi);
  return x;
}

// Tape and GiNaC agree on every output at `count` random points in [lo, hi]^n.
void expect_matches_ginac(const std::vector<ex>& outputs, const std::vector<symbol>& inputs,
                          double lo, double hi, int count = 200) {
  const Tape tape = Tape::compile(outputs, inputs);
  ASSERT_EQ(tape.input_count(), inputs.size());
  ASSERT_EQ(tape.output_count(), outputs.size());
  TapeWorkspace workspace(tape);
  test::Random random;
  std::vector<double> values(outputs.size());
  for (int p = 0; p < count; ++p) {
    const std::vector<double> x = random_point(random, inputs.size(), lo, hi);
    tape.evaluate(x, values, workspace);
    GiNaC::exmap point;
    for (std::size_t i = 0; i < inputs.size(); ++i) point[inputs[i]] = exact(x[i]);
    for (std::size_t k = 0; k < outputs.size(); ++k)
      ASSERT_TRUE(close(values[k], ginac_value(outputs[k], point)))
          << "output " << k << " = " << outputs[k] << " at point " << p;
  }
}

std::size_t instructions(const ex& e, const std::vector<symbol>& inputs) {
  return Tape::compile({e}, inputs).instruction_count();
}

struct Symbols {
  symbol x{"x"}, y{"y"}, z{"z"}, w{"w"};
  std::vector<symbol> all() const { return {x, y, z, w}; }
};

// Spherical pendulum (q = θ, φ; r = L (sinθ cosφ, sinθ sinφ, −cosθ)) by Lagrange's equations:
// M_ij = ∂²T/∂q̇_i∂q̇_j, f_i = ∂T/∂q_i − ∂U/∂q_i − Σ_j ∂²T/∂q̇_i∂q_j q̇_j.
struct SphericalPendulum {
  symbol theta{"theta"}, phi{"phi"}, dtheta{"dtheta"}, dphi{"dphi"}, m{"m"}, L{"L"}, g{"g"};

  std::vector<symbol> inputs() const { return {theta, phi, dtheta, dphi, m, L, g}; }

  std::vector<ex> mass_matrix_and_forcing() const {
    const std::array<ex, 3> r = {L * sin(theta) * cos(phi), L * sin(theta) * sin(phi),
                                 -L * cos(theta)};
    const std::array<symbol, 2> q = {theta, phi}, dq = {dtheta, dphi};
    ex T = 0;
    for (const ex& ri : r) {
      const ex vi = ri.diff(theta) * dtheta + ri.diff(phi) * dphi;
      T += m * vi * vi / 2;
    }
    const ex U = m * g * r[2];
    std::vector<ex> out;
    for (const symbol& a : dq)
      for (const symbol& b : dq) out.push_back(T.diff(a).diff(b));
    for (std::size_t i = 0; i < 2; ++i) {
      ex f = T.diff(q[i]) - U.diff(q[i]);
      for (std::size_t j = 0; j < 2; ++j) f -= T.diff(dq[i]).diff(q[j]) * dq[j];
      out.push_back(f);
    }
    return out;
  }
};

// Polynomials of several degrees and signs.
TEST(Tape, PolynomialsMatchGinac) {
  const Symbols s;
  const auto [x, y, z, w] = std::array<ex, 4>{s.x, s.y, s.z, s.w};
  expect_matches_ginac({x, 3 * x * x - 2 * x * y + 7, pow(x + y, 5), (x - y) * (y - z) * (z - w),
                        pow(x, 8) + pow(x, 4) + pow(x, 2), -x - y - z, 1 - pow(x * y - z, 3),
                        pow(x + y, 3).expand(), numeric_ex(7, 3) * pow(w, 7) - x / 4},
                       s.all(), -2.0, 2.0);
}

// Quotients with denominators bounded away from zero on the sampled region.
TEST(Tape, RationalFunctionsMatchGinac) {
  const Symbols s;
  const auto [x, y, z, w] = std::array<ex, 4>{s.x, s.y, s.z, s.w};
  expect_matches_ginac(
      {1 / (1 + x * x), (x * y - 1) / (2 + z * z + w * w), -2 * x / (y + 3), pow(1 + x * x, -3) * y,
       x / ((y + 3) * (z + 4)), 1 / (x + 3) + 1 / (y + 3), (pow(x, 3) - y) / pow(2 + z * z, 2)},
      s.all(), -2.0, 2.0);
}

// Every supported function, each inside its real domain on [−2, 2]^4.
TEST(Tape, AllFunctionsMatchGinac) {
  const Symbols s;
  const auto [x, y, z, w] = std::array<ex, 4>{s.x, s.y, s.z, s.w};
  expect_matches_ginac({sin(x * y),
                        cos(x + z),
                        tan(x / 2),
                        asin(x / 3),
                        acos(y / 3),
                        atan(x * z),
                        atan2(y, x),
                        sinh(x),
                        cosh(y - z),
                        tanh(2 * w),
                        exp(x - y),
                        log(1 + x * x),
                        sqrt(2 + y),
                        abs(x - y),
                        GiNaC::csgn(x * y),
                        GiNaC::step(z - w),
                        pow(1 + x * x, y),
                        pow(2 + z, numeric_ex(1, 3)),
                        pow(1 + y * y, numeric_ex(3, 2)),
                        pow(3 + w, numeric_ex(-5, 2)),
                        1 / sqrt(3 + x),
                        sin(x) * cos(x) - sin(2 * x) / 2 + sin(y) * sin(y),
                        GiNaC::Pi * x + sqrt(ex(2)) * y},
                       s.all(), -2.0, 2.0);
}

// Nested trigonometry: the spherical pendulum's mass matrix and forcing.
TEST(Tape, SphericalPendulumMatchesGinac) {
  const SphericalPendulum p;
  expect_matches_ginac(p.mass_matrix_and_forcing(), p.inputs(), 0.1, 3.0, 300);
}

// The same tape against the closed forms M = mL² diag(1, sin²θ), f_θ = mL² sinθ cosθ φ̇² − mgL
// sinθ, f_φ = −2mL² sinθ cosθ θ̇ φ̇: an oracle that does not come from the same expressions.
TEST(Tape, SphericalPendulumMatchesClosedForm) {
  const SphericalPendulum p;
  const Tape tape = Tape::compile(p.mass_matrix_and_forcing(), p.inputs());
  test::Random random;
  for (int k = 0; k < 200; ++k) {
    const std::vector<double> x = random_point(random, 7, 0.1, 3.0);
    const double s = std::sin(x[0]), c = std::cos(x[0]), mL2 = x[4] * x[5] * x[5];
    const std::vector<double> out = tape.evaluate(x);
    EXPECT_TRUE(close(out[0], mL2));
    EXPECT_TRUE(close(out[1], 0.0));
    EXPECT_TRUE(close(out[2], 0.0));
    EXPECT_TRUE(close(out[3], mL2 * s * s));
    EXPECT_TRUE(close(out[4], mL2 * s * c * x[3] * x[3] - x[4] * x[6] * x[5] * s));
    EXPECT_TRUE(close(out[5], -2 * mL2 * s * c * x[2] * x[3]));
  }
}

// Sums whose terms share subexpressions, across several outputs.
TEST(Tape, SharedSubexpressionsMatchGinac) {
  const Symbols s;
  const auto [x, y, z, w] = std::array<ex, 4>{s.x, s.y, s.z, s.w};
  const ex u = x * y + z, v = sin(u) * cos(w);
  expect_matches_ginac({sin(u) + exp(u), pow(u, 2) + pow(u, 3) + u, v + pow(v, 2) - 1 / (2 + v),
                        v * u, exp(-u) * sin(u) + cos(u) * cos(u)},
                       s.all(), -1.5, 1.5);
}

// u = x·y + z costs 2 instructions (mul, add); sin(u) and exp(u) 3 each when compiled alone.
// Together, u is computed once: 2 + sin + exp + the outer add = 5 < 3 + 3 + 1.
TEST(Tape, RepeatedSubexpressionIsEvaluatedOnce) {
  const Symbols s;
  const ex u = s.x * s.y + s.z;
  const std::vector<symbol> in = s.all();
  EXPECT_EQ(instructions(sin(u), in), 3u);
  EXPECT_EQ(instructions(exp(u), in), 3u);
  EXPECT_EQ(instructions(sin(u) + exp(u), in), 5u);
  // (x + y)² + (x + y)³: the sum once, its square once, the cube as square × sum, one add.
  const ex t = s.x + s.y;
  EXPECT_EQ(instructions(pow(t, 2), in), 2u);
  EXPECT_EQ(instructions(pow(t, 3), in), 3u);
  EXPECT_EQ(instructions(pow(t, 2) + pow(t, 3), in), 4u);
}

// Common factors come out of sums first (pass 0, symbolic/horner_form.hpp): x y + x z + x w is
// x (y + z + w), 2 additions and 1 multiplication rather than 3 and 2; an expanded polynomial
// evaluated that way keeps its value.
TEST(Tape, CommonFactorsTakenOutOfSums) {
  const Symbols s;
  EXPECT_EQ(instructions(s.x * s.y + s.x * s.z + s.x * s.w, s.all()), 3u);
  EXPECT_EQ(instructions(s.y / s.x + s.z / s.x, s.all()), 2u);  // (y + z)/x
  expect_matches_ginac({GiNaC::expand(pow(s.x + s.y - s.z, 6)),
                        GiNaC::expand((s.x + s.w) * pow(s.y - 1, 3) * (s.z + 2))},
                       s.all(), 0.5, 1.5);
}

// Across outputs: {sin u, exp u, sin u + exp u} needs 5 instructions, not 3 + 3 + 5.
TEST(Tape, SubexpressionsAreSharedAcrossOutputs) {
  const Symbols s;
  const ex u = s.x * s.y + s.z;
  EXPECT_EQ(Tape::compile({sin(u), exp(u), sin(u) + exp(u)}, s.all()).instruction_count(), 5u);
  EXPECT_EQ(Tape::compile({sin(s.x), sin(s.x)}, s.all()).instruction_count(), 1u);
  // The pendulum's outputs all use sin θ and cos θ: together far cheaper than one by one.
  const SphericalPendulum p;
  const std::vector<ex> outputs = p.mass_matrix_and_forcing();
  std::size_t separately = 0;
  for (const ex& e : outputs) separately += instructions(e, p.inputs());
  const std::size_t together = Tape::compile(outputs, p.inputs()).instruction_count();
  EXPECT_LT(together, separately);
  EXPECT_GE(separately - together, 4u);  // at least sin θ, cos θ, ... shared by ≥ 2 outputs
}

// Powers: repeated squaring, reciprocals, square roots; std::pow only when none applies.
TEST(Tape, PowersUseMultiplicationSqrtAndReciprocal) {
  const Symbols s;
  const ex x = s.x;
  const std::vector<symbol> in = {s.x, s.y};
  EXPECT_EQ(instructions(pow(x, 2), in), 1u);                          // x·x
  EXPECT_EQ(instructions(pow(x, 3), in), 2u);                          // x²·x
  EXPECT_EQ(instructions(pow(x, 4), in), 2u);                          // (x²)²
  EXPECT_EQ(instructions(pow(x, 8), in), 3u);                          // ((x²)²)²
  EXPECT_EQ(instructions(pow(x, 7), in), 4u);                          // ((x²·x)²)·x
  EXPECT_EQ(instructions(pow(x, -1), in), 1u);                         // 1/x
  EXPECT_EQ(instructions(pow(x, -2), in), 2u);                         // 1/(x·x)
  EXPECT_EQ(instructions(sqrt(x), in), 1u);                            // √x
  EXPECT_EQ(instructions(1 / sqrt(x), in), 2u);                        // 1/√x
  EXPECT_EQ(instructions(pow(x, numeric_ex(3, 2)), in), 2u);           // x·√x
  EXPECT_EQ(instructions(pow(x, numeric_ex(-3, 2)), in), 3u);          // 1/(x·√x)
  EXPECT_EQ(instructions(pow(x, numeric_ex(1, 3)), in), 1u);           // pow
  EXPECT_EQ(instructions(pow(x, s.y), in), 1u);                        // pow
  EXPECT_EQ(instructions(pow(x, 8) + pow(x, 4) + pow(x, 2), in), 5u);  // x², x⁴, x⁸, 2 adds
  EXPECT_NE(Tape::compile({sqrt(x)}, in).listing().find("sqrt"), std::string::npos);
  EXPECT_NE(Tape::compile({pow(x, numeric_ex(1, 3))}, in).listing().find("pow"), std::string::npos);
  expect_matches_ginac({pow(x, 7), pow(x, -2), pow(x, numeric_ex(-3, 2)), pow(x, 100), pow(x, -65),
                        pow(x, numeric_ex(5, 2)), pow(x, ex(2.5))},
                       in, 0.5, 1.5);
}

// Quotients and signs: a/b is one division, a − b one subtraction, −a − b an add and a negation.
TEST(Tape, ProductsAndSumsAreFlattened) {
  const Symbols s;
  const ex x = s.x, y = s.y, z = s.z;
  const std::vector<symbol> in = s.all();
  EXPECT_EQ(instructions(x / y, in), 1u);
  EXPECT_EQ(instructions(x / sqrt(y), in), 2u);
  EXPECT_EQ(instructions(1 / (x * y), in), 2u);
  EXPECT_EQ(instructions(-2 * x / y, in), 2u);
  EXPECT_EQ(instructions(x - y, in), 1u);
  EXPECT_EQ(instructions(-x - y, in), 2u);
  EXPECT_EQ(instructions(3 - x, in), 1u);
  EXPECT_EQ(instructions(x * y * z * s.w, in), 3u);
  EXPECT_EQ(instructions(x + y + z + s.w + 1, in), 4u);
}

// GiNaC gives a product its sign, and puts it into one of its sums, by its order of terms (which
// follows the memory layout): one product is −(x + a)(a − b + c) in one run, (x + a)(b − a − c)
// in another (made here as such, held from GiNaC's evaluation). Both make one tape, whose values
// are the expression's to the last bit (a negation is exact); so do (a − b)³(c − x)(x − a) and
// (b − a)³(c − x)(a − x).
TEST(Tape, EitherSignOfASumMakesOneTape) {
  const Symbols s;
  const ex x = s.x, a = s.y, b = s.z, c = s.w;
  const std::vector<symbol> in = s.all();
  const auto held = [](const GiNaC::exvector& factors) -> ex { return GiNaC::mul(factors).hold(); };
  const ex negated = held({a - b + c, x + a, ex(-1)}), turned = held({b - a - c, x + a});
  const ex cube = held({GiNaC::pow(a - b, 3), c - x, x - a}),
           turned_cube = held({GiNaC::pow(b - a, 3), c - x, a - x});
  ASSERT_FALSE(negated.is_equal(turned));
  ASSERT_FALSE(cube.is_equal(turned_cube));
  ASSERT_TRUE((negated - turned).expand().is_zero());
  ASSERT_TRUE((cube - turned_cube).expand().is_zero());
  const Tape t1 = Tape::compile({negated, 1 + negated, cube}, in);
  const Tape t2 = Tape::compile({turned, 1 + turned, turned_cube}, in);
  EXPECT_EQ(t1.listing(), t2.listing());
  const std::vector<double> point{0.3, -1.7, 2.9, 0.125};
  EXPECT_EQ(t1.evaluate(point), t2.evaluate(point));
  const GiNaC::exmap exact_point{
      {x, exact(0.3)}, {a, exact(-1.7)}, {b, exact(2.9)}, {c, exact(0.125)}};
  EXPECT_TRUE(close(t1.evaluate(point)[0], ginac_value(negated, exact_point)));
  EXPECT_TRUE(close(t1.evaluate(point)[2], ginac_value(cube, exact_point)));
  // a − b and a + b are not one sum
  EXPECT_NE(Tape::compile({(a - b) * x}, in).listing(), Tape::compile({(a + b) * x}, in).listing());
}

// A product reuses any product of two of its factors made already, not only one its register
// order begins with: y z, then x y z as x (y z) — two multiplications, not three.
TEST(Tape, ProductsReuseMadePairs) {
  const Symbols s;
  const Tape tape = Tape::compile({s.y * s.z, s.x * s.y * s.z}, s.all());
  EXPECT_EQ(tape.instruction_count(), 2u) << tape.listing();
  const std::vector<double> out = tape.evaluate(std::vector<double>{2.0, 3.0, 5.0, 0.0});
  EXPECT_EQ(out[0], 15.0);
  EXPECT_EQ(out[1], 30.0);
}

// A sum likewise reuses sums and differences of two of its terms made already: y − z and x + w,
// then x + y − z + w as (y − z) + (x + w) — three instructions, where a fold in one order shares
// at most one of the two.
TEST(Tape, SumsReuseMadePairs) {
  const Symbols s;
  const ex x = s.x, y = s.y, z = s.z, w = s.w;
  const Tape tape = Tape::compile({y - z, x + w, x + y - z + w, -(x + y - z + w)}, s.all());
  EXPECT_EQ(tape.instruction_count(), 4u) << tape.listing();  // and one negation
  const std::vector<double> out = tape.evaluate(std::vector<double>{2.0, 3.0, 5.0, 7.0});
  EXPECT_EQ(out[2], 2.0 + 3.0 - 5.0 + 7.0);
  EXPECT_EQ(out[3], -out[2]);
}

// sin and cos of one argument are one sincos instruction.
TEST(Tape, SinAndCosOfOneArgumentShareOneInstruction) {
  const Symbols s;
  const ex u = s.x * s.y;
  const Tape tape = Tape::compile({sin(u), cos(u)}, s.all());
  EXPECT_EQ(tape.instruction_count(), 2u);  // mul, sincos
  EXPECT_NE(tape.listing().find("sincos"), std::string::npos);
  const std::vector<double> out = tape.evaluate(std::vector<double>{0.3, -1.7, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(out[0], std::sin(0.3 * -1.7));
  EXPECT_DOUBLE_EQ(out[1], std::cos(0.3 * -1.7));
  // cos first and used before sin appears: the sincos goes where the cos was.
  const Tape reversed = Tape::compile({cos(s.x) * s.y + 1, sin(s.x)}, s.all());
  EXPECT_EQ(reversed.instruction_count(), 3u);  // sincos, mul, add
  const std::vector<double> back = reversed.evaluate(std::vector<double>{0.3, -1.7, 0.0, 0.0});
  EXPECT_DOUBLE_EQ(back[0], std::cos(0.3) * -1.7 + 1);
  EXPECT_DOUBLE_EQ(back[1], std::sin(0.3));
}

// Constant subexpressions are folded into constants.
TEST(Tape, ConstantSubexpressionsAreFolded) {
  const Symbols s;
  const Tape tape = Tape::compile(
      {sqrt(ex(2)) * s.x + sin(ex(1)), GiNaC::Pi * s.x, exp(ex(1)) / 3 + cos(ex(1))}, {s.x});
  EXPECT_EQ(tape.instruction_count(), 3u);  // mul, add; mul
  const std::vector<double> out = tape.evaluate(std::vector<double>{0.25});
  EXPECT_DOUBLE_EQ(out[0], std::sqrt(2.0) * 0.25 + std::sin(1.0));
  EXPECT_DOUBLE_EQ(out[1], std::numbers::pi * 0.25);
  EXPECT_DOUBLE_EQ(out[2], std::exp(1.0) / 3 + std::cos(1.0));
}

// csgn, step and abs where they switch: csgn(0) = 0, step(0) = 1/2 as in GiNaC.
TEST(Tape, SignStepAndAbsAtTheirCorners) {
  const symbol x("x");
  const Tape tape = Tape::compile({GiNaC::csgn(x), GiNaC::step(x), abs(x)}, {x});
  for (const double v : {-2.5, -0.0, 0.0, 1e-300, 3.0}) {
    const std::vector<double> out = tape.evaluate(std::vector<double>{v});
    const GiNaC::exmap point = {{x, exact(v)}};
    EXPECT_EQ(out[0], ginac_value(GiNaC::csgn(x), point)) << v;
    EXPECT_EQ(out[1], ginac_value(GiNaC::step(x), point)) << v;
    EXPECT_EQ(out[2], std::fabs(v)) << v;
  }
  EXPECT_EQ(tape.evaluate(std::vector<double>{0.0})[0], 0.0);
  EXPECT_EQ(tape.evaluate(std::vector<double>{0.0})[1], 0.5);
}

// The error message of compiling `outputs`, or "" if it compiles.
std::string compile_error(const std::vector<ex>& outputs, const std::vector<symbol>& inputs) {
  try {
    (void)Tape::compile(outputs, inputs);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Tape, UnsupportedFunctionIsRefusedByName) {
  const symbol x("x");
  const std::string message = compile_error({x, 1 + GiNaC::tgamma(x)}, {x});
  EXPECT_NE(message.find("unsupported function tgamma"), std::string::npos) << message;
  EXPECT_NE(message.find("tgamma(x)"), std::string::npos) << message;
  EXPECT_NE(message.find("output 1"), std::string::npos) << message;
}

TEST(Tape, SymbolNotAmongInputsIsRefusedByName) {
  const symbol x("x"), stray("stray");
  const std::string message = compile_error({sin(x * stray)}, {x});
  EXPECT_NE(message.find("not among the inputs: stray"), std::string::npos) << message;
  // A symbol of the same name is a different symbol.
  EXPECT_NE(compile_error({x}, {symbol("x")}), "");
}

TEST(Tape, ComplexNumbersAreRefused) {
  const symbol x("x");
  EXPECT_NE(compile_error({GiNaC::I * x}, {x}).find("complex"), std::string::npos);
  EXPECT_NE(compile_error({x + 2 + GiNaC::I}, {x}).find("complex"), std::string::npos);
  EXPECT_NE(compile_error({pow(x, GiNaC::I)}, {x}).find("complex"), std::string::npos);
  EXPECT_NE(compile_error({x * sqrt(ex(-2))}, {x}), "");  // folds to no real number
}

TEST(Tape, OtherUnsupportedExpressionsAreRefused) {
  const symbol x("x"), y("y");
  EXPECT_NE(compile_error({GiNaC::step(x).diff(x)}, {x}).find("unevaluated derivative"),
            std::string::npos);
  EXPECT_NE(compile_error({GiNaC::Euler * x}, {x}).find("Euler"), std::string::npos);
  EXPECT_NE(compile_error({x == y}, {x, y}).find("relational"), std::string::npos);
  EXPECT_NE(compile_error({abs(x).diff(x)}, {x}).find("conjugate"), std::string::npos);
  EXPECT_NE(compile_error({x}, {x, x}).find("listed twice"), std::string::npos);
}

TEST(Tape, ZeroOutputsAndConstantOutputs) {
  const symbol x("x");
  const Tape empty = Tape::compile({}, {x});
  EXPECT_EQ(empty.output_count(), 0u);
  EXPECT_EQ(empty.instruction_count(), 0u);
  EXPECT_TRUE(empty.evaluate(std::vector<double>{1.0}).empty());
  EXPECT_EQ(Tape().evaluate({}).size(), 0u);
  // Constants (exact rationals rounded once), Pi, an input passed through, no inputs at all.
  const Tape constants =
      Tape::compile({ex(3), GiNaC::numeric(1, 3), GiNaC::Pi, ex(-0.5), sqrt(ex(2))}, {});
  EXPECT_EQ(constants.instruction_count(), 0u);
  const std::vector<double> c = constants.evaluate({});
  EXPECT_EQ(c, (std::vector<double>{3.0, 1.0 / 3.0, std::numbers::pi, -0.5, std::sqrt(2.0)}));
  const Tape identity = Tape::compile({x, 2 * x}, {x});
  EXPECT_EQ(identity.evaluate(std::vector<double>{1.5}), (std::vector<double>{1.5, 3.0}));
}

// Wrong span sizes are refused rather than read or written out of bounds.
TEST(Tape, EvaluateChecksSizes) {
  const symbol x("x"), y("y");
  const Tape tape = Tape::compile({x + y}, {x, y});
  TapeWorkspace workspace;
  std::vector<double> out(1), wide(2);
  EXPECT_THROW(tape.evaluate(std::vector<double>{1.0}, out, workspace), std::invalid_argument);
  EXPECT_THROW(tape.evaluate(std::vector<double>{1.0, 2.0}, wide, workspace),
               std::invalid_argument);
}

// One workspace serves tapes of different sizes in turn; it grows and never shrinks.
TEST(Tape, WorkspaceIsReusedAcrossTapesOfDifferentSizes) {
  const symbol x("x");
  const SphericalPendulum p;
  const Tape small = Tape::compile({x * x}, {x});
  const Tape large = Tape::compile(p.mass_matrix_and_forcing(), p.inputs());
  ASSERT_LT(small.register_count(), large.register_count());
  TapeWorkspace workspace;
  test::Random random;
  std::vector<double> small_out(1), large_out(6);
  for (int k = 0; k < 20; ++k) {
    const std::vector<double> a = random_point(random, 1, -2, 2), b = random_point(random, 7, 0, 3);
    small.evaluate(a, small_out, workspace);
    EXPECT_EQ(small_out, small.evaluate(a));
    EXPECT_GE(workspace.capacity(), small.register_count());
    large.evaluate(b, large_out, workspace);
    EXPECT_EQ(large_out, large.evaluate(b));
    EXPECT_EQ(workspace.capacity(), large.register_count());
  }
}

// Two workspaces evaluate one tape independently, also from two threads at once.
TEST(Tape, TwoWorkspacesEvaluateOneTapeIndependently) {
  const SphericalPendulum p;
  const Tape tape = Tape::compile(p.mass_matrix_and_forcing(), p.inputs());
  const std::vector<double> a = {0.3, 1.1, -0.4, 2.0, 1.5, 0.7, 9.81};
  const std::vector<double> b = {2.1, -0.2, 1.3, 0.1, 0.5, 1.2, 3.7};
  const std::vector<double> expected_a = tape.evaluate(a), expected_b = tape.evaluate(b);
  ASSERT_NE(expected_a, expected_b);
  TapeWorkspace first, second;
  std::vector<double> out_a(6), out_b(6);
  tape.evaluate(a, out_a, first);
  tape.evaluate(b, out_b, second);
  tape.evaluate(a, out_a, first);
  EXPECT_EQ(out_a, expected_a);
  EXPECT_EQ(out_b, expected_b);
  // Concurrently: each thread with its own workspace.
  const auto run = [&tape](const std::vector<double>& in, const std::vector<double>& expected,
                           bool& ok) {
    TapeWorkspace workspace(tape);
    std::vector<double> out(tape.output_count());
    ok = true;
    for (int k = 0; k < 2000; ++k) {
      tape.evaluate(in, out, workspace);
      ok = ok && out == expected;
    }
  };
  bool ok_a = false, ok_b = false;
  std::thread ta(run, std::cref(a), std::cref(expected_a), std::ref(ok_a));
  std::thread tb(run, std::cref(b), std::cref(expected_b), std::ref(ok_b));
  ta.join();
  tb.join();
  EXPECT_TRUE(ok_a);
  EXPECT_TRUE(ok_b);
}

// Once the workspace is sized, evaluation allocates nothing.
TEST(Tape, EvaluationDoesNotAllocate) {
  const SphericalPendulum p;
  const Tape tape = Tape::compile(p.mass_matrix_and_forcing(), p.inputs());
  TapeWorkspace workspace(tape);
  const std::vector<double> in = {0.3, 1.1, -0.4, 2.0, 1.5, 0.7, 9.81};
  std::vector<double> out(tape.output_count());
  const long before = allocation_count.load();
  for (int k = 0; k < 100; ++k) tape.evaluate(in, out, workspace);
  EXPECT_EQ(allocation_count.load(), before);
  // The counter does count: the allocating form allocates.
  (void)tape.evaluate(in);
  EXPECT_GT(allocation_count.load(), before);
}

// The same formulas in symbols created in the opposite order: GiNaC orders the terms of sums and
// products differently (its order follows symbol serial numbers and, between runs, load
// addresses), yet the tape is the same instruction for instruction, so results are reproducible.
TEST(Tape, TapeDoesNotDependOnGinacTermOrder) {
  const auto compile = [](bool reversed) {
    std::vector<symbol> s;
    for (int i = 0; i < 5; ++i) s.emplace_back("s" + std::to_string(reversed ? 4 - i : i));
    if (reversed) std::reverse(s.begin(), s.end());
    const ex a = s[0], b = s[1], c = s[2], d = s[3], e = s[4];
    const ex u = a * b + c;
    return Tape::compile({pow(a + b + c + d + e, 3).expand(), sin(u) * cos(d) + a * b * c * d * e,
                          exp(-u) / (1 + d * d) - pow(e, 5) * a + b * sqrt(1 + c * c),
                          a * sin(b) * cos(b) - c * d * e / (2 + a * a)},
                         s);
  };
  const Tape forward = compile(false), backward = compile(true);
  ASSERT_EQ(forward.instruction_count(), backward.instruction_count());
  EXPECT_EQ(forward.listing(), backward.listing());
}

// Temporaries share registers: the pendulum needs fewer than one register per instruction.
TEST(Tape, RegistersAreReused) {
  const SphericalPendulum p;
  const Tape tape = Tape::compile(p.mass_matrix_and_forcing(), p.inputs());
  EXPECT_LT(tape.register_count(),
            tape.input_count() + tape.constant_count() + tape.instruction_count());
  for (const TapeInstruction& i : tape.instructions()) {
    EXPECT_LT(i.dst, tape.register_count());
    EXPECT_LT(i.a, tape.register_count());
    EXPECT_LT(i.b, tape.register_count());
    EXPECT_GE(i.dst, tape.input_count() + tape.constant_count());  // inputs, constants read-only
  }
}

// The listing has a header, one line per input, constant, instruction and output.
TEST(Tape, ListingShowsTheProgram) {
  const symbol x("x"), y("y");
  const Tape tape = Tape::compile({sin(x * y) + 2, cos(x * y)}, {x, y});
  const std::string text = tape.listing();
  std::size_t lines = 0;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  EXPECT_EQ(lines, 1 + tape.input_count() + tape.constant_count() + tape.instruction_count() +
                       tape.output_count())
      << text;
  EXPECT_NE(text.find("input x"), std::string::npos) << text;
  EXPECT_NE(text.find("sincos"), std::string::npos) << text;
  EXPECT_NE(text.find("out1 = r"), std::string::npos) << text;
}

}  // namespace
}  // namespace unidyn
