// The model commands run as a user runs them (DESIGN.md, "Command line"): `models`, `derive`,
// `check` and `simulate`, with their output, their CSV and their exit status: 0 success, 1 the run
// failed (why, and the rows so far kept), 2 bad input (one line, and for a model file
// file:line:column).
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cli_support.hpp"

namespace unidyn {
namespace {

namespace fs = std::filesystem;

using namespace cli_test;

// A minimal JSON checker: true when `text` is one JSON value and nothing else.
class JsonChecker {
 public:
  explicit JsonChecker(const std::string& text) : s_(text) {}
  bool valid() {
    if (!value(0)) return false;
    space();
    return i_ == s_.size();
  }

 private:
  void space() {
    while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
  }
  bool eat(char c) {
    space();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }
  bool string() {
    if (!eat('"')) return false;
    while (i_ < s_.size() && s_[i_] != '"') {
      if (static_cast<unsigned char>(s_[i_]) < 0x20) return false;
      i_ += s_[i_] == '\\' ? 2 : 1;
    }
    return i_++ < s_.size();
  }
  bool value(int depth) {
    if (depth > 100) return false;
    space();
    if (i_ >= s_.size()) return false;
    if (s_[i_] == '"') return string();
    if (s_[i_] == '{' || s_[i_] == '[') {
      const bool object = s_[i_++] == '{';
      const char close = object ? '}' : ']';
      if (eat(close)) return true;
      do {
        if (object && (!string() || !eat(':'))) return false;
        if (!value(depth + 1)) return false;
      } while (eat(','));
      return eat(close);
    }
    const std::size_t start = i_;
    while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '-' ||
                              s_[i_] == '+' || s_[i_] == '.')) {
      ++i_;
    }
    return i_ > start;
  }

  const std::string& s_;
  std::size_t i_ = 0;
};

const std::string kPendulumHeader = "t,phi,theta,der(phi),der(theta),energy,x,y,z,tension,H3";

// A model whose run fails at t = 1: the force 1/(1 − t) on a free particle blows up there.
std::string blow_up_model() {
  const std::string path = temp_path("blow_up.yaml");
  write_file(path,
             "unidyn: 1\n"
             "name: Blow-up at t = 1\n"
             "parameters: {m: 1}\n"
             "coordinates: [x]\n"
             "particles:\n"
             "  P: {mass: m, position: [x, 0, 0]}\n"
             "forces:\n"
             "  - force: {at: P, value: \"[1/(1 - t), 0, 0]\"}\n"
             "simulate: {t_end: 2, output_step: 0.05}\n");
  return path;
}

// `models` lists every bundled model file with the name line it gives.
TEST(CliModels, ModelsListsEveryBundledModel) {
  const Outcome r = run("models");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::size_t files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(UNIDYN_MODELS_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    ++files;
    std::string title;
    for (const auto& line : lines_of(read_file(entry.path().string()))) {
      if (line.starts_with("name:")) {
        title = line.substr(line.find_first_not_of(' ', 5));
        break;
      }
    }
    EXPECT_FALSE(title.empty()) << entry.path();
    const std::string stem = entry.path().stem().string();
    const std::vector<std::string> listed = lines_starting(r.out, stem + " ");
    ASSERT_EQ(listed.size(), 1u) << stem << " in\n" << r.out;
    EXPECT_TRUE(listed[0].ends_with(" " + title)) << listed[0];
  }
  EXPECT_GE(files, 12u);
  EXPECT_EQ(lines_of(r.out).size(), files) << r.out;
}

// `models NAME` prints the file; an unknown name is bad input.
TEST(CliModels, ModelsPrintsOneModel) {
  const Outcome r = run("models spherical-pendulum");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::string file = read_file(std::string(UNIDYN_MODELS_DIR) + "/spherical-pendulum.yaml");
  ASSERT_FALSE(file.empty());
  ASSERT_TRUE(r.out.ends_with(file)) << r.out;
  const std::string first = lines_of(r.out).at(0);
  EXPECT_TRUE(first.starts_with("# ") && first.ends_with("spherical-pendulum.yaml")) << first;
  EXPECT_EQ(r.out.size(), first.size() + 1 + file.size());

  expect_bad_input(run("models no-such-model"), "models no-such-model");
}

// `derive` (text): one equation per coordinate, in its acceleration, and T and U.
TEST(CliModels, DeriveText) {
  const Outcome r = run("derive spherical-pendulum");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines_starting(r.out, "  [").size(), 2u) << r.out;  // one equation per coordinate
  EXPECT_TRUE(lines[0].starts_with("Spherical pendulum (spherical coordinates): Lagrange's"))
      << lines[0];
  const std::vector<std::string> T = lines_starting(r.out, "  T = ");
  const std::vector<std::string> U = lines_starting(r.out, "  U = ");
  ASSERT_EQ(T.size(), 1u);
  ASSERT_EQ(U.size(), 1u);
  for (const char* part : {"phi'^2", "theta'^2", "sin(phi)^2", "L^2", "1/2"}) {
    EXPECT_TRUE(contains(T[0], part)) << part << " in " << T[0];
  }
  for (const char* part : {"cos(phi)", "g", "L", "m"}) {
    EXPECT_TRUE(contains(U[0], part)) << part << " in " << U[0];
  }
  EXPECT_FALSE(contains(U[0], "theta")) << U[0];
  // the textbook form: m L² φ'' − m L² sin φ cos φ θ'² − m g L sin φ = 0 (φ from the upward
  // vertical) and m L² sin²φ θ'' + 2 m L² sin φ cos φ φ' θ' = 0
  EXPECT_EQ(lines_starting(r.out, "  [phi]  "),
            std::vector<std::string>{
                "  [phi]  L^2*m*phi'' - L^2*m*cos(phi)*sin(phi)*theta'^2 - L*g*m*sin(phi) = 0"});
  EXPECT_EQ(lines_starting(r.out, "  [theta]  "),
            std::vector<std::string>{"  [theta]  L^2*m*sin(phi)^2*theta'' + "
                                     "2*L^2*m*cos(phi)*sin(phi)*phi'*theta' = 0"});
  // the matrix form: [phi] m L² φ'' = m L² sin φ cos φ θ'² + m g L sin φ; [theta] m L² sin² φ θ''
  // = −2 ...
  const Outcome matrix = run("derive spherical-pendulum --form matrix");
  ASSERT_EQ(matrix.status, 0) << matrix.err;
  const std::vector<std::string> phi = lines_starting(matrix.out, "  [phi]  ");
  const std::vector<std::string> theta = lines_starting(matrix.out, "  [theta]  ");
  ASSERT_EQ(phi.size(), 1u) << matrix.out;
  ASSERT_EQ(theta.size(), 1u) << matrix.out;
  const std::string phi_lhs = phi[0].substr(0, phi[0].find(" = "));
  const std::string theta_lhs = theta[0].substr(0, theta[0].find(" = "));
  EXPECT_TRUE(contains(phi_lhs, "phi''") && !contains(phi_lhs, "theta''")) << phi[0];
  EXPECT_TRUE(contains(theta_lhs, "theta''") && !contains(theta_lhs, "phi''")) << theta[0];
  EXPECT_TRUE(contains(phi[0].substr(phi_lhs.size()), "g")) << phi[0];
  EXPECT_TRUE(contains(theta[0].substr(theta_lhs.size()), "-2*")) << theta[0];
  expect_bad_input(run("derive spherical-pendulum --form pretty"), "--form pretty");
}

// `derive --form zees`: the repeated subexpressions named z1, z2, … before the equations, which
// are then shorter than in the textbook form.
TEST(CliModels, DeriveZees) {
  const Outcome zees = run("derive hinged-bodies --form zees");
  const Outcome textbook = run("derive hinged-bodies");
  ASSERT_EQ(zees.status, 0) << zees.err;
  ASSERT_EQ(textbook.status, 0) << textbook.err;
  EXPECT_EQ(lines_starting(zees.out, "  z1 = ").size(), 1u) << zees.out;
  const auto equations_length = [](const std::string& out) {
    std::size_t length = 0;
    for (const std::string& line : lines_starting(out, "  [")) length += line.size();
    return length;
  };
  EXPECT_EQ(lines_starting(zees.out, "  [").size(), 7u);
  EXPECT_LT(equations_length(zees.out), equations_length(textbook.out));
}

// `derive --form zees` of models whose expressions GiNaC writes as −e with e inside (a power of a
// sum with its sign taken out): naming the subexpressions must look into e's own parts, or the
// descent never ends (these crashed on a stack overflow). Each names some z's and prints every
// equation.
TEST(CliModels, DeriveZeesWhereGinacWritesMinusEWithEInside) {
  for (const std::string model : {"foucault-pendulum", "top-spring", "spinning-egg"}) {
    const Outcome zees = run("derive " + model + " --form zees");
    ASSERT_EQ(zees.status, 0) << model << ": " << zees.err;
    EXPECT_FALSE(lines_starting(zees.out, "  z1 = ").empty()) << zees.out;
    EXPECT_EQ(lines_starting(zees.out, "  [").size(),
              lines_starting(run("derive " + model).out, "  [").size())
        << zees.out;
  }
}

// `derive --format latex`: the textbook form in an align environment, one labelled equation per
// coordinate (\ddot{\phi}, \dot{\theta}^{2}, \sin\phi as the book writes them), T and U not
// numbered; the matrix form in display math with an aligned block.
TEST(CliModels, DeriveLatex) {
  const Outcome r = run("derive spherical-pendulum --format latex");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_LT(r.out.find("\\begin{align}"), r.out.find("\\end{align}")) << r.out;
  for (const char* part : {"\\ddot{\\phi}", "\\ddot{\\theta}", "\\dot{\\theta}^{2}", "\\sin\\phi",
                           "\\label{eq:phi}", "\\label{eq:theta}", "& T = ", "& U = "}) {
    EXPECT_TRUE(contains(r.out, part)) << part << " in\n" << r.out;
  }
  std::size_t unnumbered = 0;
  for (std::size_t at = r.out.find("\\nonumber"); at != std::string::npos;
       at = r.out.find("\\nonumber", at + 1)) {
    ++unnumbered;
  }
  EXPECT_EQ(unnumbered, 2u) << r.out;  // T and U
  const Outcome matrix = run("derive spherical-pendulum --format latex --form matrix");
  ASSERT_EQ(matrix.status, 0) << matrix.err;
  EXPECT_LT(matrix.out.find("\\[\n\\begin{aligned}"), matrix.out.find("\\end{aligned}\n\\]"));
  // one row per coordinate and T, U: four "&="
  std::size_t rows = 0;
  for (std::size_t at = matrix.out.find("&="); at != std::string::npos;
       at = matrix.out.find("&=", at + 1)) {
    ++rows;
  }
  EXPECT_EQ(rows, 4u) << matrix.out;
}

// `derive --format json`: valid JSON with the mass matrix, 2 × 2, diagonal.
TEST(CliModels, DeriveJson) {
  const Outcome r = run("derive spherical-pendulum --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(JsonChecker(r.out).valid()) << r.out;
  EXPECT_FALSE(JsonChecker(r.out + "}").valid());  // the checker can say no
  EXPECT_TRUE(contains(r.out, "\"mass_matrix\": [[")) << r.out;
  EXPECT_TRUE(contains(r.out,
                       "{\"name\": \"phi\", \"rate\": \"phi_d\", \"acceleration\": "
                       "\"phi_dd\", \"initial\": 2, \"initial_rate\": 0}"))
      << r.out;
  EXPECT_TRUE(contains(r.out, "{\"name\": \"g\", \"value\": 9.81}")) << r.out;
  EXPECT_FALSE(contains(r.out, "'")) << r.out;  // no q' for SymPy
  EXPECT_TRUE(contains(r.out, "\"method\": \"lagrange\"")) << r.out;
  const std::size_t at = r.out.find("\"mass_matrix\"");
  const std::string matrix = r.out.substr(at, r.out.find("]]", at) - at);
  EXPECT_TRUE(contains(matrix, "[\"0\", ")) << matrix;
  EXPECT_TRUE(contains(matrix, ", \"0\"]")) << matrix;

  const Outcome newton =
      run("derive spherical-pendulum-cartesian --method newton-euler --format json");
  ASSERT_EQ(newton.status, 0) << newton.err;
  EXPECT_TRUE(JsonChecker(newton.out).valid()) << newton.out;
  EXPECT_TRUE(contains(newton.out, "\"method\": \"newton-euler\"")) << newton.out;
}

// JSON for bodies: Euler's laws per body, and the second form with its partial velocities.
TEST(CliModels, DeriveBodiesJson) {
  const Outcome newton = run("derive compound-pendulum --method newton-euler --format json");
  ASSERT_EQ(newton.status, 0) << newton.err;
  EXPECT_TRUE(JsonChecker(newton.out).valid()) << newton.out;
  EXPECT_TRUE(contains(newton.out, "\"bodies\": [")) << newton.out;
  EXPECT_TRUE(contains(newton.out, "\"momentum_rate\": [")) << newton.out;
  const Outcome second = run("derive heavy-top --method second-form --format json");
  ASSERT_EQ(second.status, 0) << second.err;
  EXPECT_TRUE(JsonChecker(second.out).valid()) << second.out;
  EXPECT_TRUE(contains(second.out, "\"top.omega\": [\"0\", \"0\", \"1\"]")) << second.out;
  const Outcome text = run("derive rate-gyroscope --method second-form");
  ASSERT_EQ(text.status, 0) << text.err;
  EXPECT_EQ(lines_starting(text.out, "  [alpha]  d(gimbal.omega)/d(alpha') = ").size(), 1u)
      << text.out;
  const Outcome bad = run("derive heavy-top --method hamilton");
  EXPECT_EQ(bad.status, 2);
  EXPECT_TRUE(contains(bad.err, "second-form")) << bad.err;
}

// `derive --method newton-euler`: m a = F + R for each component of each particle.
TEST(CliModels, DeriveNewtonEuler) {
  const Outcome r = run("derive spherical-pendulum --method newton-euler");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(contains(lines_of(r.out).at(0), "m a = F + R")) << r.out;
  for (const char* axis : {"E1", "E2", "E3"}) {
    const std::vector<std::string> line =
        lines_starting(r.out, std::string("  [P.") + axis + "]  ");
    ASSERT_EQ(line.size(), 1u) << axis << "\n" << r.out;
    EXPECT_TRUE(line[0].ends_with(std::string(" + R_P.") + axis)) << line[0];
    EXPECT_TRUE(contains(line[0], "phi''")) << line[0];
  }
  // gravity −m g E3 acts along E3 only
  EXPECT_TRUE(contains(lines_starting(r.out, "  [P.E3]")[0], "= -m*g + R_P.E3") ||
              contains(lines_starting(r.out, "  [P.E3]")[0], "= -g*m + R_P.E3"))
      << r.out;
  EXPECT_TRUE(contains(lines_starting(r.out, "  [P.E1]")[0], "= 0 + R_P.E1")) << r.out;
  EXPECT_EQ(lines_starting(r.out, "  [").size(), 3u) << r.out;
}

// derive: an unknown format or method is bad input.
TEST(CliModels, DeriveBadOptions) {
  for (const std::string args :
       {"derive spherical-pendulum --format xml", "derive spherical-pendulum --method hamilton",
        "derive", "derive no-such-model"}) {
    expect_bad_input(run(args), args);
  }
}

// `check`: Newton–Euler and Lagrange agree and the constraint holds.
TEST(CliModels, CheckPasses) {
  const Outcome r = run("check spherical-pendulum-cartesian");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_FALSE(lines.empty());
  EXPECT_EQ(lines.back(), "check passed");
  EXPECT_TRUE(contains(r.out, "  symbolic agreement: yes\n")) << r.out;
  EXPECT_EQ(lines_starting(r.out, "  [").size(), 3u) << r.out;  // x, y, z
  for (const auto& line : lines_starting(r.out, "  [")) {
    EXPECT_TRUE(line.ends_with("residual simplifies to 0")) << line;
  }
  EXPECT_TRUE(contains(r.out, "rank A = 1 of 1")) << r.out;
}

// `simulate -o FILE`: the contract's columns, a row every output_step up to t_end exactly, and a
// summary with the energy drift.
TEST(CliModels, SimulateWritesCsv) {
  const std::string csv_path = temp_path("pendulum.csv");
  const Outcome r = run("simulate spherical-pendulum -o '" + csv_path + "' --t-end 1");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  const std::string text = read_file(csv_path);
  std::remove(csv_path.c_str());
  const Csv csv = parse_csv(text);
  EXPECT_EQ(csv.header, kPendulumHeader);
  ASSERT_EQ(csv.rows.size(), 101u);
  EXPECT_EQ(csv.rows.back()[0], 1.0);
  EXPECT_TRUE(lines_of(text).back().starts_with("1,")) << lines_of(text).back();
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_NEAR(csv.rows[i][0], 0.01 * static_cast<double>(i), 1e-12) << i;
  }
  // the model's initial state, and its outputs
  EXPECT_EQ(csv.at(0, "t"), 0.0);
  EXPECT_EQ(csv.at(0, "phi"), 2.0);
  EXPECT_EQ(csv.at(0, "theta"), 0.0);
  EXPECT_EQ(csv.at(0, "der(phi)"), 0.0);
  EXPECT_EQ(csv.at(0, "der(theta)"), 2.5);
  EXPECT_NEAR(csv.at(0, "x"), std::sin(2.0), 1e-15);
  EXPECT_NEAR(csv.at(0, "z"), std::cos(2.0), 1e-15);
  // E = ½ m L² (φ'² + sin²φ θ'²) + m g L cos φ, constant; H3 = m L² sin²φ θ' constant; |r| = L
  const double E0 = 0.5 * 2.5 * 2.5 * std::sin(2.0) * std::sin(2.0) + 9.81 * std::cos(2.0);
  EXPECT_NEAR(csv.at(0, "energy"), E0, 1e-12);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_NEAR(csv.at(i, "energy"), E0, 1e-9) << i;
    EXPECT_NEAR(csv.at(i, "H3"), 2.5 * std::sin(2.0) * std::sin(2.0), 1e-9) << i;
    const double x = csv.at(i, "x"), y = csv.at(i, "y"), z = csv.at(i, "z");
    EXPECT_NEAR(x * x + y * y + z * z, 1.0, 1e-12) << i;
  }
  // the summary
  EXPECT_TRUE(
      contains(r.out, "simulated from t = 0 to 1 (dopri5), 101 rows written to " + csv_path + "\n"))
      << r.out;
  EXPECT_NEAR(number_after(r.out, "energy: initial "), E0, 1e-9);
  EXPECT_LT(number_after(r.out, "relative drift "), 1e-9) << r.out;
  EXPECT_TRUE(contains(r.out, "conserved H3: initial ")) << r.out;
}

// --poses: the top's centre and Euler parameters after the columns of the run, unit norm.
TEST(CliModels, SimulatePosesAddsBodyColumns) {
  const std::string csv_path = temp_path("top-poses.csv");
  const Outcome r = run("simulate heavy-top --poses -o '" + csv_path + "' --t-end 0.1");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const Csv csv = parse_csv(read_file(csv_path));
  std::remove(csv_path.c_str());
  const std::vector<std::string> tail(csv.columns.end() - 7, csv.columns.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"top.x", "top.y", "top.z", "top.e0", "top.e1", "top.e2",
                                            "top.e3"}));
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    const double e0 = csv.at(i, "top.e0"), e1 = csv.at(i, "top.e1"), e2 = csv.at(i, "top.e2"),
                 e3 = csv.at(i, "top.e3");
    EXPECT_NEAR(e0 * e0 + e1 * e1 + e2 * e2 + e3 * e3, 1.0, 1e-14) << i;
  }
  EXPECT_NEAR(csv.at(0, "top.e0"), std::cos(0.15), 1e-15);  // θ = 0.3 about E1
  EXPECT_NEAR(csv.at(0, "top.e1"), std::sin(0.15), 1e-15);
}

// The helix has two constraints: one lambda(<name>) column each; the constraints hold.
TEST(CliModels, SimulateHelixConstraintColumns) {
  const std::string csv_path = temp_path("helix.csv");
  const Outcome r = run("simulate helix -o '" + csv_path + "' --t-end 0.5");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const Csv csv = parse_csv(read_file(csv_path));
  std::remove(csv_path.c_str());
  // t, q, der(q), energy, one lambda per constraint, then the model's outputs (if any)
  const std::string columns =
      "t,theta,r,eta,der(theta),der(r),der(eta),energy,lambda(cylinder),lambda(helicoid)";
  EXPECT_TRUE(csv.header == columns || csv.header.starts_with(columns + ",")) << csv.header;
  ASSERT_EQ(csv.rows.size(), 51u);
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_NEAR(csv.at(i, "r"), 0.8, 1e-10) << i;
    EXPECT_NEAR(csv.at(i, "eta"), 0.0, 1e-10) << i;
    EXPECT_NE(csv.at(i, "lambda(helicoid)"), 0.0) << i;
    EXPECT_NE(csv.at(i, "lambda(cylinder)"), 0.0) << i;
  }
  EXPECT_TRUE(contains(r.out, "constraint residuals: max |Psi| ")) << r.out;
}

// --set overrides a parameter, a rate or a coordinate of the first row; an unknown name is bad
// input and writes nothing.
TEST(CliModels, SimulateSet) {
  const auto first_row = [](const std::string& set) {
    const Outcome r = run("simulate spherical-pendulum --t-end 0.02 " + set);
    EXPECT_EQ(r.status, 0) << set << "\n" << r.err;
    const Csv csv = parse_csv(r.out);
    EXPECT_EQ(csv.rows.size(), 3u) << set;
    return csv;
  };
  const Csv plain = first_row("");
  ASSERT_FALSE(plain.rows.empty());
  EXPECT_EQ(plain.at(0, "phi"), 2.0);
  EXPECT_EQ(plain.at(0, "der(phi)"), 0.0);

  const Csv phi0 = first_row("--set phi0=1.0");
  ASSERT_FALSE(phi0.rows.empty());
  EXPECT_EQ(phi0.at(0, "phi"), 1.0);
  EXPECT_NEAR(phi0.at(0, "z"), std::cos(1.0), 1e-15);
  EXPECT_EQ(phi0.at(0, "der(theta)"), 2.5);

  const Csv rate = first_row("--set 'der(phi)=0.5'");
  ASSERT_FALSE(rate.rows.empty());
  EXPECT_EQ(rate.at(0, "der(phi)"), 0.5);
  EXPECT_EQ(rate.at(0, "phi"), 2.0);

  const Csv both = first_row("--set theta=0.3 --set g=0");
  ASSERT_FALSE(both.rows.empty());
  EXPECT_EQ(both.at(0, "theta"), 0.3);
  // without gravity, the energy is the kinetic energy only
  EXPECT_NEAR(both.at(0, "energy"), 0.5 * 2.5 * 2.5 * std::sin(2.0) * std::sin(2.0), 1e-12);

  const std::string csv_path = temp_path("not_written.csv");
  for (const std::string set : {"--set nosuch=1", "--set phi0=abc", "--set phi0", "--set =1",
                                "--set 'der(nosuch)=1'", "--set g=nan", "--set phi=inf"}) {
    const std::string args = "simulate spherical-pendulum -o '" + csv_path + "' " + set;
    const Outcome r = run(args);
    expect_bad_input(r, args);
    EXPECT_FALSE(fs::exists(csv_path)) << args;
  }
  const Outcome r = run("simulate spherical-pendulum --set nosuch=1");
  EXPECT_TRUE(contains(r.err, "nosuch")) << r.err;
}

// A model that does not exist, or options that make no sense: bad input.
TEST(CliModels, SimulateBadInput) {
  const std::string missing = temp_path("missing.yaml");
  const Outcome r = run("simulate '" + missing + "'");
  expect_bad_input(r, "simulate " + missing);
  EXPECT_TRUE(r.err.starts_with(missing + ": ")) << r.err;

  const std::string csv_path = temp_path("bad.csv");
  for (const std::string option : {"--method euler", "--t-end -1", "--t-end 0", "--output-step 0",
                                   "--output-step -0.1", "--rtol -1e-8", "--rtol 0", "--t-end abc",
                                   "--t-end inf", "--t-end nan", "--no-such-option"}) {
    const std::string args = "simulate spherical-pendulum -o '" + csv_path + "' " + option;
    expect_bad_input(run(args), args);
    EXPECT_FALSE(fs::exists(csv_path)) << args;
  }
  // a CSV that cannot be written
  const std::string args = "simulate spherical-pendulum -o '" + missing + "/no/such/dir.csv'";
  expect_bad_input(run(args), args);
}

// A model with a mistake: status 2 and one line that starts with file:line:column; nothing in the
// file is executed.
TEST(CliModels, ModelErrorNamesFileLineColumn) {
  const std::string path = temp_path("broken.yaml");
  const std::string sentinel = temp_path("executed");
  write_file(path,
             "unidyn: 1\n"
             "parameters: {m: 1}\n"
             "coordinates: [x]\n"
             "particles:\n"
             "  P: {mass: m, position: [x, 0, 0]}\n"
             "  Q: {mass: \"m*(1 + nosuch)\", position: [x, 1, 0]}\n");
  for (const std::string command : {"simulate", "derive", "check"}) {
    const Outcome r = run(command + " '" + path + "'");
    expect_bad_input(r, command);
    EXPECT_TRUE(r.err.starts_with(path + ":6:21: ")) << r.err;
    EXPECT_TRUE(contains(r.err, "'nosuch'")) << r.err;
  }
  write_file(path,
             "unidyn: 1\n"
             "coordinates: [x]\n"
             "particles:\n"
             "  P: {mass: \"$(touch " +
                 sentinel + ")\", position: [x, 0, 0]}\n");
  const Outcome r = run("simulate '" + path + "'");
  expect_bad_input(r, "simulate $(touch)");
  EXPECT_TRUE(r.err.starts_with(path + ":4:14: ")) << r.err;
  EXPECT_FALSE(fs::exists(sentinel));
  std::remove(path.c_str());
}

// A run that fails: status 1, why, and every row computed before the failure kept.
TEST(CliModels, FailedRunKeepsRows) {
  const std::string model = blow_up_model();
  const std::string csv_path = temp_path("blow_up.csv");
  const Outcome r = run("simulate '" + model + "' -o '" + csv_path + "'");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_TRUE(contains(r.out, "Blow-up at t = 1: FAILED from t = 0 to 2")) << r.out;
  const std::vector<std::string> why = lines_starting(r.out, "  stopped at t = ");
  ASSERT_EQ(why.size(), 1u) << r.out;
  const double t_failure = number_after(why[0], "stopped at t = ");
  EXPECT_NEAR(t_failure, 1.0, 1e-6) << why[0];
  const Csv csv = parse_csv(read_file(csv_path));
  std::remove(csv_path.c_str());
  EXPECT_EQ(csv.header, "t,x,der(x)");
  ASSERT_GE(csv.rows.size(), 2u);
  EXPECT_EQ(csv.rows.size(), 20u);  // t = 0, 0.05, ..., 0.95
  EXPECT_TRUE(contains(r.out, ", 20 rows written to ")) << r.out;
  for (std::size_t i = 0; i < csv.rows.size(); ++i) {
    EXPECT_NEAR(csv.at(i, "t"), 0.05 * static_cast<double>(i), 1e-12);
    // x' = −log(1 − t), x = (1 − t) log(1 − t) + t
    const double t = csv.at(i, "t");
    EXPECT_NEAR(csv.at(i, "der(x)"), -std::log(1 - t), 1e-6) << t;
    EXPECT_NEAR(csv.at(i, "x"), (1 - t) * std::log(1 - t) + t, 1e-6) << t;
  }
  EXPECT_LT(csv.rows.back()[0], t_failure);

  // the same with the CSV on standard output: the summary goes to standard error
  const Outcome piped = run("simulate '" + model + "'");
  EXPECT_EQ(piped.status, 1);
  EXPECT_EQ(parse_csv(piped.out).rows.size(), 20u);
  EXPECT_TRUE(contains(piped.err, "FAILED")) << piped.err;
  EXPECT_TRUE(contains(piped.err, "stopped at t = ")) << piped.err;
  std::remove(model.c_str());
}

// A run that cannot even start (a singular mass matrix at R = 0): status 1, the header kept.
TEST(CliModels, RunFailingAtTheStart) {
  const std::string model = temp_path("origin.yaml");
  write_file(model,
             "unidyn: 1\n"
             "name: Free particle at the origin\n"
             "parameters: {m: 2}\n"
             "coordinates: [R, phi, theta]\n"
             "particles:\n"
             "  P: {mass: m, position: \"R*[sin(phi)*cos(theta), sin(phi)*sin(theta), "
             "cos(phi)]\"}\n"
             "initial: {R: 0, phi: 1.2, der(R): 1}\n"
             "simulate: {t_end: 1, output_step: 0.1}\n");
  const std::string csv_path = temp_path("origin.csv");
  const Outcome r = run("simulate '" + model + "' -o '" + csv_path + "'");
  EXPECT_EQ(r.status, 1) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "FAILED")) << r.out;
  EXPECT_TRUE(contains(r.out, "stopped at t = 0: ")) << r.out;
  EXPECT_TRUE(contains(r.out, "mass matrix")) << r.out;
  EXPECT_EQ(read_file(csv_path), "t,R,phi,theta,der(R),der(phi),der(theta),energy\n");
  std::remove(csv_path.c_str());
  std::remove(model.c_str());
}

// Without -o the CSV goes to standard output and the summary to standard error.
TEST(CliModels, CsvToStandardOutput) {
  const Outcome r = run("simulate spherical-pendulum --t-end 0.1");
  ASSERT_EQ(r.status, 0) << r.err;
  const Csv csv = parse_csv(r.out);
  EXPECT_EQ(csv.header, kPendulumHeader);
  EXPECT_EQ(csv.rows.size(), 11u);
  EXPECT_TRUE(contains(r.err, "simulated from t = 0 to 0.1 (dopri5), 11 rows\n")) << r.err;
  EXPECT_TRUE(contains(r.err, "relative drift")) << r.err;
  EXPECT_FALSE(contains(r.err, "written to")) << r.err;
}

// --method rk4 gives the same motion as dopri5 to its accuracy; --output-step sets the rows.
TEST(CliModels, SimulateRk4) {
  const Outcome rk4 = run("simulate spherical-pendulum --t-end 0.5 --method rk4");
  ASSERT_EQ(rk4.status, 0) << rk4.err;
  EXPECT_TRUE(contains(rk4.err, "(rk4), 51 rows")) << rk4.err;
  const Outcome dopri5 = run("simulate spherical-pendulum --t-end 0.5 --output-step 0.05");
  ASSERT_EQ(dopri5.status, 0) << dopri5.err;
  const Csv a = parse_csv(rk4.out), b = parse_csv(dopri5.out);
  ASSERT_EQ(a.rows.size(), 51u);
  ASSERT_EQ(b.rows.size(), 11u);
  EXPECT_EQ(b.rows.back()[0], 0.5);
  for (const char* column : {"phi", "theta", "der(phi)", "der(theta)"}) {
    EXPECT_NEAR(a.at(50, column), b.at(10, column), 1e-6) << column;
    EXPECT_NEAR(a.at(25, column), b.at(5, column), 1e-6) << column;
  }
  EXPECT_NE(a.at(50, "phi"), a.at(0, "phi"));
}

// --method dop853: the eighth-order pair follows dopri5's motion; both at rtol 1e-10.
TEST(CliModels, SimulateDop853) {
  const Outcome dop853 = run("simulate heavy-top --t-end 2 --output-step 0.1 --method dop853");
  ASSERT_EQ(dop853.status, 0) << dop853.err;
  EXPECT_TRUE(contains(dop853.err, "(dop853), 21 rows")) << dop853.err;
  const Outcome dopri5 = run("simulate heavy-top --t-end 2 --output-step 0.1");
  ASSERT_EQ(dopri5.status, 0) << dopri5.err;
  const Csv a = parse_csv(dop853.out), b = parse_csv(dopri5.out);
  ASSERT_EQ(a.rows.size(), 21u);
  ASSERT_EQ(b.rows.size(), 21u);
  for (std::size_t row = 1; row < 21; ++row) {
    for (std::size_t column = 1; column < a.rows[row].size(); ++column) {
      EXPECT_NEAR(a.rows[row][column], b.rows[row][column], 1e-7) << row << ", " << column;
    }
  }
}

}  // namespace
}  // namespace unidyn
