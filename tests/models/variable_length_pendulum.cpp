// A spherical pendulum whose string is pulled in and let out (§2.7, §1.7 Fig. 1.7b, Ex. 4.2): a
// rheonomic constraint does work.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// Ψ = |r| − L0(t): the constraint force's power F_c · v is −λ ∂Ψ/∂t = λ L̇0 (Ex. 4.2), and the
// energy changes by its integral, E(t) − E(0) = ∫ λ L̇0 dt (§2.7), here by Simpson's rule on the
// 1 ms grid; E changes by more than 1 J, so it is not conserved.
TEST(VariableLengthPendulum, EnergyChangesByTheConstraintsWork) {
  const test::ModelRun run = test::run_model("variable-length-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.rows.size() % 2, 1u);  // an even number of intervals
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "power"), run.at(i, "lambda_Lrate"), 1e-10) << run.at(i, "t");
  }
  const std::vector<double> work = test::running_integral(run, "power");
  for (std::size_t i = 2; i < run.rows.size(); i += 2) {
    EXPECT_NEAR(run.at(i, "E") - run.at(0, "E"), work[i], 1e-9) << run.at(i, "t");
  }
  EXPECT_GT(std::abs(run.rows.back()[run.index("E")] - run.at(0, "E")), 1.0);
}

}  // namespace
}  // namespace unidyn
