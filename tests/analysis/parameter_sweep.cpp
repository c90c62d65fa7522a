// Eigenvalues along a parameter and the boundaries of stability (analysis/parameter_sweep.hpp):
// the benchmark bicycle's weave and capsize speeds (Meijaard et al. 2007, Table 2).
#include "unidyn/analysis/parameter_sweep.hpp"

#include <gtest/gtest.h>

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

TEST(ParameterSweep, BadSweepsRefused) {
  const System system = load_model(test::model_path("double-pendulum"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const auto given = parse_given_values(system, {"theta1=0", "theta2=0"});
  EXPECT_THROW(sweep_modes(system, compiled, given, {}, "nope", 0, 1, 3), std::invalid_argument);
  EXPECT_THROW(sweep_modes(system, compiled, given, {}, "g", 0, 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
