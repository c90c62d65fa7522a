// The MJCF test models (tests/formats/models/*.xml) read by unidyn and by MuJoCo 2.2.2 (its own
// format): M, f and q̈ at random states agree to 1e-10 relative (mujoco_oracle.hpp). These models
// have hinge and slide joints only, no damping, and no contact (no geom, or contacts disabled by
// <option><flag contact="disable"/>). A ball joint's velocities in MuJoCo are the angular
// velocity on the body frame, not Euler-parameter rates: its M and gravity forces are mapped.
#include "mujoco_oracle.hpp"

namespace unidyn {
namespace {

using mujoco_oracle::expect_agreement_with_mujoco;

// Two hinges about y in two bodies.
TEST(MjcfAgainstMujoco, AcrobotMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco(UNIDYN_EXAMPLES_DIR "/mjcf/acrobot.xml");
}

// A slide, then a hinge whose anchor is off the pole's frame.
TEST(MjcfAgainstMujoco, CartPoleMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("cart-pole.xml");
}

// Two joints in one body, composed in order about their anchors; a turned body (quat, euler).
TEST(MjcfAgainstMujoco, TwoJointsInOneBodyMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("two-joints-in-one-body.xml");
}

// MuJoCo's default angle unit, degrees, in euler and axisangle.
TEST(MjcfAgainstMujoco, DegreesMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("degrees.xml");
}

// Inertia derived from one primitive geom per body (sphere, box, cylinder, ellipsoid), as MuJoCo
// derives it: of density (default 1000) or mass. By the recursive algorithms alone: the
// derivation of its equations (exact π and densities) takes 14 s, 86 s under the sanitizers.
TEST(MjcfAgainstMujoco, GeomInertiaMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("geoms.xml", mujoco_oracle::Paths::recursive);
}

#ifdef UNIDYN_HAVE_MUJOCO

using engine_oracle::formats_model;
using engine_oracle::relative;
using mujoco_oracle::Mujoco;

// MuJoCo's ball velocity, the angular velocity on the body frame, of the Euler parameters' rates
// at a unit e: ω = 2 G(e) ė (the body-frame form of (6.36)'s kinematics).
Eigen::Matrix<double, 3, 4> body_rates(const Eigen::Vector4d& e) {
  Eigen::Matrix<double, 3, 4> G;
  G << -e[1], e[0], e[3], -e[2], -e[2], -e[3], e[0], e[1], -e[3], e[2], -e[1], e[0];
  return 2 * G;
}

// A ball joint then a hinge: with ω = 2 G ė (and the hinge's rate itself), T is the same, so
// unidyn's M = Gᵀ M_mujoco G, and at rest its forcing f = Gᵀ (−qfrc_bias) (virtual work of the
// gravity forces), at 20 random orientations and hinge angles.
TEST(MjcfAgainstMujoco, BallJointMassMatrixAndGravityForcesThroughTheRatesMap) {
  Mujoco mj(formats_model("ball-pendulum.xml"));
  const commands::LoadedModel loaded =
      commands::load_named_model(formats_model("ball-pendulum.xml"));
  const CompiledSystem compiled(loaded.system, lagrange_equations(loaded.system));
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(loaded.system, {}).parameters;
  ASSERT_EQ(mj.model->nq, 5);
  ASSERT_EQ(mj.model->nv, 4);
  ASSERT_EQ(loaded.system.coordinates().size(), 5u);
  test::Random random;
  double M_error = 0, f_error = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q(5);
    q.head<4>() = Eigen::Vector4d(random.uniform(-1, 1), random.uniform(-1, 1),
                                  random.uniform(-1, 1), random.uniform(-1, 1))
                      .normalized();
    q[4] = random.uniform(-2, 2);
    Eigen::Map<Eigen::VectorXd>(mj.data->qpos, 5) = q;
    Eigen::Map<Eigen::VectorXd>(mj.data->qvel, 4).setZero();
    mj_forward(mj.model.get(), mj.data.get());
    Eigen::Matrix<double, 4, 4, Eigen::RowMajor> M;
    mj_fullM(mj.model.get(), M.data(), mj.data->qM);
    const Eigen::Vector4d f = -Eigen::Map<const Eigen::Vector4d>(mj.data->qfrc_bias);
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(4, 5);
    G.topLeftCorner<3, 4>() = body_rates(q.head<4>());
    G(3, 4) = 1;
    compiled.mass_and_forcing(0, q, Eigen::VectorXd::Zero(5), parameters, data);
    M_error = std::max(M_error, relative(data.mass_matrix, G.transpose() * M * G));
    f_error = std::max(f_error, relative(data.forcing, G.transpose() * f));
  }
  EXPECT_LT(M_error, 1e-10);
  EXPECT_LT(f_error, 1e-10);
  std::printf("ball-pendulum.xml against MuJoCo %s: relative errors M %.3g, f at rest %.3g\n",
              mj_versionString(), M_error, f_error);
}

#endif

}  // namespace
}  // namespace unidyn
