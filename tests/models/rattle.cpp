// RATTLE (HLW §VII.1.4): second order against a tight reference, its compositions of order 4 and 6
// (Yoshida 1990), symmetric (a step forward then back returns to the start), constraints held to
// round-off, energy error bounded without drift, and refused for systems that are not natural
// conservative ones.
#include "unidyn/integrate/rattle.hpp"

#include "unidyn/equations/kane.hpp"

#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// A model's natural system and a RATTLE stepper of step h (and order) started at the model's
// initial state.
struct RattleRun {
  System system;
  CompiledNaturalSystem natural;
  SimulationStart start;
  Rattle stepper;

  RattleRun(const std::string& name, double h, int order = 2)
      : system(load_model(test::model_path(name))),
        natural(system, lagrange_equations(system)),
        start(initial_state(system, {})),
        stepper(natural, start.parameters, RattleOptions{.step = h, .order = order}) {
    stepper.initialize(0, y0());
  }
  Eigen::VectorXd y0() const {
    Eigen::VectorXd y(2 * start.q.size());
    y << start.q, start.qdot;
    return y;
  }
};

// The state at t_end from the model's initial state, by RATTLE with step h.
Eigen::VectorXd rattle_state(const std::string& name, double h, double t_end, int order) {
  RattleRun run(name, h, order);
  while (run.stepper.t() < t_end) run.stepper.step(t_end);
  return run.stepper.y();
}

// log₂ of the error's fall each time h is halved from h0, at t = 1 against Dormand–Prince at
// rtol 1e-13: the order, on an unconstrained model with M(q) (the double pendulum) and a
// constrained one (the Cartesian spherical pendulum).
void expect_order(int order, double h0, double slack) {
  for (const std::string name : {"double-pendulum", "spherical-pendulum-cartesian"}) {
    const test::ModelRun reference = test::run_model(name, {}, [](SimulationOptions& o) {
      o.t_end = 1.0;
      o.rtol = 1e-13;
      o.atol = 1e-15;
    });
    ASSERT_TRUE(reference.summary.ok);
    const std::vector<double>& last = reference.rows.back();
    const auto n = static_cast<Eigen::Index>(reference.system.coordinates().size());
    std::vector<double> errors;
    for (const double h : {h0, h0 / 2, h0 / 4}) {
      const Eigen::VectorXd y = rattle_state(name, h, 1.0, order);
      double error = 0;
      for (Eigen::Index i = 0; i < 2 * n; ++i) {
        error = std::max(error, std::abs(y[i] - last[static_cast<std::size_t>(1 + i)]));
      }
      errors.push_back(error);
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
      EXPECT_NEAR(std::log2(errors[k - 1] / errors[k]), order, slack)
          << name << " order " << order << ": error " << errors[k];
    }
  }
}

// The error falls fourfold when h is halved: second order.
TEST(Rattle, SecondOrder) {
  expect_order(2, 0.01, 0.1);
}

// Composed (Yoshida's triple jump; his seven-stage solution A): 16-fold and 64-fold.
TEST(Rattle, CompositionsOfOrderFourAndSix) {
  expect_order(4, 0.04, 0.15);
  expect_order(6, 0.025, 0.3);
}

// Symmetric: a step of h then one of −h returns to the start (to the iterations' round-off), for
// RATTLE and its compositions.
TEST(Rattle, SymmetricStep) {
  for (const int order : {2, 4, 6}) {
    RattleRun run("spherical-pendulum-cartesian", 0.05, order);
    run.stepper.step(1.0);
    EXPECT_EQ(run.stepper.t(), 0.05);
    EXPECT_GT((run.stepper.y() - run.y0()).norm(), 0.01);
    run.stepper.step(-1.0);
    EXPECT_LT((run.stepper.y() - run.y0()).cwiseAbs().maxCoeff(), 1e-13) << order;
  }
}

// Over 2·10⁴ steps the energy error stays bounded: its largest value over the whole run is no more
// than over the first tenth (an integrator that drifts would grow ~10×).
TEST(Rattle, ConstraintsAndBoundedEnergy) {
  for (const std::string name : {"spherical-pendulum-cartesian", "kepler", "heavy-top"}) {
    double first_tenth = 0, whole = 0, e0 = 0;
    std::size_t row = 0;
    const test::ModelRun run = test::run_model(name, {}, [](SimulationOptions& o) {
      o.method = "rattle";
      o.t_end = 100;
      o.output_step = 0.01;
      o.step = 0.005;
    });
    ASSERT_TRUE(run.summary.ok) << name << ": " << run.summary.message;
    for (const double e : run.column("energy")) {
      if (row == 0) e0 = e;
      whole = std::max(whole, std::abs(e - e0));
      if (row < run.rows.size() / 10) first_tenth = whole;
      ++row;
    }
    EXPECT_LT(whole, 1.5 * first_tenth) << name;
    EXPECT_LT(whole, 1e-3 * std::abs(e0)) << name;
  }
}

// Ψ = 0 and G q̇ = 0 hold to round-off after every one of 3000 steps of the sixth-order
// composition (2.1·10⁴ RATTLE substeps, each of which must end on the manifold for the next).
TEST(Rattle, ConstraintsHeldAtEveryStep) {
  RattleRun run("spherical-pendulum-cartesian", 0.005, 6);
  Rattle& stepper = run.stepper;
  const std::vector<double>& parameters = run.start.parameters;
  Eigen::VectorXd psi;
  Eigen::MatrixXd G;
  NaturalSystemData data = run.natural.make_data();
  double position = 0, velocity = 0;
  for (int k = 0; k < 3000; ++k) {
    stepper.step(1000);
    run.natural.constraints(stepper.y().head(3), parameters, psi, G, data);
    position = std::max(position, std::abs(psi[0]));
    velocity = std::max(velocity, std::abs((G * stepper.y().tail(3))[0]));
  }
  EXPECT_LT(position, 1e-15);  // |Ψ| = |x² + y² + z² − L²| with L = 1
  EXPECT_LT(velocity, 1e-14);  // |G q̇| = 2 |r · v| with |v| ≈ 3
}

// Not natural: velocity constraints (rolling disk), a driven system (the rate gyroscope's moving
// platform), a damper; Euler parameters (M singular) fail the run with the reason.
TEST(Rattle, OnlyForNaturalSystems) {
  for (const std::string name : {"rolling-disk", "rate-gyroscope", "stick-slip-oscillator"}) {
    const System system = load_model(test::model_path(name));
    EXPECT_THROW(CompiledNaturalSystem(system, lagrange_equations(system)), std::invalid_argument)
        << name;
  }
  // natural whatever form its equations take (Kane's M is not written as T's second derivatives)
  const System top = load_model(test::model_path("heavy-top"));
  EXPECT_NO_THROW(CompiledNaturalSystem(top, kane_equations(top)));
  const test::ModelRun run =
      test::run_model("heavy-top-socket", {}, [](SimulationOptions& o) { o.method = "rattle"; });
  EXPECT_FALSE(run.summary.ok);
  EXPECT_NE(run.summary.message.find("not positive definite"), std::string::npos)
      << run.summary.message;
}

}  // namespace
}  // namespace unidyn
