// MJCF <equality> constraints (closed loops by <connect> and <weld>, couplings by <joint>) read by
// unidyn and by MuJoCo 2.2.2; unidyn solves them over the tree and by the compiled equations.
// MuJoCo holds them softly, so its qacc is not the oracle; its equality rows are: Ψ(q) = efc_pos
// and A = ∂Ψ/∂q = efc_J at random q — a weld's three turning rows are other functions than MuJoCo's
// (E23, E31, E12 of the error rotation, not a quaternion's), so for them A's row space is
// MuJoCo's, and Ψ = 0 where MuJoCo's are 0 — and, at states on the constraints (q by Newton's
// method on MuJoCo's rows, q̇ in the null space of its A), unidyn's q̈ solves
//
//   M q̈ − f ∈ range(Aᵀ)    (Lagrange's equations with constraint forces Aᵀ λ, book (3.8)),
//   A q̈ + Ȧ q̇ = 0          (the constraints' second derivative),
//
// with MuJoCo's M (mj_fullM), f = −qfrc_bias and A, and Ȧ q̇ = d/ds [A(q + s q̇)] q̇ at s = 0 by
// central differences of MuJoCo's A, Richardson-extrapolated (error O(h⁴), h = 1e-3).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>

#include "mujoco_oracle.hpp"

namespace unidyn {
namespace {

#ifdef UNIDYN_HAVE_MUJOCO

using engine_oracle::formats_model;
using engine_oracle::relative;
using mujoco_oracle::Mujoco;
using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// MuJoCo's equality rows at q: Ψ and A.
struct Rows {
  Eigen::VectorXd psi;
  Eigen::MatrixXd A;
};

Rows mujoco_rows(Mujoco& mj, const Eigen::VectorXd& q) {
  const mjModel* m = mj.model.get();
  mjData* d = mj.data.get();
  Eigen::Map<Eigen::VectorXd>(d->qpos, m->nq) = q;
  Eigen::Map<Eigen::VectorXd>(d->qvel, m->nv).setZero();
  mj_forward(m, d);
  const Eigen::Map<const RowMatrix> J(d->efc_J, d->nefc, m->nv);
  std::vector<int> rows;
  for (int r = 0; r < d->nefc; ++r) {
    if (d->efc_type[r] == mjCNSTR_EQUALITY) rows.push_back(r);
  }
  Rows out{Eigen::VectorXd(static_cast<Eigen::Index>(rows.size())),
           Eigen::MatrixXd(static_cast<Eigen::Index>(rows.size()), m->nv)};
  for (std::size_t k = 0; k < rows.size(); ++k) {
    out.psi[static_cast<Eigen::Index>(k)] = d->efc_pos[rows[k]];
    out.A.row(static_cast<Eigen::Index>(k)) = J.row(rows[k]);
  }
  return out;
}

CompileOptions compiled_equations() {
  CompileOptions options;
  options.recursive_tree = false;
  return options;
}

// The file in MuJoCo and in unidyn, solved both ways: over the tree (M by the composite-rigid-body
// algorithm, f by Newton–Euler: load_and_compile's recursive algorithms at every size) and by the
// compiled Lagrange's equations.
struct Loaded {
  Mujoco mj;
  engine_oracle::LoadedFile unidyn;
  CompiledSystem equations;
  explicit Loaded(const std::string& file)
      : mj(formats_model(file)),
        unidyn(engine_oracle::load_and_compile(file, engine_oracle::Paths::both)),
        equations(unidyn.loaded.system, lagrange_equations(unidyn.loaded.system),
                  compiled_equations()) {}
};

// A random q moved onto MuJoCo's constraints by Newton's method (the smallest step each time; a
// new random start when it does not converge, 10 at most), and a random q̇ in the null space of A.
bool random_state_on_constraints(Mujoco& mj, test::Random& random, Eigen::VectorXd& q,
                                 Eigen::VectorXd& qdot) {
  const int n = mj.dofs();
  for (int start = 0; start < 10; ++start) {
    q = Eigen::VectorXd(n);
    for (int i = 0; i < n; ++i) q[i] = random.uniform(-1.5, 1.5);
    for (int k = 0; k < 60; ++k) {
      const Rows rows = mujoco_rows(mj, q);
      if (rows.psi.norm() < 1e-14) {
        const Eigen::MatrixXd N = Eigen::FullPivLU<Eigen::MatrixXd>(rows.A).kernel();
        Eigen::VectorXd c(N.cols());
        for (Eigen::Index j = 0; j < c.size(); ++j) c[j] = random.uniform(-2.0, 2.0);
        qdot = N * c;
        if (N.cols() == n - rows.A.rows()) return true;
        break;
      }
      q -= rows.A.completeOrthogonalDecomposition().solve(rows.psi);
    }
  }
  return false;
}

// Ȧ q̇ by central differences of MuJoCo's A along q̇, Richardson-extrapolated.
Eigen::VectorXd mujoco_rate_term(Mujoco& mj, const Eigen::VectorXd& q,
                                 const Eigen::VectorXd& qdot) {
  const auto D = [&](double h) -> Eigen::VectorXd {
    return (mujoco_rows(mj, q + h * qdot).A - mujoco_rows(mj, q - h * qdot).A) * qdot / (2 * h);
  };
  const double h = 1e-3;
  return (4 * D(h / 2) - D(h)) / 3;
}

// How far the rows of B are from the row space of A, relative, and infinity when B's rank is not
// A's (then their row spaces differ).
double off_row_space(const Eigen::MatrixXd& B, const Eigen::MatrixXd& A) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> a(A, Eigen::ComputeThinV), b(B);
  const auto rank = [](const Eigen::VectorXd& s) { return (s.array() > 1e-8 * s[0]).count(); };
  if (rank(a.singularValues()) != rank(b.singularValues())) return INFINITY;
  const Eigen::MatrixXd V = a.matrixV().leftCols(rank(a.singularValues()));
  return (B - B * V * V.transpose()).norm() / B.norm();
}

// Ψ and A of unidyn's constraints against MuJoCo's rows at random q (off the constraints): the
// rows `turning` (a weld's, in threes) by their row space, the others row by row.
void expect_same_rows(const std::string& file, const std::vector<Eigen::Index>& turning = {}) {
  Loaded loaded(file);
  const CompiledSystem& compiled = *loaded.unidyn.compiled;
  CompiledSystemData data = compiled.make_data();
  const auto parameters = initial_state(loaded.unidyn.loaded.system, {}).parameters;
  test::Random random;
  double psi_error = 0, A_error = 0, space_error = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q(loaded.mj.dofs());
    for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = random.uniform(-2.0, 2.0);
    Rows reference = mujoco_rows(loaded.mj, q);
    ASSERT_EQ(static_cast<std::size_t>(reference.psi.size()), compiled.constraint_count());
    compiled.constraints(0, q, Eigen::VectorXd::Zero(q.size()), parameters, data);
    Eigen::VectorXd psi = data.constraint_position;
    Eigen::MatrixXd A = data.constraint_matrix;
    for (std::size_t w = 0; w < turning.size(); w += 3) {
      const Eigen::Index first = turning[w];
      space_error = std::max(
          space_error, off_row_space(A.middleRows(first, 3), reference.A.middleRows(first, 3)));
      psi.segment(first, 3).setZero();
      reference.psi.segment(first, 3).setZero();
      A.middleRows(first, 3).setZero();
      reference.A.middleRows(first, 3).setZero();
    }
    psi_error = std::max(psi_error, relative(psi, reference.psi));
    A_error = std::max(A_error, relative(A, reference.A));
  }
  EXPECT_LT(psi_error, 1e-13);
  EXPECT_LT(A_error, 1e-13);
  EXPECT_LT(space_error, 1e-12);
  std::printf(
      "%s against MuJoCo's equality rows: Psi %.3g, A %.3g relative; turning rows' row space "
      "%.3g\n",
      file.c_str(), psi_error, A_error, space_error);
}

// How far q̈ is from solving MuJoCo's equations at a state on the constraints: M q̈ − f off the
// range of Aᵀ, and A q̈ + Ȧ q̇, each relative to its terms' size (‖A‖ ‖q̈‖: q̈ is mostly along
// the constraints, so A q̈ is small beside it).
struct Residuals {
  double force = 0, constraint = 0, multipliers = 0, position = 0;
};

Residuals mujoco_residuals(Mujoco& mj, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                           const Eigen::VectorXd& qddot) {
  const Eigen::VectorXd rate_term = mujoco_rate_term(mj, q, qdot);
  const Rows rows = mujoco_rows(mj, q);
  Eigen::Map<Eigen::VectorXd>(mj.data->qvel, mj.dofs()) = qdot;
  mj_forward(mj.model.get(), mj.data.get());
  RowMatrix M(mj.dofs(), mj.dofs());
  mj_fullM(mj.model.get(), M.data(), mj.data->qM);
  const Eigen::VectorXd f = -Eigen::Map<const Eigen::VectorXd>(mj.data->qfrc_bias, mj.dofs());
  // M q̈ − f has no part along the motions the constraints allow (the null space of A)
  const Eigen::MatrixXd N = Eigen::FullPivLU<Eigen::MatrixXd>(rows.A).kernel();
  const Eigen::VectorXd residual = M * qddot - f;
  return {(N.transpose() * residual).norm() / ((M * qddot).norm() + f.norm()),
          (rows.A * qddot + rate_term).norm() / (rows.A.norm() * qddot.norm() + rate_term.norm())};
}

// unidyn's q̈, over the tree and by the compiled equations, in MuJoCo's Lagrange's equations and
// constraints at 20 states on the constraints.
void expect_constrained_accelerations(const std::string& file) {
  Loaded loaded(file);
  ASSERT_TRUE(loaded.unidyn.compiled->closes_loops())
      << loaded.unidyn.compiled->why_not_recursive();
  const auto parameters = initial_state(loaded.unidyn.loaded.system, {}).parameters;
  Mujoco& mj = loaded.mj;
  test::Random random;
  Residuals worst;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q, qdot;
    ASSERT_TRUE(random_state_on_constraints(mj, random, q, qdot)) << "state " << k;
    std::vector<Eigen::VectorXd> multipliers;
    for (const CompiledSystem* compiled : {loaded.unidyn.compiled.get(), &loaded.equations}) {
      CompiledSystemData data = compiled->make_data();
      Eigen::VectorXd qddot, lambda;
      compiled->solve(0, q, qdot, parameters, qddot, lambda, data);
      // unidyn's constraints hold where MuJoCo's do
      compiled->constraints(0, q, qdot, parameters, data);
      worst.position = std::max(worst.position, data.constraint_position.norm());
      const Residuals r = mujoco_residuals(mj, q, qdot, qddot);
      worst.force = std::max(worst.force, r.force);
      worst.constraint = std::max(worst.constraint, r.constraint);
      multipliers.push_back(lambda);
    }
    // (not an oracle: the same rows; the tree's M and f against the derived equations')
    worst.multipliers = std::max(worst.multipliers, relative(multipliers[0], multipliers[1]));
  }
  EXPECT_LT(worst.force, 1e-12);
  EXPECT_LT(worst.constraint, 1e-10);  // the differences' error
  EXPECT_LT(worst.multipliers, 1e-10);
  EXPECT_LT(worst.position, 1e-13);
  test::record("force_error", worst.force);
  test::record("constraint_error", worst.constraint);
  std::printf(
      "%s against MuJoCo (over the tree and by the compiled equations): M q'' - f off range(A^T) "
      "by %.3g, A q'' + A' q' by %.3g relative\n",
      file.c_str(), worst.force, worst.constraint);
}

// A spatial linkage closed by a <connect>: its three rows, the point on the rocker from qpos0.
TEST(MjcfLoopsAgainstMujoco, ConnectRowsAreMujocos) {
  expect_same_rows("spatial-loop.xml");
}

TEST(MjcfLoopsAgainstMujoco, ConnectAccelerationsSolveMujocosEquations) {
  expect_constrained_accelerations("spatial-loop.xml");
}

// A spatial linkage closed by a <weld> (anchor on the tool, the relative pose at qpos0): its
// three position rows, and its three turning rows by row space.
TEST(MjcfLoopsAgainstMujoco, WeldRowsAreMujocos) {
  expect_same_rows("welded-loop.xml", {3, 4, 5});
}

TEST(MjcfLoopsAgainstMujoco, WeldAccelerationsSolveMujocosEquations) {
  expect_constrained_accelerations("welded-loop.xml");
}

// The same weld with its relative pose typed (relpose: the hand's point and the tool's turn from
// the hand, away from qpos0's).
TEST(MjcfLoopsAgainstMujoco, WeldWithRelposeRowsAreMujocos) {
  std::ifstream in(engine_oracle::formats_model("welded-loop.xml"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string weld = "anchor=\"0.02 0 0.03\"";
  text.replace(text.find(weld), weld.size(),
               weld + " relpose=\"0.1 0.02 -0.05 0.95 0.1 -0.2 0.15\"");
  const auto path = std::filesystem::path(testing::TempDir()) /
                    ("relposed-loop" + std::to_string(::getpid()) + ".xml");
  std::ofstream(path) << text;
  expect_same_rows(path.string(), {3, 4, 5});
  expect_constrained_accelerations(path.string());
  std::filesystem::remove(path);
}

// <joint> equalities: a quadratic coupling of two joints, and a joint held at a0.
TEST(MjcfLoopsAgainstMujoco, JointCouplingRowsAreMujocos) {
  expect_same_rows("coupled-pendulums.xml");
}

TEST(MjcfLoopsAgainstMujoco, JointCouplingAccelerationsSolveMujocosEquations) {
  expect_constrained_accelerations("coupled-pendulums.xml");
}

#else

TEST(MjcfLoopsAgainstMujoco, NeedsMujoco) {
  GTEST_SKIP() << "MuJoCo is not installed (scripts/setup.sh test installs libmujoco-dev)";
}

#endif

}  // namespace
}  // namespace unidyn
