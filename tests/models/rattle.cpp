// RATTLE (HLW §VII.1.4): second order against a tight reference, symmetric (a step forward then
// back returns to the start), constraints held to round-off, energy error bounded without drift,
// and refused for systems that are not natural conservative ones.
#include "unidyn/integrate/rattle.hpp"

#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// The state at t_end from the model's initial state, by RATTLE with step h.
Eigen::VectorXd rattle_state(const System& system, const CompiledNaturalSystem& natural, double h,
                             double t_end) {
  const SimulationStart start = initial_state(system, {});
  RattleOptions options;
  options.step = h;
  Rattle stepper(natural, start.parameters, options);
  Eigen::VectorXd y0(2 * start.q.size());
  y0 << start.q, start.qdot;
  stepper.initialize(0, y0);
  while (stepper.t() < t_end) stepper.step(t_end);
  return stepper.y();
}

// The error falls fourfold when h is halved: second order, on an unconstrained model with M(q)
// (the double pendulum) and a constrained one (the Cartesian spherical pendulum).
TEST(Rattle, SecondOrder) {
  for (const std::string name : {"double-pendulum", "spherical-pendulum-cartesian"}) {
    const System system = load_model(test::model_path(name));
    const CompiledNaturalSystem natural(system, lagrange_equations(system));
    const test::ModelRun reference =
        test::run_model(name, {}, [](SimulationOptions& o) { o.t_end = 1.0; });
    ASSERT_TRUE(reference.summary.ok);
    const std::vector<double>& last = reference.rows.back();
    const auto n = static_cast<Eigen::Index>(system.coordinates().size());
    std::vector<double> errors;
    for (const double h : {0.01, 0.005, 0.0025}) {
      const Eigen::VectorXd y = rattle_state(system, natural, h, 1.0);
      double error = 0;
      for (Eigen::Index i = 0; i < 2 * n; ++i) {
        error = std::max(error, std::abs(y[i] - last[static_cast<std::size_t>(1 + i)]));
      }
      errors.push_back(error);
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
      EXPECT_NEAR(std::log2(errors[k - 1] / errors[k]), 2.0, 0.1) << name << " " << errors[k];
    }
  }
}

// Symmetric: a step of h then one of −h returns to the start (to the iterations' round-off).
TEST(Rattle, SymmetricStep) {
  const System system = load_model(test::model_path("spherical-pendulum-cartesian"));
  const CompiledNaturalSystem natural(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  RattleOptions options;
  options.step = 0.05;
  Rattle stepper(natural, start.parameters, options);
  Eigen::VectorXd y0(6);
  y0 << start.q, start.qdot;
  stepper.initialize(0, y0);
  stepper.step(1.0);
  EXPECT_EQ(stepper.t(), 0.05);
  EXPECT_GT((stepper.y() - y0).norm(), 0.01);
  stepper.step(-1.0);
  EXPECT_LT((stepper.y() - y0).cwiseAbs().maxCoeff(), 1e-13);
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

// Ψ = 0 and G q̇ = 0 hold to round-off after every one of 2·10⁴ steps.
TEST(Rattle, ConstraintsHeldAtEveryStep) {
  const System system = load_model(test::model_path("spherical-pendulum-cartesian"));
  const CompiledNaturalSystem natural(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  RattleOptions options;
  options.step = 0.005;
  Rattle stepper(natural, start.parameters, options);
  Eigen::VectorXd y0(6), psi;
  Eigen::MatrixXd G;
  y0 << start.q, start.qdot;
  stepper.initialize(0, y0);
  NaturalSystemData data = natural.make_data();
  double position = 0, velocity = 0;
  for (int k = 0; k < 20000; ++k) {
    stepper.step(1000);
    natural.constraints(stepper.y().head(3), start.parameters, psi, G, data);
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
  const test::ModelRun run =
      test::run_model("heavy-top-socket", {}, [](SimulationOptions& o) { o.method = "rattle"; });
  EXPECT_FALSE(run.summary.ok);
  EXPECT_NE(run.summary.message.find("not positive definite"), std::string::npos)
      << run.summary.message;
}

}  // namespace
}  // namespace unidyn
