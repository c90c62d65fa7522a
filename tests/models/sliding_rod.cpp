// Exercise 10.3: a cylinder sliding on a smooth plane with its third 3-2-3 angle held, ω·g³ = 0.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// (10.51): m ẍ1 = m ẍ2 = 0, λ2 θ̈ = 0, λ ψ̈ = 0, so from the model's start x1 = 0.5 t,
// x2 = −0.2 t, ψ = 0.3 + 0.7 t, θ = 1 + 0.3 t (and φ = 0); the plane pushes with F_c = m g E3 and
// the rate constraint's moment is M_c = μ g³ = −λ2 ψ̇ θ̇ sin θ g³ with the dual Euler basis vector
// g³ = (cos ψ E1 + sin ψ E2)/sin θ of the 3-2-3 set (⊥ g1 = E3 and g2 = e2', g³·e3 = 1).
TEST(SlidingRod, LinearInTimeWithTheBooksConstraintMoment) {
  const double m = 2.0, g = 9.81, R = 0.1, lam2 = m * R * R / 2;
  const test::ModelRun run = test::run_model("sliding-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), 0.5 * t, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "x2"), -0.2 * t, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "psi"), 0.3 + 0.7 * t, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "theta"), 1.0 + 0.3 * t, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "phi"), 0.0, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "Fc.x"), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "Fc.y"), 0.0, 1e-12);
    EXPECT_NEAR(run.at(i, "Fc.z"), m * g, 1e-12);
    const double psi = run.at(i, "psi"), theta = run.at(i, "theta");
    const double mu = -lam2 * run.at(i, "der(psi)") * run.at(i, "der(theta)") * std::sin(theta);
    EXPECT_NEAR(run.at(i, "Mc.x"), mu * std::cos(psi) / std::sin(theta), 1e-14) << t;
    EXPECT_NEAR(run.at(i, "Mc.y"), mu * std::sin(psi) / std::sin(theta), 1e-14) << t;
    EXPECT_NEAR(run.at(i, "Mc.z"), 0.0, 1e-14) << t;
  }
}

}  // namespace
}  // namespace unidyn
