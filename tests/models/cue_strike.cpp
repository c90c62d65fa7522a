// Applied impulses (book §9.8, (11.15)): a billiard ball struck by a cue, the centre of percussion.
#include <cmath>
#include <fstream>
#include <sstream>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

constexpr double m = 0.17, g = 9.81, R = 0.0286, mu_d = 0.2, I = 0.5, t_hit = 0.1;

// At rest until the strike at t = 0.1; then v̄ = I/m, ω2 = I h/J = 5 I h/(2 m R²) (11.15), the
// contact slipping at (I/m)(1 − 5h/(2R)). At h = 2R/5 it does not slip: the ball rolls at once
// and keeps v̄ = I/m; struck at its centre (h = 0) it slides, slip v̄ − R ω2 falling at
// (7/2) μ_d g, and rolls from T = 2 I/(7 m μ_d g) after the strike at 5/7 of I/m.
TEST(CueStrike, CentreOfPercussionRollsAtOnce) {
  for (const double h : {2 * R / 5, 0.0}) {
    const test::ModelRun run = test::run_model("cue-strike", {{"h", h}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const auto& phases = run.summary.phases;
    ASSERT_GE(phases.size(), 3u);
    EXPECT_EQ(phases[0].what, "contact 'table' sticks");
    EXPECT_NEAR(phases[1].t, t_hit, 1e-12);
    EXPECT_TRUE(phases[1].what.starts_with("impulse 1 applied")) << phases[1].what;
    const bool percussion = h > 0;
    EXPECT_EQ(phases[2].what, percussion ? "contact 'table' sticks" : "'table' slides");
    const double T = t_hit + 2 * I / (7 * m * mu_d * g);
    if (!percussion) {
      ASSERT_EQ(phases.size(), 4u);
      EXPECT_EQ(phases[3].what, "contact 'table' sticks");
      EXPECT_NEAR(phases[3].t, T, 1e-10);
    } else {
      EXPECT_EQ(phases.size(), 3u);
    }
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t"), v = run.at(i, "der(x1)");
      if (t < t_hit) {
        EXPECT_EQ(v, 0.0) << t;
      } else if (percussion) {
        EXPECT_NEAR(v, I / m, 1e-10) << t;
        EXPECT_NEAR(run.at(i, "w2"), 5 * I * h / (2 * m * R * R), 1e-8) << t;
        EXPECT_NEAR(run.at(i, "slip"), 0.0, 1e-10) << t;
      } else if (t < T) {
        EXPECT_NEAR(v, I / m - mu_d * g * (t - t_hit), 1e-9) << t;
        EXPECT_NEAR(run.at(i, "slip"), I / m - 3.5 * mu_d * g * (t - t_hit), 1e-9) << t;
      } else {
        EXPECT_NEAR(v, 5.0 / 7.0 * I / m, 1e-9) << t;
      }
    }
  }
}

// An impulse at the start is a change of the initial rates: refused; and the model language's
// errors name the place.
TEST(CueStrike, BadImpulsesRefused) {
  std::ifstream file(test::model_path("cue-strike"));
  std::stringstream text;
  text << file.rdbuf();
  std::string at_start = text.str();
  at_start.replace(at_start.find("time: 0.1"), 9, "time: 0");
  EXPECT_THROW(test::run_system(parse_model(at_start, "at-start.yaml")), std::invalid_argument);
  std::string both = text.str();
  both.replace(both.find("on: ball, point"), 15, "at: ball, on: ball, point");
  EXPECT_THROW(parse_model(both, "both.yaml"), ModelError);
  std::string moving = text.str();
  moving.replace(moving.find("time: 0.1"), 9, "time: x1");
  EXPECT_THROW(parse_model(moving, "moving.yaml"), ModelError);
}

}  // namespace
}  // namespace unidyn
