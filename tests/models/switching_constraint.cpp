// The constraint x ẏ = 0 switching branches (book §2.10, Fig. 2.10b): models/switching-constraint
// .yaml, ẏ = 0 off while a wall at x = 0 holds the particle. Going from y = y0 to another line
// takes two velocity jumps — the wall's I_c1 = −m ẋ⁻ E1 and the constraint's I_c2 = −m ẏ⁻ E2 —
// and between them each phase has a closed form under P1 = −p + k t, P2 constant.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/io/equation_report.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

TEST(SwitchingConstraint, TwoVelocityJumpsJoinTheBranches) {
  const test::ModelRun run = test::run_model("switching-constraint");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1.0, p = 2.0, k = 1.0, P2 = 0.5, x0 = 1.0, y0 = 0.3, v0 = -1.0;
  // phase 1 (ẏ = 0): x = x0 + v0 t + (−p t²/2 + k t³/6)/m reaches the wall at t_a (Newton)
  const auto x1 = [&](double t) { return x0 + v0 * t + (-p * t * t / 2 + k * t * t * t / 6) / m; };
  const auto v1 = [&](double t) { return v0 + (-p * t + k * t * t / 2) / m; };
  double ta = 0.5;
  for (int i = 0; i < 50; ++i) ta -= x1(ta) / v1(ta);
  // phase 2 (x = 0 while P1 < 0): y = y0 + P2 (t − t_a)²/(2m); the wall lets go at t1 = p/k
  const double t1 = p / k, vy = P2 * (t1 - ta) / m, y1 = y0 + P2 * (t1 - ta) * (t1 - ta) / (2 * m);
  ASSERT_EQ(run.summary.phases.size(), 3u);
  EXPECT_NEAR(run.summary.phases[1].t, ta, 1e-12);
  // "contact 'wall' made (approach rate ẋ⁻, impulse I_c1); 'rail' switches off"
  const std::string made = run.summary.phases[1].what;
  const std::string rate = "contact 'wall' made (approach rate ";
  ASSERT_EQ(made.substr(0, rate.size()), rate);
  EXPECT_NEAR(std::stod(made.substr(rate.size())), v1(ta), 1e-10);
  const std::size_t impulse = made.find(", impulse ");
  ASSERT_NE(impulse, std::string::npos);
  EXPECT_NEAR(std::stod(made.substr(impulse + 10)), -m * v1(ta), 1e-10) << "I_c1 = −m ẋ⁻";
  EXPECT_TRUE(made.ends_with("); 'rail' switches off")) << made;
  EXPECT_NEAR(run.summary.phases[2].t, t1, 1e-12);
  const std::string lost = run.summary.phases[2].what;
  const std::string prefix =
      "contact 'wall' lost (its force reached 0); 'rail' switches on: impulse ";
  ASSERT_EQ(lost.substr(0, prefix.size()), prefix);
  EXPECT_NEAR(std::stod(lost.substr(prefix.size())), -m * vy, 1e-10) << "I_c2 = −m ẏ⁻";
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), x = run.at(i, "x"), y = run.at(i, "y");
    if (t < ta - 1e-9) {
      EXPECT_NEAR(x, x1(t), 1e-10) << t;
      EXPECT_NEAR(y, y0, 1e-12) << t;
    } else if (t > ta + 1e-9 && t < t1 - 1e-9) {
      EXPECT_NEAR(x, 0, 1e-12) << t;
      EXPECT_NEAR(y, y0 + P2 * (t - ta) * (t - ta) / (2 * m), 1e-10) << t;
      EXPECT_NEAR(run.at(i, "lambda(wall)"), p - k * t, 1e-10) << t;
    } else if (t > t1 + 1e-9) {
      // phase 3 (ẏ = 0 again): y = y1, x = k (t − t1)³/(6m)
      EXPECT_NEAR(y, y1, 1e-10) << t;
      EXPECT_NEAR(x, k * std::pow(t - t1, 3) / (6 * m), 1e-10) << t;
      EXPECT_NEAR(run.at(i, "der(y)"), 0, 1e-12) << t;
    }
  }
  EXPECT_GT(y1 - y0, 0.4) << "from y = y0 to another line";
}

// off_while: is for a bilateral velocity constraint and names a unilateral one; derive says it.
TEST(SwitchingConstraint, OffWhileNamesAUnilateralContact) {
  const auto model = [](const std::string& constraints) {
    return "unidyn: 1\ncoordinates: [x, y]\nparticles:\n  P: {mass: 1, position: [x, y, 0]}\n"
           "constraints:\n" +
           constraints;
  };
  const System ok = parse_model(model("  - {name: wall, position: x, unilateral: true}\n"
                                      "  - {name: rail, velocity: der(y), off_while: wall}\n"),
                                "ok.yaml");
  // `unidyn derive` says so
  EXPECT_EQ(constraint_kind_text(ok.constraints[0]), "position, unilateral");
  EXPECT_EQ(constraint_kind_text(ok.constraints[1]), "velocity, off while 'wall' holds");
  EXPECT_THROW(parse_model(model("  - {name: wall, position: x}\n"
                                 "  - {name: rail, velocity: der(y), off_while: wall}\n"),
                           "bilateral.yaml"),
               ModelError);
  EXPECT_THROW(
      parse_model(model("  - {name: rail, velocity: der(y), off_while: door}\n"), "missing.yaml"),
      ModelError);
  EXPECT_THROW(parse_model(model("  - {name: wall, position: x, unilateral: true}\n"
                                 "  - {name: rail, position: y, off_while: wall}\n"),
                           "position.yaml"),
               ModelError);
}

}  // namespace
}  // namespace unidyn
