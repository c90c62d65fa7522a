// `unidyn import` as a user runs it: the YAML on standard output or written to -o, the notes on
// standard error, a refused file with file:line:column and status 2; and a URDF file named
// wherever a model goes (`unidyn derive ROBOT.urdf`).
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace unidyn {
namespace {

namespace fs = std::filesystem;
using namespace cli_test;

// examples/urdf/three-link-arm.urdf of the source tree
std::string arm() {
  return (fs::path(UNIDYN_MODELS_DIR).parent_path() / "examples/urdf/three-link-arm.urdf").string();
}

TEST(Import, WritesTheModelToStandardOutputOrAFile) {
  const Outcome printed = run("import '" + arm() + "'");
  ASSERT_EQ(printed.status, 0) << printed.err;
  EXPECT_TRUE(contains(printed.out, "\ncoordinates: [shoulder, elbow, wrist]\n")) << printed.out;
  EXPECT_TRUE(contains(printed.err, "<limit> not applied")) << printed.err;

  const std::string output = temp_path("arm.yaml");
  const Outcome written = run("import '" + arm() + "' -o '" + output + "'");
  ASSERT_EQ(written.status, 0) << written.err;
  EXPECT_EQ(written.out, "");
  EXPECT_EQ(read_file(output), printed.out);
  // the file written is a model every command reads
  const Outcome derived = run("derive '" + output + "'");
  EXPECT_EQ(derived.status, 0) << derived.err;
  std::remove(output.c_str());
}

TEST(Import, RefusesABadFileAtItsLineAndColumnWithStatusTwo) {
  const std::string file = temp_path("bad.urdf");
  write_file(file,
             "<robot name=\"r\">\n  <link name=\"a\"><inertial><mass value=\"0.1x\"/>"
             "</inertial></link>\n</robot>\n");
  const Outcome refused = run("import '" + file + "'");
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.out, "");
  EXPECT_EQ(refused.err, file + ":2:41: mass value: '0.1x' is not a finite decimal number\n");
  // the same from any command that reads a model
  const Outcome derive = run("derive '" + file + "'");
  EXPECT_EQ(derive.status, 2);
  EXPECT_EQ(derive.err, refused.err);
  const Outcome other = run("import '" + arm() + ".yaml'");
  EXPECT_EQ(other.status, 2);
  std::remove(file.c_str());
}

TEST(Import, AUrdfFileIsAModelForEveryCommand) {
  const Outcome derived = run("derive '" + arm() + "'");
  ASSERT_EQ(derived.status, 0) << derived.err;
  EXPECT_TRUE(contains(derived.out, "three_link_arm: Lagrange's equations")) << derived.out;
  const Outcome checked = run("check '" + arm() + "'");
  EXPECT_EQ(checked.status, 0) << checked.out << checked.err;
}

}  // namespace
}  // namespace unidyn
