// A uniform sphere rolling without slipping: down an incline (§9.8, (9.26)), on a turntable
// (Exercise 9.10, (9.33)–(9.34)) and inside a pipe (a `rolling:` contact whose normal changes with
// the coordinates), described by its centre and Euler parameters with the rolling constraints
// v_P = 0 or v_P = Ω E3 × x̄ as velocity constraints; and, for Exercise 10.4, on the incline in
// 3-1-3 angles, rolling and sliding.
#include <cmath>
#include <complex>
#include <cstdio>
#include <string>
#include <utility>

#include <fstream>
#include <sstream>
#include "support/model_run.hpp"
#include "unidyn/integrate/dormand_prince.hpp"
#include "unidyn/integrate/driver.hpp"
#include "unidyn/kinematics/integrability.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// (9.26): ẍ1 = (5/7) g sin β from rest, ω = ẋ1/R E2; the plane's friction −(2/7) m g sin β E1 and
// normal force m g cos β E3 from the multipliers (8.22); energy conserved.
TEST(RollingSphere, InclineClosedForm) {
  const test::ModelRun run = test::run_model("sphere-incline");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1, g = 9.81, R = 0.1, beta = 0.3, a = 5.0 / 7.0 * g * std::sin(beta);
  for (std::size_t i = 0; i < run.rows.size(); i += 10) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), a * t * t / 2, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "x2"), 0.0, 1e-12) << t;
    EXPECT_NEAR(run.at(i, "w2"), a * t / R, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "friction"), -2.0 / 7.0 * m * g * std::sin(beta), 1e-9) << t;
    EXPECT_NEAR(run.at(i, "normal"), m * g * std::cos(beta), 1e-9) << t;
  }
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
}

// Exercise 9.10: ẍ1 = −(2/7) Ω ẋ2, ẍ2 = (2/7) Ω ẋ1, so ẋ1 + i ẋ2 = v0 e^{i κ t} and
// x1 + i x2 = z0 + v0 (e^{i κ t} − 1)/(i κ) with κ = 2Ω/7: the centre circles at 2Ω/7.
TEST(RollingSphere, TurntableCirclesAtTwoSeventhsOmega) {
  const test::ModelRun run = test::run_model("sphere-turntable");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double Omega = 2.0, kappa = 2 * Omega / 7;
  const std::complex<double> z0(0.3, 0.0), v0(0.0, 0.1), i(0.0, 1.0);
  for (std::size_t row = 0; row < run.rows.size(); row += 50) {
    const double t = run.at(row, "t");
    const std::complex<double> z = z0 + v0 * (std::exp(i * kappa * t) - 1.0) / (i * kappa);
    EXPECT_NEAR(run.at(row, "x1"), z.real(), 1e-9) << t;
    EXPECT_NEAR(run.at(row, "x2"), z.imag(), 1e-9) << t;
    EXPECT_NEAR(run.at(row, "x3"), 0.1, 1e-12) << t;
  }
  EXPECT_LT(run.summary.max_velocity_residual, 1e-10);
}

// Exercise 9.10(f): the centre's circle has centre c = z0 + i v0/κ and radius |v0|/κ, so on a
// disc of radius R0 the sphere falls off only if |c| + |v0|/κ > R0: over a period the centre's
// largest distance from the axis is |c| + |v0|/κ, and a `stop_when` at a radius 1 mm less is met,
// 1 mm more is not.
TEST(RollingSphere, TurntableEdgeOfExercise910f) {
  const double kappa = 2 * 2.0 / 7;
  const std::complex<double> z0(0.3, 0.0), v0(0.0, 0.1), i(0.0, 1.0);
  const double reach = std::abs(z0 + i * v0 / kappa) + std::abs(v0) / kappa;
  std::ifstream file(test::model_path("sphere-turntable"));
  std::stringstream base;
  base << file.rdbuf();
  for (const double margin : {-1e-3, 1e-3}) {
    std::stringstream text;
    text << base.str() << "stop_when: [" << reach + margin << "^2 - x1^2 - x2^2]\n";
    const test::ModelRun run =
        test::run_system(parse_model(text.str(), "turntable-edge.yaml"), {},
                         [&](SimulationOptions& o) { o.t_end = 2 * 3.14159265358979 / kappa; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    EXPECT_EQ(run.summary.stopped, margin < 0) << margin;
    double farthest = 0;
    for (std::size_t row = 0; row < run.rows.size(); ++row) {
      farthest = std::max(farthest, std::hypot(run.at(row, "x1"), run.at(row, "x2")));
    }
    if (margin > 0) {
      EXPECT_NEAR(farthest, reach, 1e-5);
    }
  }
}

// (9.27)–(9.29): thrown at u0 without spin, the sphere slides with ẍ1 = −μ_d g and
// ω̇2 = (5/2) μ_d g/R until the slip u0 − μ_d g t − R ω2 vanishes at T = 2 u0/(7 μ_d g); then it
// rolls at (5/7) u0 with no friction needed (§9.8).
TEST(RollingSphere, SlidesThenRolls) {
  const test::ModelRun run = test::run_model("sphere-slide-roll");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double g = 9.81, R = 0.1, mu = 0.2, u0 = 2.0, T = 2 * u0 / (7 * mu * g);
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[0].what, "'table' slides");
  EXPECT_EQ(run.summary.phases[1].what, "contact 'table' sticks");
  EXPECT_NEAR(run.summary.phases[1].t, T, 1e-10);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    if (t < T) {
      EXPECT_NEAR(run.at(i, "der(x1)"), u0 - mu * g * t, 1e-9) << t;
      EXPECT_NEAR(run.at(i, "w2"), 2.5 * mu * g / R * t, 1e-8) << t;
    } else {
      EXPECT_NEAR(run.at(i, "der(x1)"), 5.0 / 7.0 * u0, 1e-9) << t;
      EXPECT_NEAR(run.at(i, "slip"), 0.0, 1e-9) << t;
      EXPECT_NEAR(run.at(i, "lambda(table)"), 9.81, 1e-9) << t;
    }
  }
}

// Fig. 9.9: thrown with a spin ω0 = w E1 as well, the sphere's contact slips at v_P = (u0, w R, 0),
// not along v̄: the slip keeps its direction c (v̇_P = −(7/2) μ_d g c), so the friction −μ_d m g c is
// constant and the centre moves on a parabolic arc, x̄ = (u0 t, 0) − ½ μ_d g c t², until it rolls
// at T = 2 |v_P|/(7 μ_d g).
TEST(RollingSphere, SlidingCentreOnAParabolaOfFigure99) {
  const double g = 9.81, R = 0.1, mu = 0.2, u0 = 2.0, w = 10.0;
  const double slip = std::hypot(u0, w * R), cx = u0 / slip, cy = w * R / slip;
  const double T = 2 * slip / (7 * mu * g);
  // Q(0) = I: ė = ω/2
  const test::ModelRun run = test::run_model("sphere-slide-roll", {{"der(e1)", w / 2}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_NEAR(run.summary.phases[1].t, T, 1e-10);
  std::size_t sliding = 0;
  for (std::size_t i = 0; i < run.rows.size() && run.at(i, "t") < T; ++i, ++sliding) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "x1"), u0 * t - 0.5 * mu * g * cx * t * t, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "x2"), -0.5 * mu * g * cy * t * t, 1e-9) << t;
  }
  EXPECT_GT(sliding, 10u);
}

// (9.28) on a plane inclined at β: the slip speed u and its angle χ (v_P = u (cos χ E1 + sin χ E2))
// obey u̇ = −(7/2) μ_d g cos β + g sin β cos χ, u χ̇ = −g sin β sin χ — integrated here by RK4 from
// the run's start, steps of at most 1e-5 s — until the sphere rolls where u reaches 0. ⚠ The book
// prints u̇ without cos β; that equation misses the run's slip speed by far more than the
// integration's error.
TEST(RollingSphere, SlidingOnAnInclineFollowsEquation928) {
  const double g = 9.81, mu = 0.2, beta = 0.25, h_max = 1e-5;
  const test::ModelRun run =
      test::run_model("sphere-slide-roll", {{"beta", beta}, {"der(x1)", 1.0}, {"der(x2)", 1.5}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 2u);
  const double rolls = run.summary.phases[1].t;
  // RK4 of (u, χ) with the friction's normal m g cos β, or the printed m g
  const auto integrate = [&](double normal_factor, double until) {
    double u = std::hypot(1.0, 1.5), chi = std::atan2(1.5, 1.0);
    const auto rate = [&](double uu, double cc) {
      return std::pair{-3.5 * mu * g * normal_factor + g * std::sin(beta) * std::cos(cc),
                       -g * std::sin(beta) * std::sin(cc) / uu};
    };
    const int steps = std::max(1, int(std::ceil(until / h_max)));
    const double h = until / steps;
    for (int k = 0; k < steps; ++k) {
      const auto [a1, b1] = rate(u, chi);
      const auto [a2, b2] = rate(u + h / 2 * a1, chi + h / 2 * b1);
      const auto [a3, b3] = rate(u + h / 2 * a2, chi + h / 2 * b2);
      const auto [a4, b4] = rate(u + h * a3, chi + h * b3);
      u += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
      chi += h / 6 * (b1 + 2 * b2 + 2 * b3 + b4);
    }
    return std::pair{u, chi};
  };
  for (std::size_t i = 0; i < run.rows.size(); i += 5) {
    const double t = run.at(i, "t");
    if (t >= rolls || std::abs(t / 0.01 - std::round(t / 0.01)) > 1e-9) continue;
    const auto [u, chi] = integrate(std::cos(beta), t);
    const double s1 = run.at(i, "slip"), s2 = run.at(i, "slip2");
    EXPECT_NEAR(std::hypot(s1, s2), u, 1e-8) << t;
    EXPECT_NEAR(std::atan2(s2, s1), chi, 1e-8) << t;
  }
  // the sphere rolls where (9.28)'s u reaches 0, and the printed u̇ misses it
  EXPECT_NEAR(integrate(std::cos(beta), rolls).first, 0, 1e-6);
  const double at = 0.3;
  const auto [printed, unused] = integrate(1.0, at);
  const auto [corrected, unused2] = integrate(std::cos(beta), at);
  EXPECT_GT(std::abs(printed - corrected), 1e-2);
}

// Inside a pipe of radius R about E2, the centre at angle θ from the lowest line moves on a circle
// of radius R − r, and rolling (v̄ + ω × r n = 0 at the contact x̄ + r n) gives the sphere
// ω = (R − r) θ̇/r E2: T = ½ (7/5) m (R − r)² θ̇², so (7/5)(R − r) θ̈ = −g sin θ, integrated here by
// hand; the wall pushes with m g cos θ + m (R − r) θ̇² and the sphere stays in its plane.
TEST(RollingSphere, InsideAPipeAsItsReducedEquation) {
  const test::ModelRun run = test::run_model("sphere-in-pipe");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1, g = 9.81, r = 0.2, R = 1, rho = R - r;
  DormandPrinceOptions options;
  options.rtol = 1e-12;
  options.atol = 1e-14;
  DormandPrince54 reduced(
      [&](double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) {
        dydt << y[1], -5 * g / (7 * rho) * std::sin(y[0]);
      },
      options);
  std::vector<Eigen::VectorXd> expected;
  IntegrationCallbacks callbacks;
  callbacks.output = [&](double, const Eigen::VectorXd& y) { expected.push_back(y); };
  Eigen::VectorXd y0(2);
  y0 << 0.3, 0.0;
  ASSERT_TRUE(integrate(reduced, 0, y0, 3, 0.01, callbacks).ok);
  ASSERT_EQ(expected.size(), run.rows.size());
  double lowest = 1;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), theta = expected[i][0], rate = expected[i][1];
    EXPECT_NEAR(run.at(i, "theta"), theta, 1e-9) << t;
    EXPECT_NEAR(run.at(i, "w2"), rho * rate / r, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "wall_push"), m * g * std::cos(theta) + m * rho * rate * rate, 1e-8) << t;
    EXPECT_NEAR(run.at(i, "y"), 0.0, 1e-12) << t;
    lowest = std::min(lowest, std::abs(theta));
  }
  EXPECT_LT(lowest, 0.02);  // it swung through the bottom
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
}

// Exercise 10.4 redoes §9.8 in 3-1-3 angles (ψ, θ, φ): the sphere of sphere-incline.yaml with
// them in place of Euler parameters, given here as text (rough: v_P = 0; smooth but for Coulomb
// friction at the contact: the plane x3 = R alone).
std::string sphere_on_incline_313(const std::string& constraints, const std::string& initial) {
  return R"yaml(unidyn: 1
parameters: {m: 1.0, g: 9.81, R: 0.1, beta: 0.3, mu_d: 0.2, mu_s: 0.3}
coordinates: [x1, x2, x3, psi, theta, phi]
bodies:
  ball:
    mass: m
    inertia: {sphere: {radius: R}}
    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}
    center: [x1, x2, x3]
forces:
  - gravity: g*(sin(beta)*E1 - cos(beta)*E3)
constraints:
)yaml" + constraints +
         "initial: " + initial +
         "\nsimulate: {t_end: 2, output_step: 0.01, rtol: 1e-12}\noutputs:\n"
         "  vP1: dot(ball.velocity + cross(ball.omega, -R*E3), E1)\n"
         "  vP2: dot(ball.velocity + cross(ball.omega, -R*E3), E2)\n"
         "  Fc1: dot(ball.constraint_force, E1)\n"
         "  Mc1: dot(ball.constraint_moment, E1)\n  Mc2: dot(ball.constraint_moment, E2)\n"
         "  Mc3: dot(ball.constraint_moment, E3)\n";
}

// The book's slip velocities of Ex. 10.4(a), v_s1 = ẋ1 − R θ̇ sin ψ + R φ̇ sin θ cos ψ and
// v_s2 = ẋ2 + R θ̇ cos ψ + R φ̇ sin θ sin ψ, from a row of a run.
std::pair<double, double> book_slip_104(const test::ModelRun& run, std::size_t i, double R) {
  const double psi = run.at(i, "psi"), theta = run.at(i, "theta");
  const double dtheta = run.at(i, "der(theta)"), dphi = run.at(i, "der(phi)");
  return {run.at(i, "der(x1)") - R * dtheta * std::sin(psi) +
              R * dphi * std::sin(theta) * std::cos(psi),
          run.at(i, "der(x2)") + R * dtheta * std::cos(psi) +
              R * dphi * std::sin(theta) * std::sin(psi)};
}

// Exercise 10.4(a), (c), (d), (e), (f), rolling: (a) the rows v_P · E1, v_P · E2 (v_P = v̄ + ω × π_P
// (10.52), π_P = −R E3) of the 3-1-3 model are the book's v_s1, v_s2 and (d) its T is the book's
// (symbolically); (c) the rolling rows are not integrable (Frobenius, against the book). Rolling
// from ψ0 = 0.4, θ0 = π/2 at ẋ1 = 0.5 m/s with ω = ẋ1/R E2 (θ̇0 = (0.5/R) sin ψ0,
// φ̇0 = −(0.5/R) cos ψ0; all three angles then move): by (f) with v_s ≡ 0 the friction is
// F_f · E1 = −(2/7) m g sin β, F_f · E2 = 0, so x1 = 0.5 t + (5/14) g sin β t², x2 = 0, and the
// sphere turns about E2 by x1/R: cos θ = e3 · E3 = −sin ψ0 sin(x1/R). The run against these closed
// forms: x1, x2, θ, the multipliers λ(roll1) = F_f · E1, λ(roll2), λ(plane) = m g cos β, the
// run's M_c = Ḣ − M against −R E3 × F_c (c), and the book's v_s1, v_s2 recomputed from its rows
// (0).
TEST(RollingSphere, InclineIn313AnglesOfExercise104) {
  const System system = parse_model(
      sphere_on_incline_313(
          "  - {name: plane, position: x3 - R}\n"
          "  - {name: roll1, velocity: \"dot(ball.velocity + cross(ball.omega, -R*E3), E1)\"}\n"
          "  - {name: roll2, velocity: \"dot(ball.velocity + cross(ball.omega, -R*E3), E2)\"}\n",
          "{x3: R, psi: 0.4, theta: pi/2, der(x1): 0.5, der(theta): 0.5/R*sin(0.4), der(phi): "
          "-0.5/R*cos(0.4)}"),
      "sphere-incline-313.yaml");
  {
    const auto& q = system.coordinates();
    const auto at = [&](const char* name) { return q[*system.find_coordinate(name)]; };
    const Expr Rs = system.parameters[*system.find_parameter("R")].symbol;
    const Expr psi = at("psi").value, th = at("theta").value;
    const Expr dth = at("theta").rate, dphi = at("phi").rate;
    const Expr vs1 =
        at("x1").rate - Rs * dth * GiNaC::sin(psi) + Rs * dphi * GiNaC::sin(th) * GiNaC::cos(psi);
    const Expr vs2 =
        at("x2").rate + Rs * dth * GiNaC::cos(psi) + Rs * dphi * GiNaC::sin(th) * GiNaC::sin(psi);
    EXPECT_TRUE(simplify(system.constraints[1].expression - vs1).is_zero())
        << simplify(system.constraints[1].expression - vs1);
    EXPECT_TRUE(simplify(system.constraints[2].expression - vs2).is_zero())
        << simplify(system.constraints[2].expression - vs2);
    // (d)'s T = (m R²/5)(ψ̇² + θ̇² + φ̇² + 2 ψ̇ φ̇ cos θ) + (m/2)(ẋ1² + ẋ2² + ẋ3²)
    const Expr ms = system.parameters[*system.find_parameter("m")].symbol, dpsi = at("psi").rate;
    const Expr T = ms * Rs * Rs / 5 *
                       (dpsi * dpsi + dth * dth + dphi * dphi + 2 * dpsi * dphi * GiNaC::cos(th)) +
                   ms / 2 *
                       (at("x1").rate * at("x1").rate + at("x2").rate * at("x2").rate +
                        at("x3").rate * at("x3").rate);
    EXPECT_TRUE(simplify(lagrange_equations(system).kinetic_energy - T).is_zero());
    // (c): at least one rolling constraint is not integrable (here both are; the plane's is)
    EXPECT_TRUE(constraint_integrability(system, 0).integrable);
    EXPECT_FALSE(constraint_integrability(system, 1).integrable);
    EXPECT_FALSE(constraint_integrability(system, 2).integrable);
  }
  const test::ModelRun run = test::run_system(system);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1, g = 9.81, R = 0.1, beta = 0.3, v0 = 0.5, psi0 = 0.4;
  ASSERT_EQ(run.parameter("m"), m);
  ASSERT_EQ(run.parameter("R"), R);
  ASSERT_EQ(run.parameter("beta"), beta);
  double path_error = 0, angle_error = 0, load_error = 0, slip = 0, theta_range = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), x1 = v0 * t + 5.0 / 14.0 * g * std::sin(beta) * t * t;
    path_error =
        std::max({path_error, std::abs(run.at(i, "x1") - x1), std::abs(run.at(i, "x2")),
                  std::abs(run.at(i, "der(x1)") - v0 - 5.0 / 7.0 * g * std::sin(beta) * t)});
    angle_error = std::max(
        angle_error, std::abs(std::cos(run.at(i, "theta")) + std::sin(psi0) * std::sin(x1 / R)));
    theta_range = std::max(theta_range, std::abs(run.at(i, "theta") - std::acos(0.0)));
    load_error = std::max(
        {load_error, std::abs(run.at(i, "lambda(roll1)") + 2.0 / 7.0 * m * g * std::sin(beta)),
         std::abs(run.at(i, "lambda(roll2)")),
         std::abs(run.at(i, "lambda(plane)") - m * g * std::cos(beta)),
         // M_c = −R E3 × F_c = −R (F_f · E1) E2
         std::abs(run.at(i, "Mc2") - 2.0 / 7.0 * m * g * R * std::sin(beta)),
         std::abs(run.at(i, "Mc1")), std::abs(run.at(i, "Mc3"))});
    const auto [s1, s2] = book_slip_104(run, i, R);
    slip = std::max({slip, std::abs(s1), std::abs(s2)});
  }
  EXPECT_GT(theta_range, 0.3);  // θ swings through π/2 ± ψ0: all three angles move
  // a run at rtol 1e-12 over 2 s and ~50 rad of turning: ~1e-12
  EXPECT_LT(path_error, 1e-10);
  EXPECT_LT(angle_error, 1e-10);
  EXPECT_LT(load_error, 1e-10);
  EXPECT_LT(slip, 1e-10);
  EXPECT_LT(run.summary.energy_relative_drift, 1e-11);
  std::printf(
      "Ex. 10.4 rolling in 3-1-3: x1/x2/x1' %.3g, cos(theta) %.3g, F_c/M_c %.3g N (N m), book's "
      "v_s %.3g m/s off the closed forms\n",
      path_error, angle_error, load_error, slip);
}

// Exercise 10.4(b), (d), (f), sliding: with the plane x3 = R the only constraint and Coulomb
// friction (μ_d = 0.2) at the contact, the sphere of the 3-1-3 model thrown down the incline at
// u0 = 2 m/s without spin slides with F_f · E1 = −μ_d m g cos β, and the book's
// m v̇_s1 = (1 + 5/2) F_f · E1 + m g sin β, m v̇_s2 = (1 + 5/2) F_f · E2 give
// v_s1 = u0 − ((7/2) μ_d g cos β − g sin β) t, v_s2 = 0 until v_s1 = 0 at
// T = u0/((7/2) μ_d g cos β − g sin β); then it rolls, F_f · E1 = −(2/7) m g sin β (within
// μ_s m g cos β) and ẋ1 grows at (5/7) g sin β from ẋ1(T) = u0 + (g sin β − μ_d g cos β) T. The
// book's v_s1, v_s2 recomputed from the run's rows and its ẋ1, F_c · E1, normal force and
// M_c = Ḣ − M against these (M_c = −R E3 × F_c, (b)).
TEST(RollingSphere, SlidingThenRollingOnTheInclineIn313AnglesOfExercise104f) {
  const test::ModelRun run = test::run_system(parse_model(
      sphere_on_incline_313("  - name: plane\n    position: x3 - R\n    friction: {on: ball, at: "
                            "ball.center - R*E3, dynamic: mu_d, static: mu_s}\n",
                            "{x3: R, psi: 0.4, theta: pi/2, der(x1): 2.0}"),
      "sphere-slide-313.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m = 1, g = 9.81, R = 0.1, beta = 0.3, mu = 0.2, u0 = 2.0;
  ASSERT_EQ(run.parameter("mu_d"), mu);
  const double slowing = 3.5 * mu * g * std::cos(beta) - g * std::sin(beta), T = u0 / slowing;
  const double vT = u0 + (g * std::sin(beta) - mu * g * std::cos(beta)) * T;
  ASSERT_EQ(run.summary.phases.size(), 2u);
  EXPECT_EQ(run.summary.phases[1].what, "contact 'plane' sticks");
  EXPECT_NEAR(run.summary.phases[1].t, T, 1e-10);
  double slip_error = 0, speed_error = 0, force_error = 0;
  std::size_t sliding = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const auto [s1, s2] = book_slip_104(run, i, R);
    const bool slides = t < T - 1e-9;
    if (t > T - 1e-9 && t < T + 1e-9) continue;  // the switch's own row
    sliding += slides;
    slip_error = std::max({slip_error, std::abs(s1 - (slides ? u0 - slowing * t : 0.0)),
                           std::abs(s2), std::abs(run.at(i, "vP1") - s1)});
    speed_error = std::max(
        speed_error, std::abs(run.at(i, "der(x1)") -
                              (slides ? u0 + (g * std::sin(beta) - mu * g * std::cos(beta)) * t
                                      : vT + 5.0 / 7.0 * g * std::sin(beta) * (t - T))));
    const double friction =
        slides ? -mu * m * g * std::cos(beta) : -2.0 / 7.0 * m * g * std::sin(beta);
    force_error = std::max({force_error, std::abs(run.at(i, "Fc1") - friction),
                            std::abs(run.at(i, "lambda(plane)") - m * g * std::cos(beta)),
                            // M_c = −R E3 × F_c = −R (F_f · E1) E2
                            std::abs(run.at(i, "Mc2") + R * friction), std::abs(run.at(i, "Mc1")),
                            std::abs(run.at(i, "Mc3"))});
  }
  EXPECT_GT(sliding, 20u);
  // a run at rtol 1e-12 and the switch located to ~1e-12 s
  EXPECT_LT(slip_error, 1e-10);
  EXPECT_LT(speed_error, 1e-10);
  EXPECT_LT(force_error, 1e-10);
  std::printf(
      "Ex. 10.4(f) sliding then rolling in 3-1-3: rolls at T = %.6f s; book's v_s %.3g m/s, x1' "
      "%.3g m/s, F_f/N/M_c %.3g N (N m) off the closed forms\n",
      T, slip_error, speed_error, force_error);
}

}  // namespace
}  // namespace unidyn
