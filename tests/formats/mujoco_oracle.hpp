// MuJoCo 2.2.2 as an oracle for the imported formats (tests/formats/*_against_mujoco.cpp): a file
// read by unidyn and by MuJoCo, an engine written independently of unidyn, at random states
// (q, q̇): the mass matrix M, the forcing f of Lagrange's equations M q̈ = f (book (3.7); no
// constraints) and the accelerations q̈ agree with MuJoCo's mj_fullM, −qfrc_bias and the qacc of
// mj_forward.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/numeric/compiled_system.hpp"

#ifdef UNIDYN_HAVE_MUJOCO
#include <mujoco/mujoco.h>
#endif

namespace unidyn::mujoco_oracle {
namespace {

#ifdef UNIDYN_HAVE_MUJOCO

// Both engines are exact on these models up to rounding: a relative error this large is a
// difference in the physics. (The full-inertia model keeps it too: its tensors have one product
// of inertia each, which MuJoCo diagonalises in one Jacobi rotation — its body_inertia and
// body_iquat give back the tensors written, turned by the inertial rpy, to 4.9e-16 .. 5.9e-16
// relative (measured); a tensor with two or three products came back 6.6e-8 .. 4.1e-7 off.)
constexpr double kTolerance = 1e-10;

// A test model of tests/formats/models by name, or a file by its absolute path.
std::string formats_model(const std::string& file) {
  if (file.starts_with("/")) return file;
  std::string path = UNIDYN_FORMATS_DIR;
  path.append("/").append(file);
  return path;
}

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

// The oracle measures the rigid tree alone: gravity −9.81 E3, hinges and slides without
// damping, armature, friction loss or stiffness; and its dofs are unidyn's coordinates, in order.
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
    EXPECT_EQ(m.dof_damping[i] + m.dof_armature[i] + m.dof_frictionloss[i], 0.0) << i;
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

// M, f of M q̈ = f, and q̈ at one state.
struct Dynamics {
  Eigen::MatrixXd M;
  Eigen::VectorXd f, qddot;
};

// MuJoCo's: M from its sparse qM, f = −qfrc_bias (Coriolis, centripetal and gravity forces; no
// passive, applied or actuator force), q̈ = qacc; no constraint row may be active.
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
  return {M, -Eigen::Map<const Eigen::VectorXd>(d->qfrc_bias, n),
          Eigen::Map<const Eigen::VectorXd>(d->qacc, n)};
}

// unidyn's recursive dynamics of the tree (numeric/tree_evaluation.hpp): M and f by the
// composite-rigid-body and Newton–Euler algorithms, q̈ by the articulated-body algorithm.
Dynamics unidyn_dynamics(const CompiledSystem& compiled, const std::vector<double>& parameters,
                         CompiledSystemData& data, const Eigen::VectorXd& q,
                         const Eigen::VectorXd& qdot) {
  EXPECT_TRUE(compiled.recursive()) << compiled.why_not_recursive();
  Eigen::VectorXd qddot, lambda;
  compiled.solve(0, q, qdot, parameters, qddot, lambda, data);
  compiled.mass_and_forcing(0, q, qdot, parameters, data);
  return {data.mass_matrix, data.forcing, qddot};
}

// unidyn's symbolic path: the compiled Lagrange's equations M q̈ = f (the dynamics tape, which
// the analyses use), solved here.
Dynamics symbolic_dynamics(const CompiledSystem& compiled, const std::vector<double>& parameters,
                           const Eigen::VectorXd& q, const Eigen::VectorXd& qdot) {
  std::vector<double> inputs{0.0};
  inputs.insert(inputs.end(), q.begin(), q.end());
  inputs.insert(inputs.end(), qdot.begin(), qdot.end());
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  const std::vector<double> out = compiled.dynamics().evaluate(inputs);
  const auto n = q.size();
  const Eigen::MatrixXd M =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          out.data(), n, n);
  const Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(out.data() + n * n, n);
  return {M, f, M.ldlt().solve(f)};
}

// The largest relative errors of M, f and q̈ of one evaluation against MuJoCo's.
struct Errors {
  double M = 0, f = 0, qddot = 0;
  void add(const Dynamics& ours, const Dynamics& reference);
};

double relative(const Eigen::MatrixXd& value, const Eigen::MatrixXd& reference) {
  return (value - reference).norm() / reference.norm();
}

void Errors::add(const Dynamics& ours, const Dynamics& reference) {
  M = std::max(M, relative(ours.M, reference.M));
  f = std::max(f, relative(ours.f, reference.f));
  qddot = std::max(qddot, relative(ours.qddot, reference.qddot));
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Which of unidyn's evaluations a test compares with MuJoCo's.
enum class Paths { recursive, both };

// The model in both engines at 20 random states: the largest relative (Frobenius) errors of M, f
// and q̈ — of the recursive algorithms and, with Paths::both, of the compiled Lagrange's equations
// — stay within kTolerance. Prints them, and unidyn's times to load, derive and compile.
void expect_agreement_with_mujoco(const std::string& file, Paths paths = Paths::both) {
  Mujoco mj(formats_model(file));
  auto start = std::chrono::steady_clock::now();
  const commands::LoadedModel loaded = commands::load_named_model(formats_model(file));
  const double load_time = seconds_since(start);
  CompileOptions options;
  options.recursive_from_coordinates = 0;  // the recursive algorithms at every size
  // the compiled equations only when they are compared: the recursive ones need no derivation
  start = std::chrono::steady_clock::now();
  const EquationsOfMotion equations =
      paths == Paths::both ? lagrange_equations(loaded.system) : EquationsOfMotion();
  const double derive_time = seconds_since(start);
  start = std::chrono::steady_clock::now();
  const CompiledSystem compiled = paths == Paths::both
                                      ? CompiledSystem(loaded.system, equations, options)
                                      : CompiledSystem(loaded.system, options);
  if (paths == Paths::both) compiled.dynamics();
  const double compile_time = seconds_since(start);
  expect_plain_tree(mj, loaded.system);
  if (::testing::Test::HasFatalFailure()) return;
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(loaded.system, {}).parameters;
  test::Random random;
  Errors recursive, symbolic;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q, qdot;
    random_state(mj, random, q, qdot);
    const Dynamics reference = mujoco_dynamics(mj, q, qdot);
    recursive.add(unidyn_dynamics(compiled, parameters, data, q, qdot), reference);
    if (paths == Paths::both) {
      symbolic.add(symbolic_dynamics(compiled, parameters, q, qdot), reference);
    }
  }
  for (const Errors* e : {&recursive, &symbolic}) {
    EXPECT_LT(e->M, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
    EXPECT_LT(e->f, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
    EXPECT_LT(e->qddot, kTolerance) << (e == &symbolic ? "symbolic" : "recursive");
  }
  test::record("M_error", std::max(recursive.M, symbolic.M));
  test::record("f_error", std::max(recursive.f, symbolic.f));
  test::record("qddot_error", std::max(recursive.qddot, symbolic.qddot));
  std::printf(
      "%s against MuJoCo %s: relative errors of the recursive algorithms M %.3g, f %.3g, q'' "
      "%.3g; of the compiled equations M %.3g, f %.3g, q'' %.3g (0: not compared); unidyn's load "
      "%.3f s, derive %.3f s, compile %.3f s\n",
      file.c_str(), mj_versionString(), recursive.M, recursive.f, recursive.qddot, symbolic.M,
      symbolic.f, symbolic.qddot, load_time, derive_time, compile_time);
}

#else

enum class Paths { recursive, both };

void expect_agreement_with_mujoco(const std::string&, Paths = Paths::both) {
  GTEST_SKIP() << "MuJoCo is not installed (scripts/setup.sh test installs libmujoco-dev)";
}

#endif

}  // namespace
}  // namespace unidyn::mujoco_oracle
