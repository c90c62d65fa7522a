// `unidyn derive --method kane`: Kane's equations F_r + F*_r = 0 (book (10.16)), with the partial
// velocities, against the double pendulum's generalised active and inertia forces derived by hand:
//   F_1 = −(m1 + m2) g l1 sin θ1,  F_2 = −m2 g l2 sin θ2,
//   F*_1 = −[(m1 + m2) l1² θ1'' + m2 l1 l2 cos(θ1 − θ2) θ2'' + m2 l1 l2 sin(θ1 − θ2) θ2'²],
//   F*_2 = −[m2 l2² θ2'' + m2 l1 l2 cos(θ1 − θ2) θ1'' − m2 l1 l2 sin(θ1 − θ2) θ1'²]
// (v_P1 = l1 θ1' (cos θ1, sin θ1), v_P2 = v_P1 + l2 θ2' (cos θ2, sin θ2); F*_r = −Σ m a · ∂v/∂θr').
// The printed expressions are read back with GiNaC's parser and compared at random values.
#include <ginac/ginac.h>

#include <random>
#include <regex>

#include "cli/cli_support.hpp"

namespace unidyn::cli_test {
namespace {

// The string value of "key": "..." after position `from` in a JSON text.
std::string json_string(const std::string& json, const std::string& key, std::size_t& from) {
  const std::size_t at = json.find("\"" + key + "\": \"", from);
  EXPECT_NE(at, std::string::npos) << key;
  const std::size_t begin = at + key.size() + 5;
  from = json.find('"', begin);
  return json.substr(begin, from - begin);
}

TEST(KaneEquations, TheDoublePendulumsActiveAndInertiaForces) {
  const Outcome r = run("derive double-pendulum --method kane --format json");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_TRUE(contains(r.out, "\"method\": \"kane\"")) << r.out;
  EXPECT_TRUE(contains(r.out, "\"P2.velocity\": [\"l1*cos(theta1)\"")) << r.out;

  GiNaC::symtab names;
  for (const char* name : {"m1", "m2", "l1", "l2", "g", "theta1", "theta2", "theta1_d", "theta2_d",
                           "theta1_dd", "theta2_dd"}) {
    names[name] = GiNaC::symbol(name);
  }
  GiNaC::parser reader(names);
  const auto read = [&](std::string text) {
    text = std::regex_replace(text, std::regex("(\\w+)''"), "$1_dd");
    text = std::regex_replace(text, std::regex("(\\w+)'"), "$1_d");
    return reader(text);
  };
  const auto s = [&](const char* name) { return names[name]; };
  const GiNaC::ex m1 = s("m1"), m2 = s("m2"), l1 = s("l1"), l2 = s("l2"), g = s("g"),
                  t1 = s("theta1"), t2 = s("theta2"), d1 = s("theta1_d"), d2 = s("theta2_d"),
                  a1 = s("theta1_dd"), a2 = s("theta2_dd");
  const GiNaC::ex active[2] = {-(m1 + m2) * g * l1 * sin(t1), -m2 * g * l2 * sin(t2)};
  const GiNaC::ex inertia[2] = {-((m1 + m2) * l1 * l1 * a1 + m2 * l1 * l2 * cos(t1 - t2) * a2 +
                                  m2 * l1 * l2 * sin(t1 - t2) * d2 * d2),
                                -(m2 * l2 * l2 * a2 + m2 * l1 * l2 * cos(t1 - t2) * a1 -
                                  m2 * l1 * l2 * sin(t1 - t2) * d1 * d1)};

  std::size_t from = 0;
  std::mt19937 random(34);
  std::uniform_real_distribution<double> unit(-2.0, 2.0);
  for (int r_ = 0; r_ < 2; ++r_) {
    const GiNaC::ex F = read(json_string(r.out, "generalized_active_force", from));
    const GiNaC::ex Fstar = read(json_string(r.out, "generalized_inertia_force", from));
    for (int sample = 0; sample < 5; ++sample) {
      GiNaC::exmap at;
      for (const auto& [name, symbol] : names) at[symbol] = unit(random);
      const auto value = [&](const GiNaC::ex& e) {
        return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
      };
      EXPECT_NEAR(value(F), value(active[r_]), 1e-12) << F;
      EXPECT_NEAR(value(Fstar), value(inertia[r_]), 1e-12) << Fstar;
    }
  }

  // the text and LaTeX forms name the equations and list F, F* and F + F* = 0 per coordinate
  const Outcome text = run("derive double-pendulum --method kane");
  EXPECT_TRUE(contains(text.out, "Kane's equations (10.16): F_r + F*_r = 0")) << text.out;
  EXPECT_TRUE(contains(text.out,
                       "[theta2]  d(P2.velocity)/d(theta2') = [l2*cos(theta2), "
                       "l2*sin(theta2), 0]"))
      << text.out;
  EXPECT_TRUE(contains(text.out, "[theta1]  F + F* = 0")) << text.out;
  EXPECT_NE(text.out, run("derive double-pendulum").out);
  const Outcome latex = run("derive double-pendulum --method kane --format latex");
  EXPECT_TRUE(contains(latex.out, "F^*_{\\theta_{1}}")) << latex.out;
}

}  // namespace
}  // namespace unidyn::cli_test
