// `derive --format c|python` (numeric/code_export.hpp): the exported functions, compiled with the
// system's C compiler or run by python3, give q'' and λ equal to the simulation's own solve
// (CompiledSystem::solve) at random states, to round-off, for a model without constraints, one
// with rolling constraints, one with Euler parameters (M only semi-definite) and a closed loop. The
// MATLAB file is checked for its signature and solve only: no MATLAB or Octave runs here.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/numeric/code_export.hpp"

namespace unidyn {
namespace {

// Random states (t, q, q̇) of a model, each as one line "t q... qd...".
std::vector<std::vector<double>> random_states(std::size_t n, std::size_t count) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<std::vector<double>> states;
  for (std::size_t s = 0; s < count; ++s) {
    std::vector<double> state{0.3 * double(s)};
    for (std::size_t i = 0; i < 2 * n; ++i) state.push_back(uniform(random));
    states.push_back(state);
  }
  return states;
}

std::string read_all(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// q'' and λ of the exported code for each state, read from its output (one line per state).
std::vector<std::vector<double>> numbers_in(const std::string& text) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream values(line);
    std::vector<double> row;
    for (double x; values >> x;) row.push_back(x);
    rows.push_back(row);
  }
  return rows;
}

// The exported q'' and λ against the compiled system's at the same states.
void expect_same_solution(const std::string& model, const std::vector<std::vector<double>>& got,
                          const std::vector<std::vector<double>>& states) {
  const System system = load_model(test::model_path(model));
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  std::vector<double> parameters;
  for (const auto& p : system.parameters) parameters.push_back(p.value);
  const auto n = static_cast<Eigen::Index>(system.coordinates().size());
  ASSERT_EQ(got.size(), states.size()) << model;
  for (std::size_t s = 0; s < states.size(); ++s) {
    Eigen::VectorXd q(n), qdot(n), qddot, lambda;
    for (Eigen::Index i = 0; i < n; ++i) {
      q[i] = states[s][1 + std::size_t(i)];
      qdot[i] = states[s][1 + std::size_t(n + i)];
    }
    if (model == "torque-free-quaternion") q.normalize();  // q = (e0, e1, e2, e3)
    compiled.solve(states[s][0], q, qdot, parameters, qddot, lambda, data);
    ASSERT_EQ(got[s].size(), std::size_t(n + lambda.size())) << model;
    for (Eigen::Index i = 0; i < n; ++i) {
      EXPECT_NEAR(got[s][std::size_t(i)], qddot[i], 1e-9 * (1 + std::abs(qddot[i])))
          << model << " state " << s << " q''[" << i << "]";
    }
    for (Eigen::Index k = 0; k < lambda.size(); ++k) {
      EXPECT_NEAR(got[s][std::size_t(n + k)], lambda[k], 1e-9 * (1 + std::abs(lambda[k])))
          << model << " state " << s << " lambda[" << k << "]";
    }
  }
}

// The states a driver reads: Euler parameters normalised as the solve above uses them.
std::vector<std::vector<double>> states_of(const std::string& model, std::size_t n) {
  auto states = random_states(n, 5);
  if (model == "torque-free-quaternion") {
    for (auto& s : states) {
      double norm = 0;
      for (std::size_t i = 1; i <= 4; ++i) norm += s[i] * s[i];
      for (std::size_t i = 1; i <= 4; ++i) s[i] /= std::sqrt(norm);
    }
  }
  return states;
}

// The states a driver reads, one line each, every digit of the doubles.
void write_states(const std::string& path, const std::vector<std::vector<double>>& states) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& s : states) {
    for (double x : s) out << x << " ";
    out << "\n";
  }
}

// Andrews' squeezer: sin and cos of angle sums, whose tape writes sin(x) over x's register
const char* const kModels[] = {"double-pendulum", "rolling-disk", "torque-free-quaternion",
                               "andrews-squeezer"};

TEST(CodeExport, CompiledCGivesTheSimulationsAccelerations) {
  if (std::system("command -v cc >/dev/null 2>&1") != 0) GTEST_SKIP() << "no C compiler (cc)";
  for (const char* model : kModels) {
    const System system = load_model(test::model_path(model));
    const std::size_t n = system.coordinates().size(), m = system.constraints.size();
    const std::string dir = testing::TempDir() + "unidyn_export_" + std::to_string(getpid());
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/eom.c") << export_code(system, lagrange_equations(system),
                                                 CodeLanguage::c, "model");
    std::ostringstream driver;
    driver << "#include <stdio.h>\nint model_accelerations(double, const double*, const double*, "
              "const double*, double*, double*);\nint main(void) {\n  double p[] = {";
    for (std::size_t k = 0; k < system.parameters.size(); ++k) {
      driver << (k ? ", " : "") << system.parameters[k].value;
    }
    driver << "};\n  double t, q[" << n << "], qd[" << n << "], qdd[" << n << "], lambda["
           << (m > 0 ? m : 1) << "];\n  while (scanf(\"%lf\", &t) == 1) {\n"
           << "    for (int i = 0; i < " << n << "; ++i) scanf(\"%lf\", &q[i]);\n"
           << "    for (int i = 0; i < " << n << "; ++i) scanf(\"%lf\", &qd[i]);\n"
           << "    if (model_accelerations(t, q, qd, p, qdd, lambda) != 0) return 1;\n"
           << "    for (int i = 0; i < " << n << "; ++i) printf(\"%.17g \", qdd[i]);\n"
           << "    for (int k = 0; k < " << m << "; ++k) printf(\"%.17g \", lambda[k]);\n"
           << "    printf(\"\\n\");\n  }\n  return 0;\n}\n";
    std::ofstream(dir + "/main.c") << driver.str();
    const auto states = states_of(model, n);
    write_states(dir + "/states.txt", states);
    const std::string build = "cd '" + dir +
                              "' && cc -std=c99 -O2 -Wall -Werror -o eom eom.c main.c -lm " +
                              ">build.log 2>&1 && ./eom <states.txt >out.txt 2>&1";
    ASSERT_EQ(std::system(build.c_str()), 0)
        << model << ": " << read_all(dir + "/build.log") << read_all(dir + "/out.txt");
    expect_same_solution(model, numbers_in(read_all(dir + "/out.txt")), states);
    std::filesystem::remove_all(dir);
  }
}

TEST(CodeExport, PythonGivesTheSimulationsAccelerations) {
  if (std::system("command -v python3 >/dev/null 2>&1") != 0) GTEST_SKIP() << "no python3";
  for (const char* model : kModels) {
    const System system = load_model(test::model_path(model));
    const std::size_t n = system.coordinates().size();
    const std::string dir = testing::TempDir() + "unidyn_export_py_" + std::to_string(getpid());
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/eom.py")
        << export_code(system, lagrange_equations(system), CodeLanguage::python, "model");
    std::ofstream(dir + "/main.py")
        << "import sys\nimport eom\np = list(eom.PARAMETERS.values())\nfor line in sys.stdin:\n"
        << "    x = [float(v) for v in line.split()]\n"
        << "    qdd, lam = eom.accelerations(x[0], x[1:" << n + 1 << "], x[" << n + 1 << ":], p)\n"
        << "    print(' '.join(repr(v) for v in qdd + lam))\n";
    const auto states = states_of(model, n);
    write_states(dir + "/states.txt", states);
    const std::string command = "cd '" + dir + "' && python3 main.py <states.txt >out.txt 2>&1";
    ASSERT_EQ(std::system(command.c_str()), 0) << model << ": " << read_all(dir + "/out.txt");
    expect_same_solution(model, numbers_in(read_all(dir + "/out.txt")), states);
    std::filesystem::remove_all(dir);
  }
}

TEST(CodeExport, MatlabFunctionHasItsSignatureAndSolve) {
  const System system = load_model(test::model_path("rolling-disk"));
  const std::string source =
      export_code(system, lagrange_equations(system), CodeLanguage::matlab, "rolling_disk");
  EXPECT_TRUE(
      source.starts_with("function [qdd, lambda, M, f, A, b] = rolling_disk(t, q, qd, p)\n"))
      << source.substr(0, 200);
  EXPECT_NE(source.find("  x = [M, -A'; A, zeros(3)] \\ [f; -b];\n"), std::string::npos);
  EXPECT_NE(source.find("p(1)"), std::string::npos);  // indices from 1
  EXPECT_EQ(source.find("[0]"), std::string::npos);
  EXPECT_TRUE(source.ends_with("end\n"));
}

}  // namespace
}  // namespace unidyn
