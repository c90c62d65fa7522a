// The MJCF test models (tests/formats/models/*.xml) read by unidyn and by MuJoCo 2.2.2 (its own
// format): M, f and q̈ at random states agree to 1e-10 relative (mujoco_oracle.hpp). These models
// have hinge and slide joints only, no damping, and no contact (no geom, or contacts disabled by
// <option><flag contact="disable"/>). A ball or free joint's velocities in MuJoCo are the angular
// velocity on the body frame (and the origin's velocity), not Euler-parameter rates: its M,
// gravity forces and accelerations are mapped.
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

// Damping in the slide (a slide damper) and in the hinge (a torsion damper): MuJoCo's passive
// forces −b q̇.
TEST(MjcfAgainstMujoco, DampedCartPoleMassMatrixForcesAndAccelerations) {
  expect_agreement_with_mujoco("damped-cart-pole.xml");
}

// Two joints in one body, composed in order about their anchors; a turned body (quat, euler).
TEST(MjcfAgainstMujoco, TwoJointsInOneBodyMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("two-joints-in-one-body.xml");
}

// <default> classes (top, nested, childclass, class=) for joint axes and geoms' types and
// densities, read as MuJoCo reads them.
TEST(MjcfAgainstMujoco, DefaultClassesMassMatrixBiasAndAccelerations) {
  expect_agreement_with_mujoco("defaults.xml");
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

// MuJoCo's velocities at a state as unidyn's q̇, joint by joint: a hinge's or slide's rate is
// its q̇; a free joint's linear velocity (on the ground's basis) is ḋ; a ball's or free joint's
// angular velocity ω on the body frame gives ė = ½ e ⊗ (0, ω) (the inverse of ω = 2 G(e) ė at
// a unit e, with e · ė = 0).
Eigen::VectorXd coordinate_rates(const mjModel& m, const Eigen::VectorXd& qpos,
                                 const Eigen::VectorXd& qvel) {
  Eigen::VectorXd qdot(m.nq);
  for (int j = 0; j < m.njnt; ++j) {
    int a = m.jnt_qposadr[j], v = m.jnt_dofadr[j];
    if (m.jnt_type[j] == mjJNT_HINGE || m.jnt_type[j] == mjJNT_SLIDE) {
      qdot[a] = qvel[v];
      continue;
    }
    if (m.jnt_type[j] == mjJNT_FREE) {
      qdot.segment<3>(a) = qvel.segment<3>(v);
      a += 3, v += 3;
    }
    const Eigen::Vector4d e = qpos.segment<4>(a);
    qdot.segment<4>(a) = body_rates(e).transpose() * qvel.segment<3>(v) / 4;
  }
  return qdot;
}

// unidyn's q̈ as MuJoCo's qacc: ω̇ = 2 G(e) ë (G(ė) ė = 0), the rest as they are.
Eigen::VectorXd velocity_rates(const mjModel& m, const Eigen::VectorXd& qpos,
                               const Eigen::VectorXd& qddot) {
  Eigen::VectorXd qacc(m.nv);
  for (int j = 0; j < m.njnt; ++j) {
    int a = m.jnt_qposadr[j], v = m.jnt_dofadr[j];
    if (m.jnt_type[j] == mjJNT_HINGE || m.jnt_type[j] == mjJNT_SLIDE) {
      qacc[v] = qddot[a];
      continue;
    }
    if (m.jnt_type[j] == mjJNT_FREE) {
      qacc.segment<3>(v) = qddot.segment<3>(a);
      a += 3, v += 3;
    }
    qacc.segment<3>(v) = body_rates(qpos.segment<4>(a)) * qddot.segment<4>(a);
  }
  return qacc;
}

// A random state of MuJoCo's: hinges within ±2 rad, positions within ±1 m, orientations uniform
// on SO(3), velocities within ±2.
void random_mujoco_state(const mjModel& m, test::Random& random, Eigen::VectorXd& qpos,
                         Eigen::VectorXd& qvel) {
  qpos.resize(m.nq);
  qvel.resize(m.nv);
  for (int i = 0; i < m.nv; ++i) qvel[i] = random.uniform(-2, 2);
  for (int j = 0; j < m.njnt; ++j) {
    int a = m.jnt_qposadr[j];
    if (m.jnt_type[j] == mjJNT_HINGE || m.jnt_type[j] == mjJNT_SLIDE) {
      qpos[a] = random.uniform(-2, 2);
      continue;
    }
    if (m.jnt_type[j] == mjJNT_FREE) {
      for (int k = 0; k < 3; ++k) qpos[a + k] = random.uniform(-1, 1);
      a += 3;
    }
    qpos.segment<4>(a) = Eigen::Vector4d(random.uniform(-1, 1), random.uniform(-1, 1),
                                         random.uniform(-1, 1), random.uniform(-1, 1))
                             .normalized();
  }
}

// The recursive algorithms on a tree with ball and free joints (the articulated-body algorithm
// over the links' twists, tree/euler_parameter_joint.hpp) against MuJoCo's qacc at 20 random
// states, through the velocity map; the unit norms' multipliers are 0 and their second
// derivatives e · ë + ė · ė vanish.
void expect_euler_parameter_tree_agrees(const std::string& file) {
  Mujoco mj(formats_model(file));
  const mjModel& m = *mj.model;
  const commands::LoadedModel loaded = commands::load_named_model(formats_model(file));
  CompileOptions options;
  options.recursive_from_coordinates = 0;
  const CompiledSystem compiled(loaded.system, options);
  ASSERT_TRUE(compiled.recursive()) << compiled.why_not_recursive();
  ASSERT_EQ(loaded.system.coordinates().size(), static_cast<std::size_t>(m.nq));
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(loaded.system, {}).parameters;
  const Tape recorded = engine_oracle::recorded_tape(loaded.system, parameters);
  test::Random random;
  double qacc_error = 0, lambda_max = 0, unit_error = 0, recorded_error = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd qpos, qvel;
    random_mujoco_state(m, random, qpos, qvel);
    Eigen::Map<Eigen::VectorXd>(mj.data->qpos, m.nq) = qpos;
    Eigen::Map<Eigen::VectorXd>(mj.data->qvel, m.nv) = qvel;
    mj_forward(&m, mj.data.get());
    const Eigen::VectorXd qacc = Eigen::Map<const Eigen::VectorXd>(mj.data->qacc, m.nv);
    const Eigen::VectorXd qdot = coordinate_rates(m, qpos, qvel);
    Eigen::VectorXd qddot, lambda;
    compiled.solve(0, qpos, qdot, parameters, qddot, lambda, data);
    qacc_error = std::max(qacc_error, relative(velocity_rates(m, qpos, qddot), qacc));
    const Eigen::VectorXd recorded_qddot =
        engine_oracle::recorded_accelerations(recorded, parameters, qpos, qdot);
    recorded_error =
        std::max(recorded_error, relative(velocity_rates(m, qpos, recorded_qddot), qacc));
    lambda_max = std::max(lambda_max, lambda.cwiseAbs().maxCoeff());
    for (int j = 0; j < m.njnt; ++j) {
      if (m.jnt_type[j] != mjJNT_BALL && m.jnt_type[j] != mjJNT_FREE) continue;
      const int a = m.jnt_qposadr[j] + (m.jnt_type[j] == mjJNT_FREE ? 3 : 0);
      unit_error = std::max(unit_error, std::abs(qpos.segment<4>(a).dot(qddot.segment<4>(a)) +
                                                 qdot.segment<4>(a).squaredNorm()));
    }
  }
  EXPECT_LT(qacc_error, 1e-10);
  EXPECT_LT(recorded_error, 1e-10);
  EXPECT_EQ(lambda_max, 0.0);
  EXPECT_LT(unit_error, 1e-13);
  test::record("qddot_error", qacc_error);
  std::printf(
      "%s against MuJoCo %s by the articulated-body algorithm: relative error of qacc %.3g "
      "(recorded, %zu instructions: %.3g); |e.e'' + e'.e'| <= %.3g\n",
      file.c_str(), mj_versionString(), qacc_error, recorded.instruction_count(), recorded_error,
      unit_error);
}

TEST(MjcfAgainstMujoco, BallJointAccelerationsByTheRecursiveAlgorithm) {
  expect_euler_parameter_tree_agrees("ball-pendulum.xml");
}

// A torso on a free joint and four three-hinge legs.
TEST(MjcfAgainstMujoco, FloatingQuadrupedAccelerationsByTheRecursiveAlgorithm) {
  expect_euler_parameter_tree_agrees("floating-quadruped.xml");
}

// A humanoid-sized floating tree: 36 coordinates, 35 velocities, several hinges in one body (its
// bodies' ω by the tree: System::make_angular_velocities).
TEST(MjcfAgainstMujoco, FloatingHumanoidAccelerationsByTheRecursiveAlgorithm) {
  expect_euler_parameter_tree_agrees("humanoid.xml");
}

// The whole run — simulate's dopri5 at rtol 1e-10 over the recursive algorithms, the unit norm
// kept by projection — against MuJoCo's own RK4 at a step of 1e-4 s, from the file's pose with
// every velocity moving, over 0.5 s: every coordinate agrees to 1e-7 (RK4's error at that step is
// ~1e-12; a wrong q̈ anywhere drifts far more).
TEST(MjcfAgainstMujoco, FloatingQuadrupedRunAgainstMujocosRk4) {
  Mujoco mj(formats_model("floating-quadruped.xml"));
  mjModel& m = *mj.model;
  const commands::LoadedModel loaded =
      commands::load_named_model(formats_model("floating-quadruped.xml"));
  const CompiledSystem compiled(loaded.system);
  ASSERT_TRUE(compiled.recursive()) << compiled.why_not_recursive();
  SimulationStart start = initial_state(loaded.system, {});
  const Eigen::VectorXd qpos0 = Eigen::Map<const Eigen::VectorXd>(m.qpos0, m.nq);
  ASSERT_LT((start.q - qpos0).norm(), 1e-15);
  test::Random random;
  Eigen::VectorXd qvel(m.nv);
  for (int i = 0; i < m.nv; ++i) qvel[i] = random.uniform(-1, 1);
  start.qdot = coordinate_rates(m, qpos0, qvel);
  SimulationOptions options;
  options.t_end = options.output_step = 0.5;
  std::vector<double> last;
  const SimulationSummary summary = simulate(loaded.system, compiled, start, options,
                                             [&](const std::vector<double>& row) { last = row; });
  ASSERT_TRUE(summary.ok) << summary.message;
  m.opt.integrator = mjINT_RK4;
  m.opt.timestep = 1e-4;
  mj_resetData(&m, mj.data.get());
  Eigen::Map<Eigen::VectorXd>(mj.data->qvel, m.nv) = qvel;
  for (int k = 0; k < 5000; ++k) mj_step(&m, mj.data.get());
  ASSERT_NEAR(mj.data->time, 0.5, 1e-12);
  const Eigen::VectorXd ours = Eigen::Map<const Eigen::VectorXd>(last.data() + 1, m.nq);
  const double error =
      (ours - Eigen::Map<const Eigen::VectorXd>(mj.data->qpos, m.nq)).cwiseAbs().maxCoeff();
  test::record("state_error", error);
  std::printf("floating-quadruped.xml over 0.5 s against MuJoCo's RK4: max |q - qpos| %.3g\n",
              error);
  EXPECT_LT(error, 1e-7);
}

#endif

}  // namespace
}  // namespace unidyn
