// The tippe top (book Ex. 9.13, Ex. 8.4): models/tippe-top.yaml, a sphere whose centre of mass
// lies l below its centre, spun on a table with the friction −(μ_k + μ_v |v_P|) |N| v_P/|v_P|.
// Against Jellett's integral H · π_P (conserved sliding or rolling), the normal force of (a),
// the condition 1 − l/R < C/A < 1 + l/R for it to turn over (Cohen 1977; Or 1994), and — rolling
// — Routh's integral (9.35) with the book's misprint corrected.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

using test::ModelRun;

constexpr double m = 0.015, g = 9.81, R = 0.02, l = 0.006, A = 2.4e-6;

// The largest relative change of a conserved quantity over the run.
double relative_drift(const ModelRun& run, const std::string& name) {
  for (const auto& d : run.summary.conserved_drift) {
    if (d.name == name) return d.max_change / std::abs(d.initial);
  }
  ADD_FAILURE() << "no conserved quantity " << name;
  return NAN;
}

// C/A = 0.8 (with l/R = 0.3): spun at 180 rad/s, tilted 0.1 rad, it turns over — e3 · E3 from
// 0.995 to below −0.5, its centre of mass rising towards R + l — while H · π_P stays put, the
// energy only falls, and the normal force is (a)'s N = m (g + l θ̈ sin θ + l θ̇² cos θ) = m (g + ẍ3)
// (ẍ3 by central differences of rows 0.5 ms apart).
TEST(TippeTop, TurnsOverKeepingJellettsIntegral) {
  // (its start completed as `unidyn simulate` does: x3, its rate and the centre's velocity)
  const ModelRun run = test::run_model(
      "tippe-top", {},
      [](SimulationOptions& o) {
        o.t_end = 4;
        o.output_step = 0.0005;
      },
      true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(relative_drift(run, "jellett"), 1e-8);
  EXPECT_NEAR(run.at(0, "cos_theta"), std::cos(0.1), 1e-12);
  EXPECT_LT(run.rows.back()[run.index("cos_theta")], -0.5);
  EXPECT_GT(run.rows.back()[run.index("x3")], R + 0.5 * l);
  const ModelRun grid = run.on_grid(0.0005);
  double worst = 0;
  for (std::size_t i = 1; i + 1 < grid.rows.size(); ++i) {
    EXPECT_LE(grid.at(i + 1, "energy"), grid.at(i, "energy") + 1e-13) << grid.at(i, "t");
    const double h = grid.at(i + 1, "t") - grid.at(i, "t");
    if (std::abs(grid.at(i, "t") - grid.at(i - 1, "t") - h) > 1e-9) continue;  // an event between
    const double x3ddot = (grid.at(i + 1, "der(x3)") - grid.at(i - 1, "der(x3)")) / (2 * h);
    worst = std::max(worst, std::abs(grid.at(i, "lambda(table)") - m * (g + x3ddot)) / (m * g));
  }
  EXPECT_LT(worst, 1e-3) << "N against m (g + x3'') by differences 0.0005 s apart";
}

// With C/A = 1.4 > 1 + l/R the spinning upright top is stable: it stays up.
TEST(TippeTop, StaysUprightWhenCOverAExceedsOnePlusLOverR) {
  const ModelRun run = test::run_model(
      "tippe-top", {{"C", 1.4 * A}}, [](SimulationOptions& o) { o.t_end = 4; }, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(relative_drift(run, "jellett"), 1e-8);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_GT(run.at(i, "cos_theta"), std::cos(0.1) - 1e-6) << run.at(i, "t");
  }
}

// Rolling (the friction replaced by rolling without slip), energy, Jellett's integral and Routh's
// I1 = ω3² (λ_a λ_t + m λ_t ((π_P·e1)² + (π_P·e2)²) + m λ_a (π_P·e3)²) are conserved; (9.35) as
// printed, with λ_a and λ_t the other way round in the m-terms, is not.
TEST(TippeTop, RollingKeepsRouthsIntegralWithTheMisprintCorrected) {
  std::ifstream file(test::model_path("tippe-top"));
  std::stringstream text;
  text << file.rdbuf();
  std::string model = text.str();
  const std::string friction =
      "    friction: {on: top, at: top.center + l*top.e3 - R*E3, dynamic: mu_k + "
      "mu_v*slip_speed}\n";
  const std::size_t at = model.find(friction);
  ASSERT_NE(at, std::string::npos);
  const std::string pi = "(l*top.e3 - R*E3)";
  const std::string w3 = "dot(top.omega, top.e3)^2";
  const auto along = [&](const std::string& e) { return "dot(" + pi + ", top." + e + ")^2"; };
  model.replace(at, friction.size(),
                "  - {name: roll, rolling: {body: top, at: top.center + l*top.e3 - R*E3, normal: "
                "[0, 0, 1]}}\n");
  model += "  routh: " + w3 + "*(C*A + m*A*(" + along("e1") + " + " + along("e2") + ") + m*C*" +
           along("e3") + ")\n";
  model += "  routh_printed: " + w3 + "*(C*A + m*C*(" + along("e1") + " + " + along("e2") +
           ") + m*A*" + along("e3") + ")\n";
  // tilted 0.5 rad and spun at 60 rad/s it nutates
  const ModelRun run = test::run_system(
      parse_model(model, "rolling-tippe-top.yaml"), {{"tilt", 0.5}, {"spin", 60}},
      [](SimulationOptions& o) {
        o.t_end = 2;
        o.rtol = 1e-12;
      },
      true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-9);
  EXPECT_LT(relative_drift(run, "jellett"), 1e-8);
  EXPECT_LT(relative_drift(run, "routh"), 1e-8);
  EXPECT_GT(relative_drift(run, "routh_printed"), 1e-4);
  // the top must move for this to mean anything: it nutates
  double lowest = 1, highest = -1;
  for (const double c : run.column("cos_theta")) {
    lowest = std::min(lowest, c);
    highest = std::max(highest, c);
  }
  EXPECT_GT(highest - lowest, 1e-3);
}

}  // namespace
}  // namespace unidyn
