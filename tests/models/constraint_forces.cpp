// Constraint forces as vectors (§2.6, §3.8, §4.4): each constraint's λ ∂Ψ/∂r_P, and the resultant
// R = m a − F on a particle, agree with each other and with the book's closed forms.
#include "unidyn/kinematics/constraint_gradient.hpp"

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

// §3.8: on the helix F_c = (mgαθ/(1+α²) − mRθ̇²) e_r + mg/(1+α²) (E3 − α(θ e_r + e_θ)), and the
// two constraints' forces add up to R = m a − F
TEST(ConstraintForces, HelixBookClosedForm) {
  const test::ModelRun run = test::run_model("helix");
  ASSERT_TRUE(run.summary.ok);
  const double m = 1.5, g = 9.81, R = 0.8, alpha = 0.3;
  for (std::size_t i = 0; i < run.rows.size(); i += 7) {
    const double th = run.at(i, "theta"), w = run.at(i, "der(theta)");
    const Vec3 e_r(std::cos(th), std::sin(th), 0), e_t(-std::sin(th), std::cos(th), 0);
    const Vec3 Fc = (m * g * alpha * th / (1 + alpha * alpha) - m * R * w * w) * e_r +
                    m * g / (1 + alpha * alpha) * (Vec3(0, 0, 1) - alpha * (th * e_r + e_t));
    const Vec3 from_lambda(run.at(i, "Fc_x"), run.at(i, "Fc_y"), run.at(i, "Fc_z"));
    const Vec3 resultant(run.at(i, "R_x"), run.at(i, "R_y"), run.at(i, "R_z"));
    const double scale = 1 + Fc.norm();
    EXPECT_LT((from_lambda - Fc).norm(), 1e-9 * scale) << "t = " << run.at(i, "t");
    EXPECT_LT((resultant - Fc).norm(), 1e-9 * scale) << "t = " << run.at(i, "t");
  }
}

// The rod of the Cartesian spherical pendulum: λ ∂Ψ/∂r = 2λ r equals m a − F, and it is radial
TEST(ConstraintForces, RodForceIsTheResultant) {
  const test::ModelRun run = test::run_model("spherical-pendulum-cartesian", {},
                                             [](SimulationOptions& o) { o.t_end = 3; });
  ASSERT_TRUE(run.summary.ok);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const Vec3 r(run.at(i, "x"), run.at(i, "y"), run.at(i, "z"));
    const Vec3 rod(run.at(i, "rod_x"), run.at(i, "rod_y"), run.at(i, "rod_z"));
    const Vec3 resultant(run.at(i, "R_x"), run.at(i, "R_y"), run.at(i, "R_z"));
    EXPECT_LT((rod - 2 * run.at(i, "lambda(rod)") * r).norm(), 1e-12 * (1 + rod.norm()));
    EXPECT_LT((rod - resultant).norm(), 1e-8 * (1 + rod.norm()));
    EXPECT_LT(rod.cross(r).norm(), 1e-12 * (1 + rod.norm()));
  }
}

// ∂Ψ/∂r_P needs the positions to determine the coordinates: refused for the double pendulum
// (two coordinates, two particles)
TEST(ConstraintForces, GradientNeedsThreeCoordinatesPerParticle) {
  const System s = load_model(test::model_path("double-pendulum"));
  EXPECT_THROW(constraint_gradient(s, {1, 0}), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
