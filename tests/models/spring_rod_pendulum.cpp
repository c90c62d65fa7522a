// Exercise 5.6(a)–(f): a spring–rod pendulum with the non-integrable constraint (5.18).
#include <cmath>

#include "support/model_run.hpp"
#include "unidyn/kinematics/integrability.hpp"

namespace unidyn {
namespace {

// (5.18) r1 θ̇1 + L2 θ̇2 = 0 is not integrable; scleronomic with e = 0, its force does no work —
// the constraint forces' power Σ R_i · v_i is 0 along the run — and so E is conserved (5.6(f)).
TEST(SpringRodPendulum, NonIntegrableConstraintDoesNoWork) {
  const test::ModelRun run = test::run_model("spring-rod-pendulum");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_FALSE(constraint_integrability(run.system, 0).integrable);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "power"), 0.0, 1e-11) << run.at(i, "t");
  }
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  EXPECT_TRUE(run.summary.energy_not_conserved.empty()) << run.summary.energy_not_conserved;
  EXPECT_LT(run.summary.max_velocity_residual, 1e-11);
}

}  // namespace
}  // namespace unidyn
