// Eigenvalues along a parameter and the boundaries of stability (analysis/parameter_sweep.hpp):
// the benchmark bicycle's weave and capsize speeds (Meijaard et al. 2007, Table 2).
#include "unidyn/analysis/parameter_sweep.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/bicycle_benchmark.hpp"
#include "support/linearized_model.hpp"

namespace unidyn {
namespace {

TEST(ParameterSweep, BicycleWeaveAndCapsizeSpeeds) {
  const System system = load_model(test::model_path("bicycle"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const auto given =
      parse_given_values(system, {"der(thR)=v/rR", "der(phi)=0", "der(delta)=0", "der(psi)=0"});
  const ParameterSweep sweep = sweep_modes(system, compiled, given, {}, "v", 0, 10, 11);
  ASSERT_EQ(sweep.points.size(), 11u);
  EXPECT_EQ(sweep.points[3].value, 3.0);
  for (const SweepPoint& p : sweep.points) {
    EXPECT_TRUE(p.failure.empty()) << p.failure;
    EXPECT_EQ(p.zeros, 1u) << "v = " << p.value;  // the speed's own mode
  }
  ASSERT_EQ(sweep.boundaries.size(), 2u);
  EXPECT_NEAR(sweep.boundaries[0].value, test::kWeaveSpeed, 1e-10);
  EXPECT_TRUE(sweep.boundaries[0].becomes_stable);
  EXPECT_NEAR(sweep.boundaries[1].value, test::kCapsizeSpeed, 1e-10);
  EXPECT_FALSE(sweep.boundaries[1].becomes_stable);
  // self-stable in between, at 5 m/s
  EXPECT_LT(sweep.points[5].growth, 0.0);
  EXPECT_GT(sweep.points[4].growth, 0.0);
}

// Sweeping a value of the operating point rather than a parameter: the spin that keeps a thin disk
// rolling upright, Ω² > m g R I / (I3 (I3 + m R²)) = g/(3R) (I = m R²/4, I3 = m R²/2), and the spin
// that keeps a top standing (§9.7), C² ω² > 4 A_O m g l with A_O = A + m l² about the fixed point.
// Four eigenvalues meet at 0 at the disk's boundary, which limits it to about 1e-11.
TEST(ParameterSweep, CriticalSpinsOfTheRollingDiskAndTheSleepingTop) {
  const auto boundaries = [](const std::string& model, const std::vector<std::string>& at,
                             const std::string& name, double to) {
    const System system = load_model(test::model_path(model));
    const CompiledSystem compiled(system, lagrange_equations(system));
    return sweep_modes(system, compiled, parse_given_values(system, at), {}, name, 0, to, 11)
        .boundaries;
  };
  const auto disk = boundaries(
      "rolling-disk", {"theta=pi/2", "der(phi)=1", "der(psi)=0", "der(theta)=0"}, "der(phi)", 10);
  ASSERT_EQ(disk.size(), 1u);
  EXPECT_NEAR(disk[0].value, std::sqrt(9.81 / (3 * 0.15)), 1e-9);
  EXPECT_TRUE(disk[0].becomes_stable);
  const auto top = boundaries("sleeping-top", {"der(gamma)=spin"}, "der(gamma)", 100);
  ASSERT_EQ(top.size(), 1u);
  const double A_O = 0.004 + 1.0 * 0.05 * 0.05;
  EXPECT_NEAR(top[0].value, 2 * std::sqrt(A_O * 1.0 * 9.81 * 0.05) / 0.002, 1e-9);
  EXPECT_TRUE(top[0].becomes_stable);
}

TEST(ParameterSweep, BadSweepsRefused) {
  const System system = load_model(test::model_path("double-pendulum"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const auto given = parse_given_values(system, {"theta1=0", "theta2=0"});
  EXPECT_THROW(sweep_modes(system, compiled, given, {}, "nope", 0, 1, 3), std::invalid_argument);
  EXPECT_THROW(sweep_modes(system, compiled, given, {}, "g", 0, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
