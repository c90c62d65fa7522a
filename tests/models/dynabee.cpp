// Exercise 11.4, the Dynabee (Powerball): models/dynabee.yaml, a rotor whose axle rolls on a track
// inside a casing the hand moves. (e) With both centres as coordinates the constraints are 11
// independent rows on 12 coordinates (rank of A at the start), leaving the rotor's α; (d) the
// rolling gives (11.17) γ̇ = −(R_t/R_a) α̇ along the whole run, the rotor spinning ten times faster
// than it runs round the track.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Eigen/Dense>

#include "support/model_run.hpp"
#include "unidyn/equations/lagrange.hpp"

namespace unidyn {
namespace {

TEST(Dynabee, ElevenConstraintsAndTheRollingRelation1117) {
  const System system = load_model(test::model_path("dynabee"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  SimulationStart start = initial_state(system, {});
  complete_initial_state(system, compiled, start);
  CompiledSystemData data = compiled.make_data();
  compiled.constraints(start.t0, start.q, start.qdot, start.parameters, data);
  EXPECT_EQ(data.constraint_matrix.rows(), 11);
  EXPECT_EQ(data.constraint_matrix.cols(), 12);
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(data.constraint_matrix).rank(), 11);

  const test::ModelRun run = test::run_system(system, {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double R_t = 0.03, R_a = 0.003;
  double travelled = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double alpha_rate = run.at(i, "der(alpha)");
    EXPECT_NEAR(run.at(i, "der(gamma)"), -R_t / R_a * alpha_rate, 1e-9 * std::abs(alpha_rate))
        << run.at(i, "t");
    travelled = run.at(i, "alpha");
  }
  EXPECT_GT(travelled, 10.0) << "the rotor must run round the track";
}

}  // namespace
}  // namespace unidyn
