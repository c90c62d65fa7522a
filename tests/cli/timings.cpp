// derive --timings and check --timings: each phase's time on standard error, the equations on
// standard output exactly as without.
#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

TEST(Timings, DerivePrintsPhasesAndTheSameEquations) {
  const Outcome plain = run("derive double-pendulum");
  const Outcome timed = run("derive double-pendulum --timings");
  ASSERT_EQ(plain.status, 0) << plain.err;
  ASSERT_EQ(timed.status, 0) << timed.err;
  EXPECT_EQ(timed.out, plain.out);
  EXPECT_EQ(plain.err, "");
  for (const std::string phase :
       {"read model", "derive (lagrange)", "print: mass matrix, U, constraint terms",
        "print: convective terms (4.25)", "print: equations, grouped",
        "print: coefficients (simplified)", "in all"}) {
    EXPECT_TRUE(contains(timed.err, "  " + phase + " ")) << phase << " missing in\n" << timed.err;
  }
}

TEST(Timings, CheckPrintsPhases) {
  const Outcome timed = run("check double-pendulum --timings");
  ASSERT_EQ(timed.status, 0) << timed.err;
  EXPECT_TRUE(contains(timed.err, "  Newton-Euler = Lagrange (exact evaluation) ")) << timed.err;
  EXPECT_EQ(timed.out, run("check double-pendulum").out);
}

}  // namespace
}  // namespace unidyn::cli_test
