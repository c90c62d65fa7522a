// UNIDYN_PROCESSES, the processes `derive` shares its simplification among
// (symbolic/process_map.hpp): the same equations, byte for byte, with one process or several; a
// value that is not a positive integer refused.
#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

TEST(Processes, TheSameEquationsWithOneOrSeveral) {
  for (const std::string command : {"derive rolling-disk", "derive heavy-top --format latex",
                                    "derive double-pendulum --form zees"}) {
    const Outcome one = run(command, "UNIDYN_PROCESSES=1");
    ASSERT_EQ(one.status, 0) << command << ": " << one.err;
    for (const std::string n : {"2", "4"}) {
      const Outcome several = run(command, "UNIDYN_PROCESSES=" + n);
      EXPECT_EQ(several.status, 0) << command << ": " << several.err;
      EXPECT_EQ(several.out, one.out) << command << " with " << n << " processes";
    }
  }
}

TEST(Processes, NotAPositiveIntegerIsRefused) {
  for (const std::string bad : {"0", "-1", "many"}) {
    const Outcome r = run("derive double-pendulum", "UNIDYN_PROCESSES=" + bad);
    EXPECT_EQ(r.status, 2) << bad;
    EXPECT_TRUE(contains(r.err, "UNIDYN_PROCESSES must be a positive integer, not '" + bad + "'"))
        << r.err;
    EXPECT_EQ(r.out, "") << bad;
  }
}

}  // namespace
}  // namespace unidyn::cli_test
