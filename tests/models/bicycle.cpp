// The Whipple–Carvallo bicycle (models/bicycle.yaml) against the benchmark of Meijaard,
// Papadopoulos, Ruina & Schwab (2007), Proc. R. Soc. A 463: linearised about upright straight
// running at speed v, the roll φ and steer δ obey
//   M q̈ + v C1 q̇ + (g K0 + v² K2) q = 0,   q = (φ, δ),
// with the matrices of their (A1)–(A4), given there to 14 digits (support/bicycle_benchmark.hpp).
// Here the full nonlinear model
// (eight coordinates, one holonomic and four rolling constraints) is linearised by central
// differences of its accelerations, its other values completed from the constraints at each
// perturbed state, and compared with those matrices, and with the speeds where the weave and the
// capsize motions change stability (their Table 2).
#include <cmath>

#include "support/bicycle_benchmark.hpp"
#include "support/eigen_solvers.hpp"
#include "support/model_run.hpp"
#include "unidyn/kinematics/integrability.hpp"

namespace unidyn {
namespace {

using test::benchmark_state_matrix;
constexpr double rR = test::kBenchmarkRearRadius;

class Bicycle {
 public:
  Bicycle()
      : system_(load_model(test::model_path("bicycle"))),
        compiled_(system_, lagrange_equations(system_)),
        data_(compiled_.make_data()) {}

  // (φ̈, δ̈) at roll, steer and their rates, the rear wheel turning at v / rR; every other value
  // completed from the constraints.
  Eigen::Vector2d accelerations(const Eigen::Vector4d& x, double v) {
    SimulationStart start = initial_state(system_, {{"phi", x[0]},
                                                    {"delta", x[1]},
                                                    {"der(phi)", x[2]},
                                                    {"der(delta)", x[3]},
                                                    {"der(thR)", v / rR}});
    complete_initial_state(system_, compiled_, start);
    Eigen::VectorXd qddot, lambda;
    compiled_.solve(start.t0, start.q, start.qdot, start.parameters, qddot, lambda, data_);
    return {qddot[index("phi")], qddot[index("delta")]};
  }

  // The state matrix of (φ, δ, φ̇, δ̇) about upright straight running, by central differences.
  Eigen::Matrix4d state_matrix(double v) {
    constexpr double h = 1e-5;
    Eigen::Matrix4d A = Eigen::Matrix4d::Zero();
    A.topRightCorner<2, 2>() = Eigen::Matrix2d::Identity();
    for (int k = 0; k < 4; ++k) {
      const Eigen::Vector4d step = h * Eigen::Vector4d::Unit(k);
      A.block<2, 1>(2, k) = (accelerations(step, v) - accelerations(-step, v)) / (2 * h);
    }
    return A;
  }

 private:
  Eigen::Index index(const std::string& name) const {
    return static_cast<Eigen::Index>(*system_.find_coordinate(name));
  }

  System system_;
  CompiledSystem compiled_;
  CompiledSystemData data_;
};

// The largest real part of the weave (complex pair) and of the capsize (real) eigenvalues.
std::pair<double, double> weave_and_capsize(const Eigen::Matrix4d& A) {
  const Eigen::VectorXcd lambda = test::eigenvalues(A);
  double weave = -INFINITY, capsize = -INFINITY;
  for (const auto& l : lambda) {
    if (std::abs(l.imag()) > 1e-6) {
      weave = std::max(weave, l.real());
    } else if (std::abs(l.real()) < 1.0) {  // the slow real root (castering is fast, < -1)
      capsize = std::max(capsize, l.real());
    }
  }
  return {weave, capsize};
}

TEST(Bicycle, LinearisedEquationsAreTheBenchmarks) {
  Bicycle bicycle;
  for (const double v : {0.0, 2.0, 5.0, 8.0}) {
    const Eigen::Matrix4d ours = bicycle.state_matrix(v);
    const Eigen::Matrix4d theirs = benchmark_state_matrix(v);
    EXPECT_LT((ours - theirs).cwiseAbs().maxCoeff(), 1e-7 * (1 + theirs.cwiseAbs().maxCoeff()))
        << "v = " << v << "\nunidyn:\n"
        << ours << "\nbenchmark:\n"
        << theirs;
  }
}

// Table 2: the weave motion becomes stable at v_w = 4.29238253634111 m/s, the capsize motion
// unstable at v_c = 6.02426201538837 m/s.
TEST(Bicycle, SelfStableBetweenTheWeaveAndCapsizeSpeeds) {
  Bicycle bicycle;
  constexpr double v_w = test::kWeaveSpeed, v_c = test::kCapsizeSpeed;
  EXPECT_NEAR(weave_and_capsize(bicycle.state_matrix(v_w)).first, 0.0, 1e-6);
  EXPECT_NEAR(weave_and_capsize(bicycle.state_matrix(v_c)).second, 0.0, 1e-6);
  const auto [weave, capsize] = weave_and_capsize(bicycle.state_matrix(5.0));
  EXPECT_LT(weave, 0.0);
  EXPECT_LT(capsize, 0.0);
}

// The nonlinear run of the bundled model: energy kept (no friction does work in rolling), the
// front contact at rest, and the roll perturbation dying away at 4.6 m/s (self-stable).
TEST(Bicycle, RightsItselfAtFourPointSixMetresPerSecond) {
  const test::ModelRun run = test::run_model("bicycle", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-9);
  double early = 0, late = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_LT(run.at(i, "front_contact_speed"), 1e-9);
    EXPECT_NEAR(run.at(i, "speed"), 4.6, 0.5);
    const double t = run.at(i, "t"), phi = std::abs(run.at(i, "phi"));
    if (t < 1) early = std::max(early, phi);  // the largest roll in the first second
    if (t > 4) late = std::max(late, phi);    // and in the last
  }
  EXPECT_LT(late, 0.3 * early);
}

// Each rolling constraint is non-integrable by (1.21); the four together are past the size the
// Frobenius test (8.18) is run at, and say so rather than take minutes.
TEST(Bicycle, RollingConstraintsNonIntegrableTheSetNotTested) {
  const System system = load_model(test::model_path("bicycle"));
  std::vector<std::size_t> velocity;
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    if (system.constraints[k].kind != Constraint::Kind::velocity) continue;
    velocity.push_back(k);
    EXPECT_FALSE(constraint_integrability(system, k).integrable) << system.constraints[k].name;
  }
  ASSERT_EQ(velocity.size(), 4u);
  try {
    set_integrability(system, velocity);
    FAIL() << "the set was tested";
  } catch (const std::invalid_argument& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("not tested")) << e.what();
  }
}

}  // namespace
}  // namespace unidyn
