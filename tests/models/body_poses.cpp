// The poses along a run (numeric/poses.hpp), against the rotation layer: the heavy top's Euler
// parameters give the rotation tensor of its 3-1-3 angles (6.20), its centre is l e3, and the
// parameters keep a continuous sign; the double pendulum's particles are where its positions say.
// The constraint forces (numeric/constraint_forces.hpp) against Newton's law for the pendulum.
#include "unidyn/numeric/constraint_forces.hpp"
#include "unidyn/numeric/poses.hpp"

#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/rotation/euler_angles.hpp"

namespace unidyn {
namespace {

TEST(BodyPoses, HeavyTopsEulerParametersAndCentre) {
  const test::ModelRun run =
      test::run_model("heavy-top", {}, [](SimulationOptions& o) { o.t_end = 1; });
  ASSERT_TRUE(run.summary.ok);
  Poses poses(run.system);
  ASSERT_EQ(poses.columns(), (std::vector<std::string>{"top.x", "top.y", "top.z", "top.e0",
                                                       "top.e1", "top.e2", "top.e3"}));
  const double l = 0.05;
  const EulerSet set = *EulerSet::parse("3-1-3");
  std::vector<double> before;
  for (std::size_t r = 0; r < run.rows.size(); ++r) {
    const Eigen::Vector3d angles(run.at(r, "psi"), run.at(r, "theta"), run.at(r, "phi"));
    std::vector<double> pose;
    poses.append(run.at(r, "t"), angles, {1.0, 9.81, l, 0.004, 0.002}, pose);
    ASSERT_EQ(pose.size(), 7u);
    const EulerParameters e{pose[3], Vec3(pose[4], pose[5], pose[6])};
    EXPECT_NEAR(e.e0 * e.e0 + e.e.squaredNorm(), 1.0, 1e-14);
    const Tensor Q = rotation_tensor(set, angles);
    EXPECT_LT((rotation_tensor(e) - Q).cwiseAbs().maxCoeff(), 1e-14) << r;
    EXPECT_LT((Eigen::Vector3d(pose[0], pose[1], pose[2]) - l * Q.col(2)).norm(), 1e-15);
    // continuous: the spin turns the top 0.6 rad per row, e by about 0.3
    if (!before.empty()) {
      double jump = 0.0;
      for (std::size_t k = 3; k < 7; ++k) jump += std::pow(pose[k] - before[k], 2);
      EXPECT_LT(std::sqrt(jump), 0.5) << r;
    }
    before = pose;
  }
}

TEST(BodyPoses, DoublePendulumsParticles) {
  const test::ModelRun run =
      test::run_model("double-pendulum", {}, [](SimulationOptions& o) { o.t_end = 1; });
  Poses poses(run.system);
  ASSERT_EQ(poses.columns(),
            (std::vector<std::string>{"P1.x", "P1.y", "P1.z", "P2.x", "P2.y", "P2.z"}));
  for (std::size_t r = 0; r < run.rows.size(); r += 10) {
    const double a = run.at(r, "theta1"), b = run.at(r, "theta2");
    std::vector<double> pose;
    poses.append(run.at(r, "t"), Eigen::Vector2d(a, b), {1.0, 1.0, 1.0, 1.0, 9.81}, pose);
    EXPECT_NEAR(pose[0], std::sin(a), 1e-15);
    EXPECT_NEAR(pose[1], -std::cos(a), 1e-15);
    EXPECT_NEAR(pose[3], std::sin(a) + std::sin(b), 1e-15);
    EXPECT_NEAR(pose[4], -std::cos(a) - std::cos(b), 1e-15);
    EXPECT_EQ(pose[5], 0.0);
  }
}

// The rod's force on the bob, λ ∇Ψ from the run's multiplier, is what Newton's law asks of it:
// m a = −m g E3 + F_c with a · r̂ = −|v|²/L on the sphere, so F_c is radial with
// F_c · r̂ = −m |v|²/L + m g E3 · r̂ (m = 1, g = 9.81, L = 1).
TEST(BodyPoses, PendulumRodForceIsNewtons) {
  const test::ModelRun run = test::run_model("spherical-pendulum-cartesian", {},
                                             [](SimulationOptions& o) { o.t_end = 2; });
  ConstraintForces forces(run.system);
  ASSERT_EQ(forces.columns(), (std::vector<std::string>{"P.Fc.x", "P.Fc.y", "P.Fc.z"}));
  for (std::size_t r = 0; r < run.rows.size(); r += 7) {
    const Eigen::Vector3d x(run.at(r, "x"), run.at(r, "y"), run.at(r, "z")),
        v(run.at(r, "der(x)"), run.at(r, "der(y)"), run.at(r, "der(z)"));
    std::vector<double> F;
    forces.append(run.at(r, "t"), x, v, Eigen::VectorXd::Constant(1, run.at(r, "lambda(rod)")),
                  {1.0, 9.81, 1.0, 2.0, 0.0, 0.0, 2.5}, F);
    const Eigen::Vector3d Fc(F[0], F[1], F[2]), radial = x.normalized();
    EXPECT_NEAR(Fc.dot(radial), -v.squaredNorm() + 9.81 * radial.z(), 1e-8) << r;
    EXPECT_LT((Fc - Fc.dot(radial) * radial).norm(), 1e-10) << r;
  }
}

}  // namespace
}  // namespace unidyn
