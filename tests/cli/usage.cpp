// How the command introduces itself: bare `unidyn` prints its usage, `--version` its version,
// `--help` points to the model language's reference, and a mistyped bundled model's name gets
// the nearest one.
#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

TEST(Usage, BareCommandPrintsUsage) {
  const Outcome r = run("");
  EXPECT_EQ(r.status, 0) << r.err;
  for (const char* part : {"derive", "simulate", "check", "models", "rotation", "--version"}) {
    EXPECT_TRUE(contains(r.out, part)) << part << "\n" << r.out;
  }
  EXPECT_TRUE(contains(r.out, "docs/model-format.md")) << r.out;
  EXPECT_EQ(r.err, "");
}

TEST(Usage, VersionAndHelp) {
  const Outcome version = run("--version");
  EXPECT_EQ(version.status, 0);
  EXPECT_EQ(version.out, "unidyn 0.1.0\n");
  const Outcome help = run("--help");
  EXPECT_EQ(help.status, 0);
  EXPECT_TRUE(contains(help.out, "docs/model-format.md")) << help.out;
}

TEST(Usage, MistypedModelNameGetsTheNearest) {
  const Outcome r = run("derive spherical-pendulm");
  expect_bad_input(r, "spherical-pendulm");
  EXPECT_TRUE(contains(r.err, "did you mean 'spherical-pendulum'?")) << r.err;
  const Outcome far = run("simulate zzzzzzzzzzzz");
  expect_bad_input(far, "zzzzzzzzzzzz");
  EXPECT_FALSE(contains(far.err, "did you mean")) << far.err;
  EXPECT_TRUE(contains(far.err, "neither a model file nor a bundled model")) << far.err;
  // a path that does not exist is named as such
  const Outcome path = run("check /nonexistent/model.yaml");
  expect_bad_input(path, "path");
  EXPECT_TRUE(contains(path.err, "/nonexistent/model.yaml: cannot open the model file"))
      << path.err;
}

}  // namespace
}  // namespace unidyn
