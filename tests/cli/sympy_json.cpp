// `derive --format json` is read by SymPy: its expressions sympify with the names the JSON declares
// (q, q_d, q_dd, the parameters), and its M and f equal those of SymPy's own LagrangesMethod for
// three bundled models built independently in tests/sympy/lagranges_method.py. python3-sympy comes
// from Debian (scripts/setup.sh test); without it the test is skipped, saying so.
#include <cstdlib>
#include <string>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

bool have_sympy() {
  return std::system("python3 -c 'import sympy' >/dev/null 2>&1") == 0;
}

TEST(SympyJson, LagrangesMethodAgrees) {
  if (!have_sympy()) GTEST_SKIP() << "python3 with sympy is not installed (python3-sympy)";
  for (const char* model : {"double-pendulum", "spherical-pendulum", "rotating-hoop"}) {
    const Outcome r = run("derive " + std::string(model) + " --format json");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string json = temp_path("equations.json"), log = temp_path("sympy.log");
    write_file(json, r.out);
    const std::string command = "python3 '" + std::string(UNIDYN_SYMPY_CHECK) + "' " + model +
                                " '" + json + "' >'" + log + "' 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << model << ":\n" << read_file(log);
    EXPECT_TRUE(contains(read_file(log), "agrees with LagrangesMethod")) << read_file(log);
  }
}

}  // namespace
}  // namespace unidyn
