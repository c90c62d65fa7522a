// The rolling disk (§10.7, (10.25)–(10.36)): energy, the contact force and moment M_c = π_P × F_c,
// Euler's laws with the multipliers, integrability (Ex. 8.9), and its steady motions.
#include <array>
#include <cmath>
#include <cstdio>
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

// (10.35)–(10.36) with the rolling eliminated, by hand. Let s = φ̇ + ψ̇ cos θ (= ω · e3) and
// e1' = cos ψ E1 + sin ψ E2, e2' = E3 × e1'. π1 = π2 = 0 of (10.36) say the centre moves
// horizontally at v̄ = −R s e1' − R θ̇ sin θ e2', so (e1', e2' turning at ψ̇)
//   ā · e1' = −R ṡ + R ψ̇ θ̇ sin θ,   ā · e2' = −R (θ̈ sin θ + θ̇² cos θ) − R ψ̇ s,
// and x3 = R sin θ gives ā · E3 = R (θ̈ cos θ − θ̇² sin θ). With μ1 = m ẍ1, μ2 = m ẍ2 (the first two
// of (10.35)), Φ5 = R m ā · e1', Φ3 = cos θ Φ5 and Φ4 = −m g R cos θ + R sin θ m ā · e2', the
// φ, ψ and θ equations of (10.35) become
//   (λ3 + m R²) ṡ = m R² ψ̇ θ̇ sin θ,
//   λ sin θ ψ̈ = λ3 s θ̇ − 2 λ cos θ θ̇ ψ̇,
//   (λ + m R²) θ̈ = −m g R cos θ − (λ3 + m R²) s ψ̇ sin θ + λ ψ̇² sin θ cos θ
// (the m R² θ̇² terms cancel), and the contact force is F_c = m ā + m g E3 (μ3 from the last of
// (10.35)). The notes' misprints of §10.7 (the unknowns printed as "x1, φ, θ, ψ", (10.32)–(10.33)
// written with "u^1..u^9", the erratum of (10.38)) do not touch (10.35)'s equations used here.
// State (x1, x2, ψ, θ, φ, ψ̇, θ̇, φ̇).
using DiskState = std::array<double, 8>;

struct DiskAccelerations {
  double s_rate, psi, theta;
};

DiskAccelerations disk_accelerations(const DiskState& y) {
  const double st = std::sin(y[3]), ct = std::cos(y[3]);
  const double psid = y[5], thd = y[6], s = y[7] + psid * ct;
  return {
      m * R * R * psid * thd * st / (lambda3 + m * R * R),
      (lambda3 * s * thd - 2 * lambda * ct * thd * psid) / (lambda * st),
      (-m * g * R * ct - (lambda3 + m * R * R) * s * psid * st + lambda * psid * psid * st * ct) /
          (lambda + m * R * R)};
}

DiskState disk_rates(const DiskState& y) {
  const double sp = std::sin(y[2]), cp = std::cos(y[2]), st = std::sin(y[3]), ct = std::cos(y[3]);
  const double psid = y[5], thd = y[6], s = y[7] + psid * ct;
  const DiskAccelerations a = disk_accelerations(y);
  return {-R * (s * cp - thd * st * sp),
          -R * (s * sp + thd * st * cp),
          psid,
          thd,
          y[7],
          a.psi,
          a.theta,
          a.s_rate - a.psi * ct + psid * thd * st};
}

// The contact force m ā + m g E3 from the hand kinematics above.
std::array<double, 3> contact_force(const DiskState& y) {
  const double sp = std::sin(y[2]), cp = std::cos(y[2]), st = std::sin(y[3]), ct = std::cos(y[3]);
  const double psid = y[5], thd = y[6], s = y[7] + psid * ct;
  const DiskAccelerations a = disk_accelerations(y);
  const double along = -R * a.s_rate + R * psid * thd * st;
  const double across = -R * (a.theta * st + thd * thd * ct) - R * psid * s;
  return {m * (along * cp - across * sp), m * (along * sp + across * cp),
          m * R * (a.theta * ct - thd * thd * st) + m * g};
}

DiskState disk_rk4(DiskState y, double h, int n) {
  auto add = [](const DiskState& x, const DiskState& k, double f) {
    DiskState z;
    for (std::size_t j = 0; j < z.size(); ++j) z[j] = x[j] + f * k[j];
    return z;
  };
  for (int i = 0; i < n; ++i) {
    const DiskState k1 = disk_rates(y), k2 = disk_rates(add(y, k1, h / 2)),
                    k3 = disk_rates(add(y, k2, h / 2)), k4 = disk_rates(add(y, k3, h));
    for (std::size_t j = 0; j < y.size(); ++j)
      y[j] += h / 6 * (k1[j] + 2 * k2[j] + 2 * k3[j] + k4[j]);
  }
  return y;
}

// §10.7's transient: from the model's start (θ0 = 1.2, θ̇0 = 0, ψ̇0 = 1.5, φ̇0 = 12 — not a steady
// circle: θ̈(0) ≈ −40 rad/s², θ then nutates between ~0.97 and 1.2 and ψ̇ swings to ~−5.7) the
// run's θ, ψ̇, φ̇ (and ψ, φ, x1, x2) against the reduced (10.35)–(10.36) above integrated here by
// RK4 (h = 0.1 ms), and the run's contact force F_c = disk.constraint_force (the three
// constraints' loads) against m ā − F = m ā + m g E3 with ā from the hand kinematics of the
// centre on the RK4 state.
TEST(RollingDisk, TransientAndContactForceAgreeWithReduced1035ByRk4) {
  std::ifstream file(test::model_path("rolling-disk"));
  std::stringstream text;
  text << file.rdbuf()
       << "  Fc1: dot(disk.constraint_force, E1)\n  Fc2: dot(disk.constraint_force, E2)\n"
          "  Fc3: dot(disk.constraint_force, E3)\n";
  const test::ModelRun run = test::run_system(parse_model(text.str(), "rolling-disk-fc.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.parameter("m"), m);
  ASSERT_EQ(run.parameter("g"), g);
  ASSERT_EQ(run.parameter("R"), R);
  DiskState y{run.at(0, "x1"),         run.at(0, "x2"),      run.at(0, "psi"),
              run.at(0, "theta"),      run.at(0, "phi"),     run.at(0, "der(psi)"),
              run.at(0, "der(theta)"), run.at(0, "der(phi)")};
  double theta_error = 0, rate_error = 0, angle_error = 0, position_error = 0, force_error = 0;
  double theta_min = y[3], largest_friction = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    if (k > 0) y = disk_rk4(y, 1e-4, 100);  // the rows are 0.01 s apart
    ASSERT_NEAR(run.at(k, "t"), 0.01 * static_cast<double>(k), 1e-12);
    theta_error = std::max(theta_error, std::abs(run.at(k, "theta") - y[3]));
    rate_error = std::max({rate_error, std::abs(run.at(k, "der(psi)") - y[5]),
                           std::abs(run.at(k, "der(phi)") - y[7])});
    angle_error = std::max(
        {angle_error, std::abs(run.at(k, "psi") - y[2]), std::abs(run.at(k, "phi") - y[4])});
    position_error = std::max(
        {position_error, std::abs(run.at(k, "x1") - y[0]), std::abs(run.at(k, "x2") - y[1])});
    const std::array<double, 3> F = contact_force(y);
    force_error = std::max({force_error, std::abs(run.at(k, "Fc1") - F[0]),
                            std::abs(run.at(k, "Fc2") - F[1]), std::abs(run.at(k, "Fc3") - F[2])});
    theta_min = std::min(theta_min, y[3]);
    largest_friction = std::max(largest_friction, std::hypot(F[0], F[1]));
  }
  EXPECT_LT(theta_min, 1.0);         // a transient, far from the start's θ0 = 1.2
  EXPECT_GT(largest_friction, 1.0);  // the rolling does act (m g = 9.81 N)
  // RK4 at h = 1e-4 s (φ̇ ~ 12–16 rad/s: error ~1e-13) against a run at rtol 1e-12 over 5 s,
  // ~11 spin turns: ~1e-10 of the rates and of m g
  EXPECT_LT(theta_error, 1e-10);
  EXPECT_LT(rate_error, 1e-9);
  EXPECT_LT(angle_error, 1e-9);
  EXPECT_LT(position_error, 1e-10);
  EXPECT_LT(force_error, 1e-9);
  std::printf(
      "reduced (10.35) by RK4 vs model over 5 s: theta %.3g, rates %.3g rad/s, psi/phi %.3g, "
      "x1/x2 %.3g m, F_c %.3g N (friction up to %.3g N)\n",
      theta_error, rate_error, angle_error, position_error, force_error, largest_friction);
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

namespace unidyn {
namespace {

// §8.6.3, (8.21)–(8.22): the contact loads of the rolling disk against closed forms.
// (a) The model's rows are the book's π1, π2 as printed in (8.21), and the height x3 = R sin θ
//     differentiates to its π3 = ẋ3 − R θ̇ cos θ (symbolically).
// (b) Steady circular rolling (θ = θ0, ψ̇ = Ω, s = φ̇ + ψ̇ cos θ constant, s from the θ equation as in
//     `RollingDisk.SteadyCircularRolling`): by hand the centre moves at v̄ = −R s e1' on the circle
//     x1 = −(R s/Ω) sin Ωt, x2 = −(R s/Ω)(1 − cos Ωt), so ā = −R s Ω e2' (e2' = −sin ψ E1 + cos ψ
//     E2, ψ = Ωt) and F_c = m ā − F = −m R s Ω e2' + m g E3: the multipliers of (8.22), F_c = Σ μ_i
//     E_i, are μ1 = m R s Ω sin Ωt, μ2 = −m R s Ω cos Ωt (the centripetal friction) and μ3 = m g
//     (the normal force), and the run's M_c = Ḣ − M (from its motion) is π_P × F_c with this F_c
//     and π_P = −R(−cos θ sin ψ E1 + cos θ cos ψ E2 + sin θ E3).
TEST(RollingDisk, ContactLoadsOf822InSteadyCircularRollingAgainstClosedForm) {
  std::ifstream file(test::model_path("rolling-disk"));
  std::stringstream text;
  text << file.rdbuf()
       << "  Mc1: dot(disk.constraint_moment, E1)\n  Mc2: dot(disk.constraint_moment, E2)\n"
          "  Mc3: dot(disk.constraint_moment, E3)\n";
  const System system = parse_model(text.str(), "rolling-disk-loads.yaml");
  {
    const auto& q = system.coordinates();
    const auto at = [&](const char* name) { return q[*system.find_coordinate(name)]; };
    const Expr Rs = system.parameters[*system.find_parameter("R")].symbol;
    const Expr psi = at("psi").value, th = at("theta").value;
    const Expr dpsi = at("psi").rate, dth = at("theta").rate, dphi = at("phi").rate;
    const Expr book1 = at("x1").rate + Rs * dphi * GiNaC::cos(psi) +
                       Rs * dpsi * GiNaC::cos(th) * GiNaC::cos(psi) -
                       Rs * dth * GiNaC::sin(th) * GiNaC::sin(psi);
    const Expr book2 = at("x2").rate + Rs * dphi * GiNaC::sin(psi) +
                       Rs * dpsi * GiNaC::cos(th) * GiNaC::sin(psi) +
                       Rs * dth * GiNaC::sin(th) * GiNaC::cos(psi);
    const Expr book3 = at("x3").rate - Rs * dth * GiNaC::cos(th);
    ASSERT_EQ(system.constraints[1].name, "pi1");
    ASSERT_EQ(system.constraints[2].name, "pi2");
    EXPECT_TRUE(simplify(system.constraints[1].expression - book1).is_zero())
        << simplify(system.constraints[1].expression - book1);
    EXPECT_TRUE(simplify(system.constraints[2].expression - book2).is_zero())
        << simplify(system.constraints[2].expression - book2);
    Expr height_rate = 0;
    for (const auto& c : q) height_rate += system.constraints[0].expression.diff(c.value) * c.rate;
    EXPECT_TRUE(simplify(height_rate - book3).is_zero()) << simplify(height_rate - book3);
  }
  for (const auto& [theta0, Omega] : {std::pair{1.2, 6.0}, std::pair{1.4, -4.0}}) {
    const double s = (lambda * Omega * Omega * std::sin(theta0) * std::cos(theta0) -
                      m * g * R * std::cos(theta0)) /
                     ((lambda3 + m * R * R) * Omega * std::sin(theta0));
    const test::ModelRun run = test::run_system(system,
                                                {{"theta", theta0},
                                                 {"x3", R * std::sin(theta0)},
                                                 {"der(psi)", Omega},
                                                 {"der(phi)", s - Omega * std::cos(theta0)},
                                                 {"der(x1)", -R * s}},
                                                [](SimulationOptions& o) { o.t_end = 2.0; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    ASSERT_EQ(run.parameter("m"), m);
    ASSERT_EQ(run.parameter("g"), g);
    ASSERT_EQ(run.parameter("R"), R);
    const double friction = m * R * s * Omega, radius = R * s / Omega;
    double force_error = 0, moment_error = 0, path_error = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t"), psi = Omega * t;
      const double F[3] = {friction * std::sin(psi), -friction * std::cos(psi), m * g};
      const double P[3] = {R * std::cos(theta0) * std::sin(psi),
                           -R * std::cos(theta0) * std::cos(psi), -R * std::sin(theta0)};
      const double M[3] = {P[1] * F[2] - P[2] * F[1], P[2] * F[0] - P[0] * F[2],
                           P[0] * F[1] - P[1] * F[0]};
      force_error = std::max({force_error, std::abs(run.at(i, "lambda(pi1)") - F[0]),
                              std::abs(run.at(i, "lambda(pi2)") - F[1]),
                              std::abs(run.at(i, "lambda(height)") - F[2]),
                              std::abs(run.at(i, "normal_force") - F[2])});
      moment_error =
          std::max({moment_error, std::abs(run.at(i, "Mc1") - M[0]),
                    std::abs(run.at(i, "Mc2") - M[1]), std::abs(run.at(i, "Mc3") - M[2])});
      path_error = std::max({path_error, std::abs(run.at(i, "x1") + radius * std::sin(psi)),
                             std::abs(run.at(i, "x2") + radius * (1 - std::cos(psi)))});
    }
    // a run at rtol 1e-12 over 2 s (~2 turns of ψ): its loads ~1e-10 of m g, the centre ~1e-11 m
    EXPECT_LT(force_error, 1e-9) << theta0;
    EXPECT_LT(moment_error, 1e-10) << theta0;
    EXPECT_LT(path_error, 1e-10) << theta0;
    EXPECT_GT(std::abs(friction), 0.5);  // the friction does act
    std::printf(
        "steady rolling theta0 %.2f, Omega %.1f: friction %.4f N on a circle of %.4f m; F_c %.3g "
        "N, "
        "M_c %.3g N m, centre %.3g m off the closed form\n",
        theta0, Omega, std::abs(friction), std::abs(radius), force_error, moment_error, path_error);
  }
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// Euler's disk settling (book §9.9: the whirring rises in frequency as the disk sinks). A resisting
// moment −c ω on the disk (c = 4e-4 N m s, a rolling or air resistance chosen here: the book gives
// none) drains the energy of the disk started rolling in place at α = 0.3 (Ω² = 4g/(R sin α)). It
// sinks slowly through the steady circling motions of `RollingDisk.SteadyCircularRolling`: in every
// 1 s window the mean of their condition (by hand from the θ equation),
//   ρ = [(λ3 + m R²) s Ω sin θ − λ Ω² sin θ cos θ + m g R cos θ] / (m g R cos θ) = 0,
// s = φ̇ + ψ̇ cos θ, Ω = ψ̇, stays below 1e-3 (the nutation the moment excites makes ρ oscillate
// about 0 by about 1 %), while θ falls from 0.3 to 0.075 in 30 s and the contact point's rate Ω
// rises from 29.8 to 56.7 rad/s, following Ω² = 4g/(R sin θ) within 10 % in 1 s means (the spin s
// drifts to −1.7 % of Ω, off rolling in place). The abrupt stop, a finite-time end, is not reached.
TEST(RollingDisk, EulersDiskWithResistanceSinksThroughSteadyMotionsAtRisingRate) {
  std::ifstream file(test::model_path("rolling-disk"));
  std::string text((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  const std::string gravity = "  - gravity: -g*E3\n";
  const std::size_t at = text.find(gravity);
  ASSERT_NE(at, std::string::npos);
  text.insert(at + gravity.size(), "  - moment: {on: disk, value: -4e-4*disk.omega}\n");
  const double alpha = 0.3, Omega = std::sqrt(4 * g / (R * std::sin(alpha)));
  const test::ModelRun run = test::run_system(parse_model(text, "eulers-disk.yaml"),
                                              {{"theta", alpha},
                                               {"x3", R * std::sin(alpha)},
                                               {"der(psi)", Omega},
                                               {"der(phi)", -Omega * std::cos(alpha)},
                                               {"der(x1)", 0.0},
                                               {"der(x2)", 0.0},
                                               {"der(theta)", 0.0}},
                                              [](SimulationOptions& o) { o.t_end = 30; });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double window_sum = 0, window_ratio = 0, worst_mean = 0, worst_rho = 0, low = 1, high = 0;
  int window_rows = 0, window = 0;
  double theta_before = alpha + 1, rate_before = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), th = run.at(i, "theta"), W = run.at(i, "der(psi)");
    const double s = run.at(i, "der(phi)") + W * std::cos(th);
    const double rho = ((lambda3 + m * R * R) * s * W * std::sin(th) -
                        lambda * W * W * std::sin(th) * std::cos(th) + m * g * R * std::cos(th)) /
                       (m * g * R * std::cos(th));
    worst_rho = std::max(worst_rho, std::abs(rho));
    window_ratio += W * W * R * std::sin(th) / (4 * g);
    window_sum += rho;
    ++window_rows;
    if (t >= window + 1 - 1e-9) {  // the end of a 1 s window
      worst_mean = std::max(worst_mean, std::abs(window_sum / window_rows));
      low = std::min(low, window_ratio / window_rows);
      high = std::max(high, window_ratio / window_rows);
      EXPECT_LT(th, theta_before) << "it sinks, t = " << t;
      EXPECT_GT(W, rate_before) << "the rate rises, t = " << t;
      theta_before = th;
      rate_before = W;
      window_sum = 0;
      window_ratio = 0;
      window_rows = 0;
      ++window;
    }
  }
  const double theta_end = run.rows.back()[run.index("theta")],
               rate_end = run.rows.back()[run.index("der(psi)")];
  std::printf(
      "theta %.3f -> %.4f, Omega %.2f -> %.2f rad/s; steady condition: largest 1 s mean "
      "%.2e, largest |rho| %.2e; 1 s means of Omega^2 R sin(theta)/(4g) in [%.4f, %.4f]\n",
      alpha, theta_end, Omega, rate_end, worst_mean, worst_rho, low, high);
  EXPECT_EQ(window, 30);
  EXPECT_LT(worst_mean, 1e-3);
  EXPECT_LT(worst_rho, 0.02);
  EXPECT_GT(low, 0.9);
  EXPECT_LE(high, 1);
  EXPECT_LT(theta_end, 0.1);
  EXPECT_GT(rate_end, 1.8 * Omega);
}

}  // namespace
}  // namespace unidyn
