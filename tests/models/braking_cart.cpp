// The three-wheeled braking cart (§4.4, Fig. 4.4, (4.5)): nine particle coordinates with the rigid
// links, the ground and the axle's rolling constraint e2 · v1 = 0 as constraints, against the
// cart's equations derived by hand as one planar body with the knife edge at the axle's centre A.
#include <cmath>
#include <numbers>

#include "support/model_run.hpp"
#include "unidyn/integrate/dormand_prince.hpp"

namespace unidyn {
namespace {

constexpr double g = 9.81;

// The cart's parameters as the model file gives them, with b, u0 and mu_d overridable.
struct Cart {
  double m1 = 100, m2 = 100, m3 = 100, a = 0.6, b = -1.0, mu_d = 0.5, u0 = 10.0, w0 = 0.05;

  double M() const { return m1 + m2 + m3; }
  double c() const { return m3 * b / M(); }  // A to the centre of mass, along e1
  double I_A() const { return (m1 + m2) * a * a + m3 * b * b; }  // about A
  double N() const { return m3 * g; }                            // the locked wheel's normal force

  // With v_A = u e1 (the knife edge) and the locked wheel's velocity v3 = u e1 + b ω e2 of speed s,
  // Kane's equations for u and ω (generalised inertia forces from a_C = (u' − c ω²) e1 +
  // (u ω + c ω') e2, the friction −μ_d N v3/s at m3):
  //   M (u' − c ω²) = −μ_d N u/s,   I_A ω' + M c u ω = −μ_d N b² ω/s,
  // and φ' = ω, x_A' = u cos φ, y_A' = u sin φ. State (u, ω, φ, x_A, y_A).
  void rhs(const Eigen::VectorXd& y, Eigen::VectorXd& dydt) const {
    const double u = y[0], w = y[1], phi = y[2];
    const double s = std::hypot(u, b * w);
    dydt[0] = c() * w * w - mu_d * N() * u / (M() * s);
    dydt[1] = (-M() * c() * u * w - mu_d * N() * b * b * w / s) / I_A();
    dydt[2] = w;
    dydt[3] = u * std::cos(phi);
    dydt[4] = u * std::sin(phi);
  }

  std::vector<std::pair<std::string, double>> overrides() const {
    return {{"b", b}, {"mu_d", mu_d}, {"u0", u0}, {"w0", w0}};
  }
};

// The run against the hand-derived equations, row by row until just before the cart stops: the
// heading, u, ω, the axle centre's path, and the rolling constraint's multiplier from the lateral
// balance M a_C · e2 = F_c1 · e2 + F_f · e2 with F_c1 = λ (r2 − r1) = 2 a λ e2 (4.5).
void expect_hand_equations(const Cart& cart, double* heading_change = nullptr) {
  const test::ModelRun run = test::run_model("braking-cart", cart.overrides());
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.front().what, "'ground3' slides");
  const double t_rest = run.summary.phases.size() > 1 ? run.summary.phases.back().t : 7.0;
  DormandPrinceOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  DormandPrince54 hand(
      [&cart](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) { cart.rhs(y, dydt); },
      options);
  Eigen::VectorXd y0(5);
  y0 << cart.u0, cart.w0, 0, 0, 0;
  hand.initialize(0, y0);
  std::size_t checked = 0;
  for (std::size_t i = 1; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (t > t_rest - 0.05) break;
    while (hand.t() < t) hand.step(t);
    const Eigen::VectorXd& y = hand.y();
    const double u = y[0], w = y[1], phi = y[2];
    EXPECT_NEAR(std::remainder(run.at(i, "heading") - phi, 2 * std::numbers::pi), 0, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "u"), u, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "omega"), w, 1e-8) << t;
    const double xA = 0.5 * (run.at(i, "x1") + run.at(i, "x2"));
    const double yA = 0.5 * (run.at(i, "y1") + run.at(i, "y2"));
    EXPECT_NEAR(xA, y[3], 1e-8) << t;
    EXPECT_NEAR(yA, y[4], 1e-8) << t;
    Eigen::VectorXd rate(5);
    cart.rhs(y, rate);
    const double s = std::hypot(u, cart.b * w);
    const double lateral =
        cart.M() * (u * w + cart.c() * rate[1]) + cart.mu_d * cart.N() * cart.b * w / s;  // = 2 a λ
    EXPECT_NEAR(2 * cart.a * run.at(i, "lambda(rolling)"), lateral, 1e-6 * (1 + std::abs(lateral)))
        << t;
    ++checked;
    if (heading_change != nullptr) *heading_change = phi;
  }
  EXPECT_GT(checked, 100u);
}

// The locked wheel trailing (b < 0) at u0² = 100 > μ_d g |b| = 4.9: the small turn grows and the
// cart swings round (more than a quarter turn) before it stops.
TEST(BrakingCart, TrailingLockedWheelSwingsRound) {
  Cart cart;
  double heading = 0;
  expect_hand_equations(cart, &heading);
  EXPECT_GT(std::abs(heading), std::numbers::pi / 2);
}

// The locked wheel leading (b > 0): the turn dies out and the cart brakes nearly straight.
TEST(BrakingCart, LeadingLockedWheelBrakesStraight) {
  Cart cart;
  cart.b = 1.0;
  double heading = 0;
  expect_hand_equations(cart, &heading);
  EXPECT_LT(std::abs(heading), 0.01);
}

// Linearised about straight braking, ω'/ω = −(M c u + μ_d N b²/u)/I_A: with the wheel trailing
// the turn grows while u² > μ_d g |b| (M |c| = m3 |b|, N = m3 g), and dies out below.
TEST(BrakingCart, StraightBrakingStabilityBound) {
  for (const double u0 : {1.5, 3.0}) {  // μ_d g |b| = 4.905: u0² = 2.25 below, 9 above
    Cart cart;
    cart.u0 = u0;
    cart.w0 = 1e-4;
    const test::ModelRun run = test::run_model("braking-cart", cart.overrides(),
                                               [](SimulationOptions& o) { o.t_end = 0.05; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const double w_end = run.at(run.rows.size() - 1, "omega");
    EXPECT_EQ(w_end > cart.w0, u0 * u0 > cart.mu_d * g * std::abs(cart.b)) << u0;
  }
}

// Without a turn the cart brakes straight at μ_d m3 g/M and stops at T = M u0/(μ_d m3 g), where
// the locked wheel sticks; the axle needs no side force.
TEST(BrakingCart, StraightBrakingStopsOnTime) {
  Cart cart;
  cart.w0 = 0;
  const test::ModelRun run = test::run_model("braking-cart", cart.overrides());
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double T = cart.M() * cart.u0 / (cart.mu_d * cart.N());
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what, "contact 'ground3' sticks");
  EXPECT_NEAR(run.summary.phases[1].t, T, 1e-9);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = std::min(run.at(i, "t"), T);
    EXPECT_NEAR(run.at(i, "u"), cart.u0 * (1 - t / T), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "x3"), cart.b + cart.u0 * t * (1 - t / (2 * T)), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "lambda(rolling)"), 0, 1e-9 * cart.N()) << t;  // vs forces ~ N
    EXPECT_NEAR(run.at(i, "heading"), 0, 1e-12) << t;
  }
}

}  // namespace
}  // namespace unidyn
