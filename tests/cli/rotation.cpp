// The `unidyn rotation` command run as a user runs it: `convert` between parametrisations (book
// §6.5, §6.8, §6.9) and `show`; bad input gives one line on stderr and exit status 2.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "support/oracles.hpp"  // test_cli_rotation has no tests/ include directory
#include "unidyn/rotation/parametrisation.hpp"

namespace unidyn {
namespace {

using test::kPi;
using test::max_abs_diff;

struct Outcome {
  int status;
  std::string out;
  std::string err;
};

// Runs `unidyn ARGS` through the shell; stdout through the pipe, stderr to a temporary file named
// by process id and call (ctest may run the test cases as parallel processes).
Outcome run(const std::string& args) {
  static int counter = 0;
  const std::string err_path = testing::TempDir() + "unidyn_cli_rotation_stderr_" +
                               std::to_string(getpid()) + "_" + std::to_string(++counter) + ".txt";
  const std::string command =
      std::string("'") + UNIDYN_EXECUTABLE + "' " + args + " 2>'" + err_path + "'";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) {
    ADD_FAILURE() << "popen failed for " << command;
    return {-1, "", ""};
  }
  std::string out;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) out.append(buffer.data(), n);
  const int raw = pclose(pipe);
  std::ifstream err_file(err_path);
  std::stringstream err;
  err << err_file.rdbuf();
  std::remove(err_path.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out, err.str()};
}

// The numbers of one output line, as std::stod reads them.
std::vector<double> numbers(const std::string& line) {
  std::istringstream in(line);
  std::vector<double> values;
  std::string word;
  while (in >> word) values.push_back(std::stod(word));
  return values;
}

// Full precision, so that the command reads back exactly the double given.
std::string join(const std::vector<double>& values) {
  std::string text;
  for (const double x : values) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.17g", x);
    if (!text.empty()) text += ' ';
    text += buffer;
  }
  return text;
}

std::size_t count_lines(const std::string& text) {
  std::size_t lines = 0;
  for (const char c : text) lines += c == '\n' ? 1 : 0;
  return lines;
}

// (6.25) elementary rotation matrices, typed as in the book; axis 1..3.
Tensor elementary(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Tensor R;
  if (axis == 1) R << 1, 0, 0, 0, c, -s, 0, s, c;
  if (axis == 2) R << c, 0, s, 0, 1, 0, -s, 0, c;
  if (axis == 3) R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

std::vector<double> rows(const Tensor& Q) {
  return {Q(0, 0), Q(0, 1), Q(0, 2), Q(1, 0), Q(1, 1), Q(1, 2), Q(2, 0), Q(2, 1), Q(2, 2)};
}

Tensor from_rows(const std::vector<double>& v) {
  Tensor Q;
  Q << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
  return Q;
}

// §6.5.1 W3: euler:3-2-3 (0.2, −0.5, 0.1) → axis-angle, 33.3161° about (0.043135, ...).
TEST(CliRotation, ConvertEuler323ToAxisAngleW3) {
  const Outcome r = run("rotation convert --from euler:3-2-3 0.2 -0.5 0.1 --to axis-angle");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(count_lines(r.out), 1u);
  const std::vector<double> v = numbers(r.out);
  ASSERT_EQ(v.size(), 4u) << r.out;
  // The printed matrix differs from the exact 3-2-3 rotation by ≤ 5e-7, the book's digits by 5e-7.
  EXPECT_NEAR(v[0], 0.043135, 1e-6);
  EXPECT_NEAR(v[1], -0.861981, 1e-6);
  EXPECT_NEAR(v[2], 0.505103, 1e-6);
  EXPECT_NEAR(v[3] * 180 / kPi, 33.3161, 1e-4);
  // And exactly: (6.11)–(6.12) written out on R = Rz(0.2) Ry(−0.5) Rz(0.1), well conditioned here.
  const Tensor R = elementary(3, 0.2) * elementary(2, -0.5) * elementary(3, 0.1);
  const double angle = std::acos(0.5 * (R.trace() - 1.0));
  const Vec3 axis =
      -Vec3(R(1, 2) - R(2, 1), R(2, 0) - R(0, 2), R(0, 1) - R(1, 0)) / (2.0 * std::sin(angle));
  EXPECT_NEAR(v[3], angle, 1e-14);
  EXPECT_NEAR(v[0], axis.x(), 1e-14);
  EXPECT_NEAR(v[1], axis.y(), 1e-14);
  EXPECT_NEAR(v[2], axis.z(), 1e-14);
}

// --degrees: the W3 rotation typed in degrees gives the axis-angle pair with the angle in
// degrees, 33.3161°; Euler angles in degrees read back; other values are not angles.
TEST(CliRotation, Degrees) {
  const double d = 180 / kPi;
  const Outcome r = run("rotation convert --degrees --from euler:3-2-3 " +
                        join({0.2 * d, -0.5 * d, 0.1 * d}) + " --to axis-angle");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<double> v = numbers(r.out);
  ASSERT_EQ(v.size(), 4u) << r.out;
  EXPECT_NEAR(v[0], 0.043135, 1e-6);
  EXPECT_NEAR(v[3], 33.3161, 1e-4);
  const Outcome back =
      run("rotation convert --degrees --from axis-angle " + join(v) + " --to euler:3-2-3");
  const std::vector<double> angles = numbers(back.out);
  ASSERT_EQ(angles.size(), 3u) << back.out << back.err;
  // γ² ∈ [0, π] for a symmetric set: (0.2, −0.5, 0.1) is returned as (0.2 − π, 0.5, 0.1 − π)
  EXPECT_NEAR(angles[0], 0.2 * d - 180, 1e-10);
  EXPECT_NEAR(angles[1], 0.5 * d, 1e-10);
  EXPECT_NEAR(angles[2], 0.1 * d - 180, 1e-10);
  const Outcome quaternion =
      run("rotation convert --degrees --from axis-angle 0 0 1 90 --to quaternion");
  const std::vector<double> e = numbers(quaternion.out);
  ASSERT_EQ(e.size(), 4u);
  EXPECT_NEAR(e[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(e[3], std::sqrt(0.5), 1e-15);
  EXPECT_TRUE(run("rotation show --degrees --from axis-angle 0 0 1 90")
                  .out.find("euler angles (6.20), deg") != std::string::npos);
}

// Exercise 6.4(g), (6.36): matrix [[0,0,1],[1,0,0],[0,1,0]] → quaternion (½, ½, ½, ½).
TEST(CliRotation, ConvertMatrixToQuaternion) {
  const Outcome r = run("rotation convert --from matrix 0 0 1 1 0 0 0 1 0 --to quaternion");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<double> v = numbers(r.out);
  ASSERT_EQ(v.size(), 4u) << r.out;
  for (int n = 0; n < 4; ++n) EXPECT_NEAR(v[n], 0.5, 1e-15) << n;

  // (6.36) read backwards: e0 = ½ √(1 + tr Q), 4 e0 e = (Q32 − Q23, Q13 − Q31, Q21 − Q12), for
  // random Q with e0 ≥ 0.3 (well away from π).
  test::Random random;
  for (int n = 0; n < 5; ++n) {
    const Tensor Q = random.rotation();
    const double e0 = 0.5 * std::sqrt(1.0 + Q.trace());
    if (e0 < 0.3) continue;
    const Outcome q = run("rotation convert --from matrix " + join(rows(Q)) + " --to quaternion");
    ASSERT_EQ(q.status, 0) << q.err;
    const std::vector<double> w = numbers(q.out);
    ASSERT_EQ(w.size(), 4u) << q.out;
    EXPECT_NEAR(w[0], e0, 1e-14);
    EXPECT_NEAR(w[1], (Q(2, 1) - Q(1, 2)) / (4 * e0), 1e-14);
    EXPECT_NEAR(w[2], (Q(0, 2) - Q(2, 0)) / (4 * e0), 1e-14);
    EXPECT_NEAR(w[3], (Q(1, 0) - Q(0, 1)) / (4 * e0), 1e-14);
  }
}

// §6.8.2 (3-1-3, Rz(ψ) Rx(θ) Rz(φ)): the quaternion of known angles converts back to them.
TEST(CliRotation, ConvertQuaternionToEuler313) {
  const double psi = 0.7, theta = 1.2, phi = -2.0;
  const Tensor Q = elementary(3, psi) * elementary(1, theta) * elementary(3, phi);
  // e0 = ½ √(1 + tr Q) (not near zero here) and e from the skew part (6.36).
  const double e0 = 0.5 * std::sqrt(1.0 + Q.trace());
  const std::vector<double> quaternion = {e0, (Q(2, 1) - Q(1, 2)) / (4 * e0),
                                          (Q(0, 2) - Q(2, 0)) / (4 * e0),
                                          (Q(1, 0) - Q(0, 1)) / (4 * e0)};
  const Outcome r =
      run("rotation convert --from quaternion " + join(quaternion) + " --to euler:3-1-3");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<double> v = numbers(r.out);
  ASSERT_EQ(v.size(), 3u) << r.out;
  EXPECT_NEAR(v[0], psi, 1e-13);
  EXPECT_NEAR(v[1], theta, 1e-13);
  EXPECT_NEAR(v[2], phi, 1e-13);
}

// §6.5, §6.8, §6.9: matrix → KIND → matrix through printed numbers, to 1e-12, for every kind.
TEST(CliRotation, RoundTripEveryKind) {
#ifdef UNIDYN_SANITIZED
  // 96 conversions, each a process (24 s here): the rotation layer's tests run each kind under
  // the sanitizers
  GTEST_SKIP() << "checked in the plain build";
#endif
  std::vector<std::string> kinds = {"matrix", "axis-angle", "quaternion", "rodrigues"};
  for (const char* set : {"1-2-3", "1-3-2", "2-1-3", "2-3-1", "3-1-2", "3-2-1", "1-2-1", "1-3-1",
                          "2-1-2", "2-3-2", "3-1-3", "3-2-3"}) {
    kinds.push_back(std::string("euler:") + set);
  }
  test::Random random(3u);
  const Tensor Q = random.rotation();
  for (const std::string& kind : kinds) {
    const Outcome there = run("rotation convert --from matrix " + join(rows(Q)) + " --to " + kind);
    ASSERT_EQ(there.status, 0) << kind << ": " << there.err;
    EXPECT_EQ(there.err, "") << kind;
    EXPECT_EQ(count_lines(there.out), 1u) << kind;
    const std::vector<double> values = numbers(there.out);
    ASSERT_EQ(values.size(), Parametrisation::parse(kind).size()) << kind << ": " << there.out;
    // The printed numbers, in-process, are the rotation to 1e-12 ...
    EXPECT_LE(max_abs_diff(rotation_from(Parametrisation::parse(kind), values), Q), 1e-12) << kind;
    // ... and given back to the command verbatim, too.
    std::string printed = there.out;
    while (!printed.empty() && printed.back() == '\n') printed.pop_back();
    const Outcome back = run("rotation convert --from " + kind + " " + printed + " --to matrix");
    ASSERT_EQ(back.status, 0) << kind << ": " << back.err;
    const std::vector<double> m = numbers(back.out);
    ASSERT_EQ(m.size(), 9u) << back.out;
    EXPECT_LE(max_abs_diff(from_rows(m), Q), 1e-12) << kind;
  }
}

// Bad input (incl. the Rodrigues vector at π, §6.9): one line on stderr, exit status 2.
TEST(CliRotation, BadInputGivesOneLineAndStatus2) {
  const std::vector<std::string> cases = {
      // unknown kind
      "rotation convert --from quat 1 0 0 0 --to matrix",
      "rotation convert --from quaternion 1 0 0 0 --to Matrix",
      // wrong count
      "rotation convert --from quaternion 1 0 0 --to matrix",
      "rotation convert --from matrix 1 0 0 0 1 0 0 0 --to quaternion",
      // an Euler set with an axis twice in a row
      "rotation convert --from euler:1-1-2 0.1 0.2 0.3 --to matrix",
      "rotation convert --from matrix 1 0 0 0 1 0 0 0 1 --to euler:1-1-2",
      // not a rotation
      "rotation convert --from matrix 1 0 0 0 1 0 0 0 2 --to quaternion",
      "rotation convert --from matrix 1 0 0 0 1 0 0 0 -1 --to quaternion",
      "rotation convert --from quaternion 1 0 0 0.1 --to matrix",
      // not a number
      "rotation convert --from euler:3-1-3 0.1 abc 0.2 --to matrix",
      "rotation convert --from euler:3-1-3 0.1 0.2x 0.2 --to matrix",
      "rotation convert --from euler:3-1-3 0.1 nan 0.2 --to matrix",
      // missing --to
      "rotation convert --from euler:3-1-3 0.1 0.2 0.3",
      // the Rodrigues vector does not exist at angle π
      "rotation convert --from axis-angle 0 0 1 3.141592653589793 --to rodrigues",
      "rotation convert --from matrix 1 0 0 0 -1 0 0 0 -1 --to rodrigues",
  };
  for (const std::string& args : cases) {
    const Outcome r = run(args);
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_EQ(r.out, "") << args;
    EXPECT_EQ(count_lines(r.err), 1u) << args << "\nstderr: " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    if (!r.err.empty()) {
      EXPECT_EQ(r.err.back(), '\n') << args;
    }
  }
}

// §6.8.2: the 3-1-3 angles with θ = 0 are at gimbal lock, which `show` reports on the 3-1-3 line.
TEST(CliRotation, ShowReportsGimbalLock) {
  const Outcome r = run("rotation show --from euler:3-1-3 0.3 0 0.2");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::istringstream lines(r.out);
  std::string line;
  bool found = false;
  while (std::getline(lines, line)) {
    if (line.find("3-1-3:") == std::string::npos) continue;
    found = true;
    EXPECT_NE(line.find("GIMBAL LOCK"), std::string::npos) << line;
  }
  EXPECT_TRUE(found) << r.out;

  const Outcome away = run("rotation show --from euler:3-1-3 0.3 0.5 0.2");
  ASSERT_EQ(away.status, 0) << away.err;
  EXPECT_EQ(away.out.find("GIMBAL LOCK"), std::string::npos) << away.out;
}

}  // namespace
}  // namespace unidyn
