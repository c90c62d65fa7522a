// Poisson's top: its apex slides on a smooth plane (§10.8, Exercise 7.10).
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

using V = Eigen::Vector3d;

// The plane pushes vertically at the apex P = x̄ − L3 e3: E, G·E1, G·E2, H·E3 and H·e3 are
// conserved (§10.8; the plane does push, λ > 0). About the moving apex, H_P = H + (x̄ − x_P) × m v̄
// equals the book's λ_a ω3 e3 + (λ_t + m L3²)(ω1 e1 + ω2 e2) + L3 e3 × m v_P (Ex. 7.10), with
// v_P = v̄ − ω × L3 e3.
TEST(PoissonTop, IntegralsAndAngularMomentumAboutTheApex) {
  const double m = 1.0, L3 = 0.05, lt = 0.004, la = 0.002;
  const test::ModelRun run = test::run_model("poisson-top");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-12);
  ASSERT_EQ(run.summary.conserved_drift.size(), 4u);
  for (const auto& c : run.summary.conserved_drift) {
    EXPECT_LT(c.max_change, 1e-12 * (1 + std::abs(c.initial))) << c.name;
    EXPECT_NE(c.initial, 0.0) << c.name;
  }
  const auto vec = [&](std::size_t i, const std::string& name) {
    return V(run.at(i, name + ".x"), run.at(i, name + ".y"), run.at(i, name + ".z"));
  };
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_GT(run.at(i, "lambda_plane"), 0.0);
    const V H = vec(i, "H"), w = vec(i, "omega"), e3 = vec(i, "e3_"), v = vec(i, "v");
    const V H_P = H + (L3 * e3).cross(m * v);
    const V v_P = v - w.cross(L3 * e3);
    const V w_axial = w.dot(e3) * e3;
    const V book = la * w_axial + (lt + m * L3 * L3) * (w - w_axial) + (L3 * e3).cross(m * v_P);
    EXPECT_LT((H_P - book).norm(), 1e-12 * (1 + H_P.norm())) << run.at(i, "t");
  }
}

}  // namespace
}  // namespace unidyn
