// Modes and the stability verdict (analysis/modes.hpp) against closed forms: the double pendulum's
// frequencies, Fig. 9.1's rotations about principal axes, the bead on the hoop at its bifurcation.
#include "unidyn/analysis/modes.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/linearized_model.hpp"

namespace unidyn {
namespace {

using test::LinearizedModel;

// The double pendulum with m1 = m2, l1 = l2 = l hanging down: ω² = (g/l)(2 ∓ √2), the slow mode
// in phase (θ2/θ1 = √2), the fast one in opposition (−√2); upside down, unstable.
TEST(Modes, DoublePendulumFrequenciesAndShapes) {
  const double g = 9.81, l = 1.3;
  const LinearizedModel down("double-pendulum", {"theta1=0", "theta2=0"}, {{"l1", l}, {"l2", l}});
  const ModeAnalysis modes = analyse_modes(down.linearization);
  ASSERT_EQ(modes.modes.size(), 2u);
  const double slow = std::sqrt(g / l * (2 - std::sqrt(2.0))),
               fast = std::sqrt(g / l * (2 + std::sqrt(2.0)));
  EXPECT_NEAR(modes.modes[0].damped_frequency, slow, 1e-12);
  EXPECT_NEAR(modes.modes[1].damped_frequency, fast, 1e-12);
  EXPECT_NEAR(modes.modes[0].natural_frequency, slow, 1e-12);
  EXPECT_NEAR(modes.modes[0].damping_ratio, 0.0, 1e-12);
  // shapes scaled so that the largest is 1: θ2 = 1, θ1 = ±1/√2
  EXPECT_NEAR(std::abs(modes.modes[0].shape[0] - 1 / std::sqrt(2.0)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(modes.modes[1].shape[0] + 1 / std::sqrt(2.0)), 0.0, 1e-12);
  EXPECT_EQ(modes.verdict, Stability::linearly_stable) << modes.reason;

  const LinearizedModel up("double-pendulum", {"theta1=pi", "theta2=pi"});
  EXPECT_EQ(analyse_modes(up.linearization).verdict, Stability::unstable);
}

// Fig. 9.1: steady rotation ω about e3 of a torque-free body (3-2-1 Euler angles, ψ ignorable):
// δ'' = −ω² (λ3 − λ1)(λ3 − λ2)/(λ1 λ2) δ: stable about the major and the minor axes, unstable about
// the intermediate one; with λ1 = λ3 (a transverse axis of an axisymmetric body) the linear motion
// drifts, and the verdict is left to the nonlinear terms.
TEST(Modes, RotationAboutPrincipalAxes) {
  const double w = 5;
  const auto rotation = [&](double l1, double l2, double l3) {
    const LinearizedModel body("torque-free-body", {"der(psi)=5"},
                               {{"l1", l1}, {"l2", l2}, {"l3", l3}});
    EXPECT_EQ(body.linearization.ignorable, (std::vector<std::string>{"psi"}));
    return analyse_modes(body.linearization);
  };
  const auto wobble = [&](double l1, double l2, double l3) {
    return w * std::sqrt(std::abs((l3 - l1) * (l3 - l2) / (l1 * l2)));
  };
  const auto has_frequency = [](const ModeAnalysis& m, double frequency) {
    for (const Mode& mode : m.modes) {
      if (std::abs(mode.damped_frequency - frequency) < 1e-10) return true;
    }
    return false;
  };
  const ModeAnalysis major = rotation(2, 4, 5), minor = rotation(4, 5, 2);
  EXPECT_EQ(major.verdict, Stability::linearly_stable) << major.reason;
  EXPECT_TRUE(has_frequency(major, wobble(2, 4, 5)));
  EXPECT_EQ(minor.verdict, Stability::linearly_stable) << minor.reason;
  EXPECT_TRUE(has_frequency(minor, wobble(4, 5, 2)));
  const ModeAnalysis intermediate = rotation(2, 5, 4);
  EXPECT_EQ(intermediate.verdict, Stability::unstable);
  ASSERT_FALSE(intermediate.modes.empty());
  EXPECT_NEAR(intermediate.modes[0].eigenvalue.real(), wobble(2, 5, 4), 1e-10);
  EXPECT_EQ(rotation(4, 2, 4).verdict, Stability::inconclusive);
}

// The bead on the hoop at Ω² = g/R0 exactly (the pitchfork): at the bottom δφ'' = 0 δφ, a double
// zero eigenvalue with one eigenvector, and φ is not dropped as ignorable though its column of A is
// 0 there (it is not at a point nearby). On either side: stable below, unstable above.
TEST(Modes, RotatingHoopAtItsBifurcation) {
  const double critical = std::sqrt(9.81 / 0.5);
  const LinearizedModel at("rotating-hoop", {"phi=pi"}, {{"Omega", critical}});
  EXPECT_TRUE(at.linearization.ignorable.empty());
  EXPECT_EQ(analyse_modes(at.linearization).verdict, Stability::inconclusive);
  const LinearizedModel below("rotating-hoop", {"phi=pi"}, {{"Omega", 0.9 * critical}});
  EXPECT_EQ(analyse_modes(below.linearization).verdict, Stability::linearly_stable);
  const LinearizedModel above("rotating-hoop", {"phi=pi"}, {{"Omega", 1.1 * critical}});
  EXPECT_EQ(analyse_modes(above.linearization).verdict, Stability::unstable);
}

// The thin disk rolling upright at spin Ω: the lean oscillates at ω² = ((I3 + m R²) I3 Ω²/I − m g
// R) / (I + m R²), I = m R²/4, I3 = m R²/2; the top spinning upright at ω precesses at (C ω ± √(C²
// ω² − 4 A_O m g l)) / (2 A_O), A_O = A + m l².
TEST(Modes, RollingDiskAndSleepingTopFrequencies) {
  const auto frequencies = [](const std::string& model, const std::vector<std::string>& at) {
    std::vector<double> out;
    for (const Mode& m : analyse_modes(LinearizedModel(model, at).linearization).modes) {
      if (m.damped_frequency > 0) out.push_back(m.damped_frequency);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const double m = 1, g = 9.81, R = 0.15, W = 10, I = m * R * R / 4, I3 = m * R * R / 2;
  const auto disk =
      frequencies("rolling-disk", {"theta=pi/2", "der(phi)=10", "der(psi)=0", "der(theta)=0"});
  ASSERT_EQ(disk.size(), 1u);
  EXPECT_NEAR(disk[0], std::sqrt(((I3 + m * R * R) * I3 * W * W / I - m * g * R) / (I + m * R * R)),
              1e-10);
  const double A_O = 0.004 + 0.05 * 0.05, C = 0.002, w = 60,
               root = std::sqrt(C * C * w * w - 4 * A_O * g * 0.05);
  const auto top = frequencies("sleeping-top", {"der(gamma)=spin"});
  ASSERT_EQ(top.size(), 2u);
  EXPECT_NEAR(top[0], (C * w - root) / (2 * A_O), 1e-10);
  EXPECT_NEAR(top[1], (C * w + root) / (2 * A_O), 1e-10);
}

// The bicycle at 4.6 m/s rights itself: every mode decays but the one of neighbouring speeds.
TEST(Modes, BicycleSelfStableAtFourPointSix) {
  const LinearizedModel bike("bicycle",
                             {"der(thR)=v/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"});
  const ModeAnalysis modes = analyse_modes(bike.linearization);
  EXPECT_EQ(modes.verdict, Stability::linearly_stable) << modes.reason;
  int zeros = 0;
  for (const Mode& m : modes.modes) {
    if (m.natural_frequency == 0.0 || std::abs(m.eigenvalue) < 1e-9) {
      ++zeros;
      EXPECT_TRUE(m.of_rates);  // the rates change, no coordinate: the speed
    } else {
      EXPECT_LT(m.eigenvalue.real(), 0.0);
    }
  }
  EXPECT_EQ(zeros, 1);
  const LinearizedModel slow("bicycle",
                             {"der(thR)=3/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"});
  EXPECT_EQ(analyse_modes(slow.linearization).verdict, Stability::unstable);  // weave grows
}

}  // namespace
}  // namespace unidyn
