// MuJoCo 2.2.2 as an oracle for the imported formats (tests/formats/*_against_mujoco.cpp): a file
// read by unidyn and by MuJoCo at random states (q, q̇): M, f and q̈ (engine_oracle.hpp) agree
// with MuJoCo's mj_fullM, −qfrc_bias and the qacc of mj_forward.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "engine_oracle.hpp"

#ifdef UNIDYN_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace unidyn::mujoco_oracle {
namespace {

using engine_oracle::Dynamics;
using engine_oracle::Paths;

#ifdef UNIDYN_HAVE_MUJOCO

// (The full-inertia model keeps engine_oracle's 1e-10: its tensors have one product of inertia
// each, which MuJoCo diagonalises in one Jacobi rotation — its body_inertia and body_iquat give
// back the tensors written, turned by the inertial rpy, to 4.9e-16 .. 5.9e-16 relative
// (measured); a tensor with two or three products came back 6.6e-8 .. 4.1e-7 off: such tensors
// are checked against KDL, kdl_oracle.hpp.)

// One file in MuJoCo: its model and data, freed with it.
struct Mujoco {
  std::unique_ptr<mjModel, decltype(&mj_deleteModel)> model{nullptr, mj_deleteModel};
  std::unique_ptr<mjData, decltype(&mj_deleteData)> data{nullptr, mj_deleteData};

  explicit Mujoco(const std::string& path) {
    char error[1000] = "";
    model.reset(mj_loadXML(path.c_str(), nullptr, error, sizeof error));
    if (!model) throw std::runtime_error("MuJoCo refused " + path + ": " + error);
    data.reset(mj_makeData(model.get()));
  }
  int dofs() const { return model->nv; }
  // The joint of dof i (hinges and slides: one dof each).
  std::string joint_name(int i) const {
    return mj_id2name(model.get(), mjOBJ_JOINT, model->dof_jntid[i]);
  }
};

// The oracle measures the rigid tree and its joints' damping: gravity −9.81 E3, hinges and slides
// without armature, friction loss or stiffness; and its dofs are unidyn's coordinates, in order.
void expect_plain_tree(const Mujoco& mj, const System& system) {
  const mjModel& m = *mj.model;
  EXPECT_EQ(m.opt.gravity[0], 0.0);
  EXPECT_EQ(m.opt.gravity[1], 0.0);
  EXPECT_EQ(m.opt.gravity[2], -9.81);
  ASSERT_EQ(m.nq, m.nv);
  for (int j = 0; j < m.njnt; ++j) {
    EXPECT_TRUE(m.jnt_type[j] == mjJNT_HINGE || m.jnt_type[j] == mjJNT_SLIDE) << j;
    EXPECT_EQ(m.jnt_stiffness[j], 0.0) << j;
  }
  for (int i = 0; i < m.nv; ++i) {
    EXPECT_EQ(m.dof_armature[i] + m.dof_frictionloss[i], 0.0) << i;
  }
  ASSERT_EQ(system.coordinates().size(), static_cast<std::size_t>(m.nv));
  for (int i = 0; i < m.nv; ++i) {
    ASSERT_EQ(system.coordinates()[static_cast<std::size_t>(i)].name, mj.joint_name(i));
  }
}

// A random state inside every joint's range: angles within ±2 rad (the arm's narrowest limits are
// ±2.09), slides within ±0.5 m, rates within ±2.
void random_state(const Mujoco& mj, test::Random& random, Eigen::VectorXd& q,
                  Eigen::VectorXd& qdot) {
  q.resize(mj.dofs());
  qdot.resize(mj.dofs());
  for (int i = 0; i < mj.dofs(); ++i) {
    const bool slide = mj.model->jnt_type[mj.model->dof_jntid[i]] == mjJNT_SLIDE;
    q[i] = slide ? random.uniform(-0.5, 0.5) : random.uniform(-2.0, 2.0);
    qdot[i] = random.uniform(-2.0, 2.0);
  }
}

// MuJoCo's: M from its sparse qM, f = qfrc_passive − qfrc_bias (the joints' damping −b q̇;
// Coriolis, centripetal and gravity forces; no applied or actuator force), q̈ = qacc; no
// constraint row may be active.
Dynamics mujoco_dynamics(Mujoco& mj, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  const mjModel* m = mj.model.get();
  mjData* d = mj.data.get();
  const int n = mj.dofs();
  Eigen::Map<Eigen::VectorXd>(d->qpos, n) = q;
  Eigen::Map<Eigen::VectorXd>(d->qvel, n) = qdot;
  mj_forward(m, d);
  EXPECT_EQ(d->nefc, 0);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> M(n, n);
  mj_fullM(m, M.data(), d->qM);
  return {M,
          Eigen::Map<const Eigen::VectorXd>(d->qfrc_passive, n) -
              Eigen::Map<const Eigen::VectorXd>(d->qfrc_bias, n),
          Eigen::Map<const Eigen::VectorXd>(d->qacc, n)};
}

// The model in both engines at 20 random states (engine_oracle::expect_agreement).
[[maybe_unused]] void expect_agreement_with_mujoco(const std::string& file,
                                                   Paths paths = Paths::both) {
  Mujoco mj(engine_oracle::formats_model(file));
  const engine_oracle::LoadedFile unidyn = engine_oracle::load_and_compile(file, paths);
  expect_plain_tree(mj, unidyn.loaded.system);
  if (::testing::Test::HasFatalFailure()) return;
  const engine_oracle::Engine engine{
      std::string("MuJoCo ") + mj_versionString(),
      [&](test::Random& random, Eigen::VectorXd& q, Eigen::VectorXd& qdot) {
        random_state(mj, random, q, qdot);
      },
      [&](const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
        return mujoco_dynamics(mj, q, qdot);
      }};
  engine_oracle::expect_agreement(file, unidyn, paths, engine);
}

#else

[[maybe_unused]] void expect_agreement_with_mujoco(const std::string&, Paths = Paths::both) {
  GTEST_SKIP() << "MuJoCo is not installed (scripts/setup.sh test installs libmujoco-dev)";
}

#endif

}  // namespace
}  // namespace unidyn::mujoco_oracle
