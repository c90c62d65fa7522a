// derive --timings and check --timings: each phase's time on standard error, the equations on
// standard output exactly as without. The notices of a long command (still working, last step).
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

// A command still running after the delay says so on standard error, with the last step it
// finished; its output is the same bytes.
TEST(ProgressNotices, ALongCommandSaysItIsStillWorking) {
  const std::string args = "simulate double-pendulum --t-end 3e3 --output-step 1e3";
  const Outcome watched = run(args, "UNIDYN_PROGRESS_AFTER=0.1");
  ASSERT_EQ(watched.status, 0) << watched.err;
  const auto notices = lines_starting(watched.err, "unidyn: still working after 0.");
  ASSERT_FALSE(notices.empty()) << watched.err;
  EXPECT_TRUE(contains(notices[0], " MB in memory); last step finished: ")) << notices[0];
  EXPECT_EQ(watched.out, run(args).out);
}

TEST(ProgressNotices, NoneForAQuickCommandOrWhenTurnedOff) {
  const Outcome quick = run("derive compound-pendulum", "UNIDYN_PROGRESS_AFTER=30");
  ASSERT_EQ(quick.status, 0) << quick.err;
  EXPECT_EQ(quick.err, "");
  const Outcome off =
      run("simulate double-pendulum --t-end 3e3 --output-step 1e3", "UNIDYN_PROGRESS_AFTER=never");
  ASSERT_EQ(off.status, 0) << off.err;
  EXPECT_FALSE(contains(off.err, "still working")) << off.err;
  // a value that is no delay is said, not guessed
  const Outcome bad = run("derive compound-pendulum", "UNIDYN_PROGRESS_AFTER=5s");
  ASSERT_EQ(bad.status, 0) << bad.err;
  EXPECT_TRUE(contains(bad.err, "UNIDYN_PROGRESS_AFTER=5s is neither a number of seconds"))
      << bad.err;
}

}  // namespace
}  // namespace unidyn::cli_test
