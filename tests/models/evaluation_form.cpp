// The evaluation form of the equations (numeric/evaluation_form.hpp): the same values as the
// derived expressions at random states, fewer sines and cosines where they cancel, large entries
// left as derived.
#include "unidyn/numeric/evaluation_form.hpp"

#include <random>

#include "support/model_run.hpp"
#include "unidyn/equations/kane.hpp"

namespace unidyn {
namespace {

// The trigonometric instructions of a tape (sin, cos, sincos).
std::size_t trig_instructions(const Tape& tape) {
  std::size_t count = 0;
  for (const TapeInstruction& i : tape.instructions()) {
    count += i.op == TapeOp::sin || i.op == TapeOp::cos || i.op == TapeOp::sincos;
  }
  return count;
}

// M, f, A, b as derived, in dynamics_tape's order, on a tape of their own.
Tape derived_dynamics_tape(const System& system, const EquationsOfMotion& eq) {
  std::vector<Expr> outputs = eq.mass_matrix.data;
  outputs.insert(outputs.end(), eq.forcing.begin(), eq.forcing.end());
  outputs.insert(outputs.end(), eq.constraint_matrix.data.begin(), eq.constraint_matrix.data.end());
  outputs.insert(outputs.end(), eq.constraint_bias.begin(), eq.constraint_bias.end());
  return Tape::compile(outputs, tape_inputs(system, false));
}

class EvaluationForm : public ::testing::TestWithParam<std::string> {};

// The evaluation form's M, f, A, b agree with the derived ones to round-off at random states.
TEST_P(EvaluationForm, SameValuesAsTheDerivedEquations) {
  const System system = load_model(test::model_path(GetParam()));
  const EquationsOfMotion equations = lagrange_equations(system);
  const Tape form = dynamics_tape(system, equations);
  const Tape derived = derived_dynamics_tape(system, equations);
  ASSERT_EQ(form.output_count(), derived.output_count());
  std::mt19937 random(5);
  std::uniform_real_distribution<double> value(-2.0, 2.0);
  std::vector<double> inputs(form.input_count());
  for (int trial = 0; trial < 20; ++trial) {
    for (double& x : inputs) x = value(random);
    const std::vector<double> a = form.evaluate(inputs), b = derived.evaluate(inputs);
    for (std::size_t k = 0; k < a.size(); ++k) {
      EXPECT_NEAR(a[k], b[k], 1e-12 * (1 + std::abs(b[k]))) << GetParam() << " output " << k;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Bundled, EvaluationForm,
                         ::testing::Values("heavy-top", "rolling-disk", "double-pendulum",
                                           "torque-free-body", "rate-gyroscope", "sphere-incline"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

// The heavy top in 3-1-3 angles: ψ and φ enter M and f as derived only through sin² + cos² = 1;
// the evaluation form needs the sine and cosine of θ alone (one sincos instead of three).
TEST(EvaluationFormHeavyTop, OnlyTheNutationAngleIsEvaluated) {
  const System system = load_model(test::model_path("heavy-top"));
  const EquationsOfMotion equations = kane_equations(system);
  const std::size_t derived = trig_instructions(derived_dynamics_tape(system, equations));
  const std::size_t form = trig_instructions(dynamics_tape(system, equations));
  EXPECT_EQ(form, 1u);
  EXPECT_GT(derived, form);
}

// Each small entry becomes its simplification only when that is smaller; a large one (past the
// node bound) stays exactly as derived.
TEST(EvaluationFormEntries, SimplifiedOnlyWhenSmallAndShorter) {
  const GiNaC::symbol x("x"), y("y");
  EquationsOfMotion eq;
  eq.mass_matrix = ExprMatrix(1, 1);
  eq.mass_matrix(0, 0) = 3 * pow(sin(x), 2) + 3 * pow(cos(x), 2) + y;
  Expr large = 0;
  for (int k = 1; k <= 200; ++k) large += k * pow(y, k);
  large += pow(sin(x), 2) + pow(cos(x), 2);
  eq.forcing = {x * y, large};
  const EquationsOfMotion form = evaluation_form(eq);
  EXPECT_TRUE(form.mass_matrix(0, 0).is_equal(y + 3)) << form.mass_matrix(0, 0);
  EXPECT_TRUE(form.forcing[0].is_equal(x * y));
  EXPECT_TRUE(form.forcing[1].is_equal(large));
}

}  // namespace
}  // namespace unidyn
