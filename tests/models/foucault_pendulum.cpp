// Foucault's pendulum (named in book §1.2 as the reason an Earth-fixed frame is not inertial):
// models/foucault-pendulum.yaml, a pendulum hanging from a point of a turning planet, simulated in
// the inertial frame. Its swing plane — the azimuth of each turning point, fitted by least
// squares over the run — turns at Ω sin λ for a small swing, clockwise seen from above in the
// northern hemisphere, the other way in the southern one, and not at all on the equator.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The least-squares rate of the swing plane's azimuth (from north towards east): the direction of
// the chord from each end of a swing (least relative speed) to the next, continued across ±π/2
// (a plane, not a ray). Chords need no centre: the swing is centred on the plumb line.
double swing_plane_rate(const test::ModelRun& run) {
  std::vector<double> t, azimuth;
  double xn = NAN, xe = NAN;
  for (std::size_t i = 1; i + 1 < run.rows.size(); ++i) {
    const double v = run.at(i, "speed");
    if (!(v < run.at(i - 1, "speed") && v <= run.at(i + 1, "speed"))) continue;
    if (!std::isnan(xn)) {
      double a = std::atan2(run.at(i, "xe") - xe, run.at(i, "xn") - xn);
      if (!azimuth.empty()) {
        while (a - azimuth.back() > std::numbers::pi / 2) a -= std::numbers::pi;
        while (a - azimuth.back() < -std::numbers::pi / 2) a += std::numbers::pi;
      }
      t.push_back(run.at(i, "t"));
      azimuth.push_back(a);
    }
    xn = run.at(i, "xn");
    xe = run.at(i, "xe");
  }
  EXPECT_GT(t.size(), 30u);
  double mt = 0, ma = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    mt += t[k] / double(t.size());
    ma += azimuth[k] / double(t.size());
  }
  double sxy = 0, sxx = 0;
  for (std::size_t k = 0; k < t.size(); ++k) {
    sxy += (t[k] - mt) * (azimuth[k] - ma);
    sxx += (t[k] - mt) * (t[k] - mt);
  }
  return sxy / sxx;
}

TEST(FoucaultPendulum, SwingPlaneTurnsAtOmegaSinLatitude) {
  const double Omega = 0.05;
  for (const double latitude : {std::numbers::pi / 3, -std::numbers::pi / 4, 0.0}) {
    const test::ModelRun run = test::run_model("foucault-pendulum", {{"lat", latitude}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const double rate = swing_plane_rate(run), expected = Omega * std::sin(latitude);
    // (measured: −0.02 % for this 2 cm swing of a 1 m pendulum; wider swings turn slower, −0.3 %
    // at 10 cm, and a plumb line tilted by a larger Ω² R faster, +0.6 % at R = 100 m)
    EXPECT_NEAR(rate, expected, 1e-3 * Omega) << "latitude " << latitude;
  }
}

}  // namespace
}  // namespace unidyn
