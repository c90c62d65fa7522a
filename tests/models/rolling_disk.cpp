// The rolling disk (§10.7, (10.25)–(10.36)): energy, the contact force and moment M_c = π_P × F_c,
// Euler's laws with the multipliers, integrability (Ex. 8.9), and its steady motions.
#include <cmath>
#include <fstream>
#include <iterator>

#include <sstream>
#include "support/model_run.hpp"
#include "unidyn/equations/reduction.hpp"
#include "unidyn/kinematics/constraint_gradient.hpp"
#include "unidyn/kinematics/integrability.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

constexpr double m = 1.0, g = 9.81, R = 0.15, lambda = m * R * R / 4, lambda3 = 2 * lambda;

TEST(RollingDisk, EnergyContactLoadsAndEulersLaws) {
  const test::ModelRun run = test::run_model("rolling-disk");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);  // E = T + m g x3 (§10.7)
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_LT(run.at(i, "moment_check"), 1e-12);   // M_c = π_P × F_c
    EXPECT_LT(run.at(i, "newton_euler"), 1e-12);   // m ā − F = F_c, Ḣ − M = M_c
    EXPECT_LT(run.at(i, "contact_speed"), 1e-11);  // v_P = 0 (10.27)
    EXPECT_GT(run.at(i, "normal_force"), 0.0);     // the plane pushes
  }
}

// Ex. 8.9: the rolling constraints are not integrable; I(x1, ψ, φ) = −R sin ψ = S^1_45 and
// I(x2, ψ, φ) = R cos ψ = S^2_45, as the book has them.
TEST(RollingDisk, RollingIsNonholonomic) {
  const System system = load_model(test::model_path("rolling-disk"));
  const Integrability pi1 = constraint_integrability(system, 1);
  ASSERT_FALSE(pi1.integrable);
  EXPECT_EQ(pi1.witness, "I(x1, psi, phi)");
  const Expr psi = system.coordinates()[3].value;
  const Expr Rs = system.parameters[2].symbol;
  EXPECT_TRUE((pi1.value + Rs * GiNaC::sin(psi)).expand().is_zero()) << pi1.value;
  // and π2's witness, S^2_45 = R cos ψ
  const Integrability pi2 = constraint_integrability(system, 2);
  ASSERT_FALSE(pi2.integrable);
  EXPECT_EQ(pi2.witness, "I(x2, psi, phi)");
  EXPECT_TRUE((pi2.value - Rs * GiNaC::cos(psi)).expand().is_zero()) << pi2.value;
  EXPECT_TRUE(constraint_integrability(system, 0).integrable);
  EXPECT_FALSE(set_integrability(system, {1, 2}).integrable);
}

// Steady motion: θ = θ0, ψ̇ = Ω and s = φ̇ + ψ̇ cos θ constant satisfy (10.35)–(10.36) when (by hand
// from the θ equation with μ1, μ2 = m ẍ1, m ẍ2 of the centre's circle)
//   (λ3 + m R²) s Ω sin θ0 − λ Ω² sin θ0 cos θ0 + m g R cos θ0 = 0.
TEST(RollingDisk, SteadyCircularRolling) {
  const double theta0 = 1.2, Omega = 6.0;
  const double s = (lambda * Omega * Omega * std::sin(theta0) * std::cos(theta0) -
                    m * g * R * std::cos(theta0)) /
                   ((lambda3 + m * R * R) * Omega * std::sin(theta0));
  const test::ModelRun run = test::run_model("rolling-disk",
                                             {{"theta", theta0},
                                              {"x3", R * std::sin(theta0)},
                                              {"der(psi)", Omega},
                                              {"der(phi)", s - Omega * std::cos(theta0)},
                                              {"der(x1)", -R * s}},
                                             [](SimulationOptions& o) { o.t_end = 2.0; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "theta"), theta0, 1e-9) << run.at(i, "t");
    EXPECT_NEAR(run.at(i, "der(psi)"), Omega, 1e-8) << run.at(i, "t");
  }
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// (10.37)–(10.38), sliding on a smooth plane: with x3 = R sin θ eliminated (approach II), the θ
// equation is the notes' correction of (10.38) (the printed one lacks the centre's vertical
// motion):
//   (λ + m R² cos²θ) θ̈ − m R² sin θ cos θ θ̇² + λ3 φ̇ ψ̇ sin θ + (λ3 − λ) ψ̇² sin 2θ/2 = −m g R cos θ.
TEST(SlidingDisk, ThetaEquationIsTheCorrected1038) {
  const Reduction reduced = eliminate_constraints(load_model(test::model_path("sliding-disk")));
  const System& s = reduced.system;
  ASSERT_EQ(s.coordinates().size(), 5u);
  const EquationsOfMotion eq = lagrange_equations(s);
  const auto p = [&](const char* name) {
    return Expr(s.parameters[*s.find_parameter(name)].symbol);
  };
  const Expr m_ = p("m"), g_ = p("g"), R_ = p("R"), l = m_ * R_ * R_ / 4, l3 = 2 * l;
  const auto& q = s.coordinates();
  const std::size_t theta = *s.find_coordinate("theta");
  const Expr th = q[theta].value, thd = q[theta].rate, thdd = q[theta].acceleration;
  const Expr psid = q[*s.find_coordinate("psi")].rate, phid = q[*s.find_coordinate("phi")].rate;
  const Expr c = GiNaC::cos(th), sn = GiNaC::sin(th);
  const Expr book = (l + m_ * R_ * R_ * c * c) * thdd - m_ * R_ * R_ * sn * c * thd * thd +
                    l3 * phid * psid * sn + (l3 - l) * psid * psid * sn * c + m_ * g_ * R_ * c;
  const Expr ours = eq.inertia_terms[theta] + eq.potential_energy.diff(q[theta].value) -
                    eq.generalized_force[theta];
  EXPECT_TRUE(simplify(ours - book).is_zero()) << simplify(ours - book);
}

// The integrals of the sliding disk: uniform horizontal motion of the centre, the spin about e3,
// H · E3, and E.
TEST(SlidingDisk, Integrals) {
  const test::ModelRun run = test::run_model("sliding-disk");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
  for (const auto& c : run.summary.conserved_drift) EXPECT_LT(c.max_change, 1e-11) << c.name;
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// Euler's disk (named in book §9.9): rolling in place — its centre at rest, the disk turning about
// the line from the centre to the contact point — at a tilt α from the table, Euler's law about the
// centre (the contact force m g E3 has the moment R m g cos α e3 × u) asks for the precession
// Ω² = 4 g/(R sin α): the contact point's frequency rises as the disk sinks (Ω ∝ α^(−1/2)). The
// run stays there (θ = α, ψ̇ = Ω); 3 % off that rate it does not. The abrupt stop needs the
// dissipation the model leaves out.
TEST(RollingDisk, EulersDiskRollsInPlaceAtOmegaSquaredFourGOverRSinAlpha) {
  double previous = 0;
  for (const double alpha : {0.5, 0.2, 0.08}) {
    const double Omega = std::sqrt(4 * g / (R * std::sin(alpha)));
    EXPECT_GT(Omega, previous) << "the frequency rises as the disk sinks";
    previous = Omega;
    for (const double factor : {1.0, 1.03}) {
      const double rate = factor * Omega;
      const test::ModelRun run = test::run_model("rolling-disk",
                                                 {{"theta", alpha},
                                                  {"x3", R * std::sin(alpha)},
                                                  {"der(psi)", rate},
                                                  {"der(phi)", -rate * std::cos(alpha)},
                                                  {"der(x1)", 0.0},
                                                  {"der(x2)", 0.0},
                                                  {"der(theta)", 0.0}},
                                                 [](SimulationOptions& o) { o.t_end = 1; });
      ASSERT_TRUE(run.summary.ok) << run.summary.message;
      double drift = 0;
      for (std::size_t i = 0; i < run.rows.size(); ++i) {
        drift = std::max(drift, std::abs(run.at(i, "theta") - alpha));
        if (factor == 1.0) {
          EXPECT_NEAR(run.at(i, "der(psi)"), Omega, 1e-8 * Omega) << run.at(i, "t");
        }
      }
      if (factor == 1.0) {
        EXPECT_LT(drift, 1e-9) << "alpha " << alpha;
      } else {
        EXPECT_GT(drift, 1e-3 * alpha) << "alpha " << alpha;
      }
    }
  }
}

// `rolling: {body, at, normal}` is the same pair of no-slip rows as the two written out in
// rolling-disk.yaml: one motion; and its closed-form loads f = t, h = (x_P − x̄) × t (8.22) are the
// ones solved from its rows.
TEST(RollingDisk, RollingShorthandIsTheWrittenOutConstraints) {
  std::ifstream file(test::model_path("rolling-disk"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::size_t from = text.find("  - {name: pi1"), to = text.find("# leaning");
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  text.replace(from, to - from,
               "  - {name: roll, rolling: {body: disk, at: \"disk.center + "
               "R*[cos(theta)*sin(psi), -cos(theta)*cos(psi), -sin(theta)]\", normal: [0, 0, "
               "1]}}\n");
  text = text.substr(0, text.find("outputs:"));
  const System shorthand = parse_model(text, "rolling-shorthand.yaml");
  ASSERT_EQ(shorthand.constraints.size(), 3u);
  EXPECT_EQ(shorthand.constraints[1].name, "roll_1");
  EXPECT_EQ(shorthand.constraints[1].kind, Constraint::Kind::velocity);
  // the loads
  GiNaC::exmap state = shorthand.parameter_values();
  double value = 0.2;
  for (const auto& q : shorthand.coordinates()) state[q.value] = value += 0.31;
  const auto number = [&](const Expr& e) {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(state))).to_double();
  };
  for (std::size_t k = 1; k < 3; ++k) {
    const ConstraintLoads closed = constraint_loads(shorthand, k);
    const ConstraintLoads solved = solve_constraint_loads(shorthand, constraint_row(shorthand, k));
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(number(closed.body_force[0][i]), number(solved.body_force[0][i]), 1e-12);
      EXPECT_NEAR(number(closed.body_moment[0][i]), number(solved.body_moment[0][i]), 1e-12);
    }
  }
  // the motion
  const test::ModelRun written = test::run_model("rolling-disk");
  const CompiledSystem compiled(shorthand, lagrange_equations(shorthand));
  std::vector<std::vector<double>> rows;
  const SimulationSummary s = simulate(
      shorthand, compiled, initial_state(shorthand, {}), simulation_options(shorthand.simulate),
      [&](const std::vector<double>& row) { rows.push_back(row); });
  ASSERT_TRUE(s.ok) << s.message;
  ASSERT_EQ(rows.size(), written.rows.size());
  for (std::size_t i = 0; i < rows.size(); i += 10) {
    for (std::size_t c = 1; c <= 6; ++c) EXPECT_NEAR(rows[i][c], written.rows[i][c], 1e-10);
  }
}

// Exercise 7.3: a rate gyro fixed to the disk along e3 reads ω3 = ω·e3 = φ̇ + ψ̇ cos θ (3-1-3), so
// its integral is φ(t1) − φ(t0) only when ∫ ψ̇ cos θ dt = 0: along the rolling disk's motion
// (Simpson's rule on a 1 ms grid) the two differ by that integral, which is not 0.
TEST(RollingDisk, BodyFixedRateSensorOfExercise73) {
  std::ifstream file(test::model_path("rolling-disk"));
  std::stringstream text;
  text << file.rdbuf() << "  w3: dot(disk.omega, disk.e3)\n  turn: der(psi)*cos(theta)\n";
  const test::ModelRun run = test::run_system(parse_model(text.str(), "rolling-disk-gyro.yaml"), {},
                                              [](SimulationOptions& o) {
                                                o.t_end = 2.0;
                                                o.output_step = 0.001;
                                              });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const std::vector<double> sensed = test::running_integral(run, "w3"),
                            turned = test::running_integral(run, "turn");
  for (std::size_t i = 2; i < run.rows.size(); i += 2) {
    EXPECT_NEAR(sensed[i], run.at(i, "phi") - run.at(0, "phi") + turned[i], 1e-9) << run.at(i, "t");
  }
  ASSERT_EQ(run.rows.size() % 2, 1u);
  EXPECT_GT(std::abs(turned.back()), 0.1);
}

}  // namespace
}  // namespace unidyn
