// Two bodies joined by a cylindrical hinge (§8.6.4, §11.3), derived two independent ways: with
// seven coordinates and no multipliers (hinged-bodies, Lagrange's approach II (11.5)), and with
// twelve coordinates and the pin's five multipliers (hinged-bodies-pinned, (11.6)). The two runs
// must give one motion, and the hinge force on A from the seven-coordinate run's m ā − F must be
// the pin's Σ μ_k f_k (8.23) from the twelve-coordinate run.
#include <cmath>

#include "support/joint_loads.hpp"
#include "support/model_run.hpp"
#include "unidyn/kinematics/constraint_gradient.hpp"

namespace unidyn {
namespace {

TEST(HingedBodies, SevenAndTwelveCoordinatesGiveOneMotionAndOneHingeForce) {
  const test::ModelRun reduced = test::run_model("hinged-bodies");
  const test::ModelRun pinned = test::run_model("hinged-bodies-pinned");
  ASSERT_TRUE(reduced.summary.ok) << reduced.summary.message;
  ASSERT_TRUE(pinned.summary.ok) << pinned.summary.message;
  ASSERT_EQ(reduced.rows.size(), pinned.rows.size());
  for (std::size_t i = 0; i < reduced.rows.size(); ++i) {
    for (const char* column : {"x", "y", "z", "xB", "yB", "zB", "a3_1", "a3_2", "a1_3"}) {
      EXPECT_NEAR(reduced.at(i, column), pinned.at(i, column), 1e-9) << column << " row " << i;
    }
    for (const char* column : {"hinge_force_1", "hinge_force_2", "hinge_force_3"}) {
      EXPECT_NEAR(reduced.at(i, column), pinned.at(i, column), 1e-8) << column << " row " << i;
    }
  }
}

// (8.24): F_cA = −F_cB, the reaction moments M_r = M_c − π_P × F_c are equal and opposite and
// perpendicular to the axis, and the pin's loads are m ā − F and Ḣ − M of each body (Euler's laws
// with the multipliers the saddle-point solve returned).
TEST(HingedBodies, PinObeysTheGeneralisedThirdLaw) {
  const test::ModelRun run = test::run_model("hinged-bodies-pinned");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    largest = std::max(largest, std::abs(run.at(i, "hinge_force_1")));
    EXPECT_LT(run.at(i, "force_sum"), 1e-14);
    EXPECT_LT(run.at(i, "reaction_sum"), 1e-14);
    EXPECT_LT(std::abs(run.at(i, "reaction_along_axis")), 1e-14);
    EXPECT_LT(run.at(i, "newton_euler"), 1e-12);
  }
  EXPECT_GT(largest, 0.5);  // the hinge does carry a load
}

// (8.24) from the loads solved from each pin row in the coordinates alone (not the closed forms
// of model/joints): F_cA = −F_cB, and the reaction moments M_c − π_P × F_c are equal and opposite
// and perpendicular to the axis A.e3.
TEST(HingedBodies, SolvedRowLoadsObeyTheThirdLaw) {
  const System system = load_model(test::model_path("hinged-bodies-pinned"));
  GiNaC::exmap state = system.parameter_values();
  double value = 0.1;
  for (const auto& q : system.coordinates()) state[q.value] = value += 0.23;
  const auto number = [&](const Expr& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(state))).to_double();
  };
  const auto vec = [&](const VectorExpr& v) {
    return Vec3(number(v[0]), number(v[1]), number(v[2]));
  };
  const auto p = [&](const char* name) {
    return Expr(system.parameters[*system.find_parameter(name)].symbol);
  };
  const Vec3 arm_A =
      vec(system.material_point(0, VectorExpr(p("L1"), 0, 0)) - system.bodies[0].center);
  const Vec3 arm_B =
      vec(system.material_point(1, VectorExpr(-p("L2"), 0, 0)) - system.bodies[1].center);
  const Vec3 axis = vec(system.body_basis_vector(0, 3));
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const ConstraintLoads solved = solve_constraint_loads(system, constraint_row(system, k));
    const Vec3 fA = vec(solved.body_force[0]), fB = vec(solved.body_force[1]);
    const Vec3 rA = vec(solved.body_moment[0]) - arm_A.cross(fA);
    const Vec3 rB = vec(solved.body_moment[1]) - arm_B.cross(fB);
    EXPECT_LT((fA + fB).norm(), 1e-12) << system.constraints[k].name;
    EXPECT_LT((rA + rB).norm(), 1e-12) << system.constraints[k].name;
    EXPECT_LT(std::abs(rA.dot(axis)), 1e-12) << system.constraints[k].name;
  }
}

// Without external loads E, G and H_O are constants of both descriptions.
TEST(HingedBodies, MomentaAndEnergyConserved) {
  for (const char* model : {"hinged-bodies", "hinged-bodies-pinned"}) {
    const test::ModelRun run = test::run_model(model);
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    EXPECT_LT(run.summary.energy_relative_drift, 1e-11) << model;
    for (const auto& c : run.summary.conserved_drift) {
      EXPECT_LT(c.max_change, 1e-11) << model << " " << c.name;
    }
  }
}

TEST(HingedBodies, PinLoadsMatchTheirRowsInTheCoordinates) {
  test::expect_joint_loads_match_rows(load_model(test::model_path("hinged-bodies-pinned")));
}

}  // namespace
}  // namespace unidyn
