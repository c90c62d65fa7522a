// A URDF robot's equations exported as C (`unidyn derive FILE --format c`,
// numeric/code_export.hpp), compiled by the system's C compiler with warnings as errors and run:
// its q̈ at random states agrees with Orocos KDL's (an engine written independently of unidyn,
// reading the file by this test's own URDF reading, kdl_oracle.hpp) to 1e-9 relative. The 7-DoF
// arm: the export of a robot-sized tree compiles and computes the robot's dynamics, not only
// unidyn's own.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "kdl_oracle.hpp"
#include "unidyn/numeric/code_export.hpp"

namespace unidyn {
namespace {

#ifdef UNIDYN_HAVE_KDL

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A driver for the exported model_accelerations: states "q... qd..." on standard input, q̈ out.
std::string driver_source(const System& system) {
  const std::size_t n = system.coordinates().size();
  std::ostringstream c;
  c.precision(17);
  c << "#include <stdio.h>\nint model_accelerations(double, const double*, const double*, "
       "const double*, double*, double*);\nint main(void) {\n  double p[] = {0";
  for (const auto& parameter : system.parameters) c << ", " << parameter.value;
  c << "};\n  double q[" << n << "], qd[" << n << "], qdd[" << n << "], lambda[1];\n"
    << "  for (;;) {\n    for (int i = 0; i < " << n
    << "; ++i) if (scanf(\"%lf\", &q[i]) != 1) return 0;\n"
    << "    for (int i = 0; i < " << n << "; ++i) if (scanf(\"%lf\", &qd[i]) != 1) return 1;\n"
    << "    if (model_accelerations(0.0, q, qd, p + 1, qdd, lambda) != 0) return 1;\n"
    << "    for (int i = 0; i < " << n << "; ++i) printf(\"%.17g \", qdd[i]);\n"
    << "    printf(\"\\n\");\n  }\n}\n";
  return c.str();
}

TEST(ExportedCodeAgainstKdl, IiwaLikeArmCompilesAndGivesKdlsAccelerations) {
  if (std::system("command -v cc >/dev/null 2>&1") != 0) GTEST_SKIP() << "no C compiler (cc)";
  const std::string file = engine_oracle::formats_model("iiwa-like-arm.urdf");
  const kdl_oracle::KdlTree kdl = kdl_oracle::read_kdl_tree(file);
  const System system = commands::load_named_model(file).system;
  const std::size_t n = system.coordinates().size();
  ASSERT_EQ(n, kdl.joint_names.size());
  const std::string dir = testing::TempDir() + "unidyn_arm_export_" + std::to_string(getpid());
  std::filesystem::create_directories(dir);
  std::ofstream(dir + "/eom.c") << export_code(system, lagrange_equations(system), CodeLanguage::c,
                                               "model");
  std::ofstream(dir + "/main.c") << driver_source(system);
  // random states within the joints' ranges
  test::Random random;
  std::vector<Eigen::VectorXd> qs, qdots;
  std::ofstream states(dir + "/states.txt");
  states.precision(17);
  for (int k = 0; k < 10; ++k) {
    Eigen::VectorXd q(static_cast<Eigen::Index>(n)), qdot(q.size());
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      q[i] = random.uniform(-2.0, 2.0);
      qdot[i] = random.uniform(-2.0, 2.0);
    }
    for (const double x : q) states << x << " ";
    for (const double x : qdot) states << x << " ";
    states << "\n";
    qs.push_back(q);
    qdots.push_back(qdot);
  }
  states.close();
  const std::string build = "cd '" + dir +
                            "' && cc -std=c99 -O1 -Wall -Werror -o eom eom.c main.c -lm "
                            ">build.log 2>&1 && ./eom <states.txt >out.txt 2>&1";
  ASSERT_EQ(std::system(build.c_str()), 0)
      << read_text(dir + "/build.log") << read_text(dir + "/out.txt");
  std::istringstream out(read_text(dir + "/out.txt"));
  double largest = 0;
  for (std::size_t k = 0; k < qs.size(); ++k) {
    Eigen::VectorXd exported(qs[k].size());
    for (Eigen::Index i = 0; i < exported.size(); ++i) ASSERT_TRUE(out >> exported[i]) << k;
    const Eigen::VectorXd reference = kdl_oracle::kdl_dynamics(kdl, qs[k], qdots[k]).qddot;
    largest = std::max(largest, (exported - reference).norm() / reference.norm());
  }
  EXPECT_LT(largest, 1e-9);
  std::printf("iiwa-like-arm.urdf exported as C (%zu bytes) against KDL: q'' relative error %.3g\n",
              static_cast<std::size_t>(std::filesystem::file_size(dir + "/eom.c")), largest);
  std::filesystem::remove_all(dir);
}

#else

TEST(ExportedCodeAgainstKdl, Skipped) {
  GTEST_SKIP() << "Orocos KDL is not installed (scripts/setup.sh test installs liborocos-kdl-dev)";
}

#endif

}  // namespace
}  // namespace unidyn
