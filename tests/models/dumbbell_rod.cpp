// Two particles joined by a rigid rod orbiting a planet (§5.3 with a rod, §4.3–4.5): the rod's
// forces (4.3) against closed forms of the tension, spinning freely and on the orbit.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/analysis/equilibria.hpp"

namespace unidyn {
namespace {

// (4.3): the rod's forces on its ends are equal and opposite and along the rod (F_c1 = −F_c2 =
// −μ t), so they do no net work and no net moment: E and H_O are conserved; the rod keeps its
// length.
TEST(DumbbellRod, RodForcesEqualOppositeAlongTheRod) {
  const test::ModelRun run = test::run_model("dumbbell-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  double largest = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    EXPECT_NEAR(run.at(i, "length"), 0.012, 1e-12);
    for (const char* c : {".x", ".y", ".z"}) {
      const double F1 = run.at(i, std::string("F1") + c), F2 = run.at(i, std::string("F2") + c);
      EXPECT_NEAR(F1 + F2, 0.0, 1e-18);
      largest = std::max(largest, std::abs(F1));
    }
    EXPECT_NEAR(run.at(i, "F1_across"), 0.0, 1e-18);
  }
  EXPECT_GT(largest, 1e-6);  // the rod does pull
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  ASSERT_EQ(run.summary.conserved_drift.size(), 3u);
  for (const auto& c : run.summary.conserved_drift) {
    EXPECT_LT(c.max_change, 1e-10 * std::abs(run.summary.conserved_drift[2].initial)) << c.name;
  }
}

// The rod's force from the state alone, derived here: with x = r2 − r1, |x| = L, the rod's
// forces F_c1 = −μ t, F_c2 = μ t (4.3), t = x/|x|, and the applied forces F1, F2,
//   ẍ = F2/m2 − F1/m1 + μ (1/m1 + 1/m2) t,
// and the rod twice differentiated, x·ẍ + |ẋ|² = 0, give (μ_r = m1m2/(m1 + m2))
//   μ = −μ_r (|ẋ|² + x·(F2/m2 − F1/m1)) / |x|.
// μ < 0 when the rod pulls the particles together (F_c1 = −μ t points from m1 towards m2).
double rod_mu(const Vec3& x, const Vec3& xdot, const Vec3& relative_applied_acceleration, double m1,
              double m2) {
  const double reduced = m1 * m2 / (m1 + m2);
  return -reduced * (xdot.squaredNorm() + x.dot(relative_applied_acceleration)) / x.norm();
}

struct RodRow {
  Vec3 r1, r2, v1, v2, F1;
  double lambda;
};

RodRow rod_row(const test::ModelRun& run, std::size_t i) {
  return {Vec3(run.at(i, "x1"), run.at(i, "y1"), run.at(i, "z1")),
          Vec3(run.at(i, "x2"), run.at(i, "y2"), run.at(i, "z2")),
          Vec3(run.at(i, "der(x1)"), run.at(i, "der(y1)"), run.at(i, "der(z1)")),
          Vec3(run.at(i, "der(x2)"), run.at(i, "der(y2)"), run.at(i, "der(z2)")),
          Vec3(run.at(i, "F1.x"), run.at(i, "F1.y"), run.at(i, "F1.z")),
          run.at(i, "lambda(rod)")};
}

// (4.3)–(4.4) with the tension's value: the dumbbell of models/dumbbell-rod.yaml with the planet
// switched off (G = 0) spins freely at the model's ω = 0.8 rad/s about E3 (relative velocity
// 0.8 L (−sin 0.4, cos 0.4, 0)) while C moves uniformly. Each mass circles C, at m2 L/(m1 + m2)
// and m1 L/(m1 + m2), so the rod pulls each towards the other with
//   |F_c| = (m1m2/(m1 + m2)) L ω²,   F_c1 = −F_c2 = +|F_c| t,
// i.e. μ = −(m1m2/(m1 + m2)) L ω² in (4.3), and the model's multiplier (Ψ = |x|² − L², ∂Ψ/∂r1 =
// −2x = −2L t) is λ = μ/(2L) = −(m1m2/(m1 + m2)) ω²/2. Compared with: the F1, F2 columns and
// lambda(rod), and the positions with the closed-form motion r1,2 = r̄0 + v̄0 t ∓ (m2, m1)/(m1 +
// m2) L (cos(0.4 + ωt), sin(0.4 + ωt), 0).
TEST(DumbbellRod, FreeSpinningRodTensionIsReducedMassTimesLOmegaSquared) {
  const test::ModelRun run = test::run_model("dumbbell-rod", {{"G", 0.0}});
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m1 = run.parameter("m1"), m2 = run.parameter("m2"), L = run.parameter("L");
  const double m = m1 + m2, reduced = m1 * m2 / m, omega = 0.8;
  const RodRow start = rod_row(run, 0);
  // the model's start is that spin
  ASSERT_NEAR((start.r2 - start.r1).cross(start.v2 - start.v1).z() / (L * L), omega, 1e-14);
  const Vec3 c0 = (m1 * start.r1 + m2 * start.r2) / m, u0 = (m1 * start.v1 + m2 * start.v2) / m;
  const double tension = reduced * L * omega * omega, lambda = -reduced * omega * omega / 2;
  double force_error = 0, lambda_error = 0, position_error = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    const RodRow row = rod_row(run, i);
    const Vec3 e(std::cos(0.4 + omega * t), std::sin(0.4 + omega * t), 0.0);
    const Vec3 c = c0 + u0 * t;
    position_error = std::max({position_error, (row.r1 - (c - m2 / m * L * e)).norm(),
                               (row.r2 - (c + m1 / m * L * e)).norm()});
    const Vec3 F2(run.at(i, "F2.x"), run.at(i, "F2.y"), run.at(i, "F2.z"));
    const Vec3 t_hat = (row.r2 - row.r1).normalized();
    force_error =
        std::max({force_error, (row.F1 - tension * t_hat).norm(), (F2 + tension * t_hat).norm()});
    lambda_error = std::max(lambda_error, std::abs(row.lambda - lambda));
  }
  std::printf(
      "Free dumbbell, |F_c| = (m1m2/(m1 + m2)) L ω² = %.6g: force error %.3g (relative), lambda "
      "%.3g (relative), positions against the uniform spin %.3g m over %g s\n",
      tension, force_error / tension, lambda_error / std::abs(lambda), position_error,
      run.rows.back()[0]);
  // the run's state keeps |x| = L and ω to its rtol 1e-12; μ is evaluated at that state
  EXPECT_LT(force_error / tension, 1e-10);
  EXPECT_LT(lambda_error / std::abs(lambda), 1e-10);
  // the global error at rtol 1e-12 over 20 s, ~2.5 turns
  EXPECT_LT(position_error, 1e-10);
}

// (4.3) on the orbit of models/dumbbell-rod.yaml: the rod's force at every row against μ above,
// computed here from the row's positions and velocities with the planet's pulls
// F_i/m_i = −GM r_i/|r_i|³ (the tidal part x·(F2/m2 − F1/m1) changes along the orbit and is up
// to ~35 times the spin part |ẋ|², so μ is far from the free value): F_c1 = −μ t against the F1
// column, F_c2 = μ t against F2, and the multiplier λ = μ/(2L).
TEST(DumbbellRod, RodForceOnTheOrbitMatchesTheClosedForm) {
  const test::ModelRun run = test::run_model("dumbbell-rod");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const double m1 = run.parameter("m1"), m2 = run.parameter("m2"),
               GM = run.parameter("G") * run.parameter("M");
  const auto pull = [&](const Vec3& r) -> Vec3 { return -GM * r / std::pow(r.norm(), 3); };
  double force_error = 0, lambda_error = 0, smallest = INFINITY, largest = 0, tidal = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const RodRow row = rod_row(run, i);
    const Vec3 x = row.r2 - row.r1, xdot = row.v2 - row.v1;
    const double mu = rod_mu(x, xdot, pull(row.r2) - pull(row.r1), m1, m2);
    const Vec3 F2(run.at(i, "F2.x"), run.at(i, "F2.y"), run.at(i, "F2.z"));
    const Vec3 t_hat = x.normalized();
    force_error = std::max({force_error, (row.F1 + mu * t_hat).norm() / std::abs(mu),
                            (F2 - mu * t_hat).norm() / std::abs(mu)});
    lambda_error = std::max(
        lambda_error, std::abs(row.lambda - mu / (2 * x.norm())) / std::abs(mu / (2 * x.norm())));
    smallest = std::min(smallest, std::abs(mu));
    largest = std::max(largest, std::abs(mu));
    tidal = std::max(tidal, std::abs(x.dot(pull(row.r2) - pull(row.r1))) / xdot.squaredNorm());
  }
  std::printf(
      "Orbiting dumbbell: |μ| from %.4g to %.4g N (tidal/spin part up to %.3g); force error %.3g, "
      "lambda %.3g (relative)\n",
      smallest, largest, tidal, force_error, lambda_error);
  // μ from the row's state against the solver's at the same state: round-off and the constraint
  // drift of the run (|Ψ| ~ 1e-18)
  EXPECT_LT(force_error, 1e-10);
  EXPECT_LT(lambda_error, 1e-10);
  EXPECT_GT(largest - smallest, 0.1 * largest);  // μ does vary along the orbit
}

// Ex. 5.5 (Fig. 5.9, potential (5.15)): the rod satellite with C = R e_r(θ) + z E3 (cylindrical)
// and the rod along u = sin β (cos α e_r(θ) + sin α e_θ(θ)) + cos β E3, m1 at C − (m2/m) L u, m2 at
// C + (m1/m) L u (m = m1 + m2). θ is cyclic: a uniform circle of C about E3 is a steady motion at
// θ̇ = ω with R, z, α, β constant.
const char* const kSatellite = R"yaml(unidyn: 1
parameters: {G: 1.0, M: 1.0, m1: 0.001, m2: 0.002, L: 0.012}
coordinates: [R, theta, z, alpha, beta]
particles:
  O: {mass: M, position: [0, 0, 0]}
  P1: {mass: m1, position: "R*[cos(theta), sin(theta), 0] + [0, 0, z] - m2/(m1 + m2)*L*(sin(beta)*(cos(alpha)*[cos(theta), sin(theta), 0] + sin(alpha)*[-sin(theta), cos(theta), 0]) + cos(beta)*[0, 0, 1])"}
  P2: {mass: m2, position: "R*[cos(theta), sin(theta), 0] + [0, 0, z] + m1/(m1 + m2)*L*(sin(beta)*(cos(alpha)*[cos(theta), sin(theta), 0] + sin(alpha)*[-sin(theta), cos(theta), 0]) + cos(beta)*[0, 0, 1])"}
forces:
  - gravitation: {between: [O, P1], G: G}
  - gravitation: {between: [O, P2], G: G}
  - gravitation: {between: [P1, P2], G: G}
initial: {R: 1, beta: 1.5707963267948966}
)yaml";

// The circles of Ex. 5.5(f) derived here (GM = G M): C moves uniformly (ω) on a circle about the
// E3 axis with the rod's attitude fixed in the turning frame iff each mass's pull and its
// centrifugal force, F_i = m_i (ω² P r_i − GM r_i/|r_i|³) (P the projection on the orbit's
// plane), are held by the rod's forces alone: F1 + F2 = 0 and F1 ∥ u (the rod's force on m1 is
// −F1 = μ u; the masses' own attraction in (5.15) is along u as well). With C in the plane:
//   (i) the rod radial, u = σ e, e = C/|C|, ρ1 = R − σ a1, ρ2 = R + σ a2 (a1 = m2 L/m,
//       a2 = m1 L/m): ω² m R = GM (m1/ρ1² + m2/ρ2²), the rod in tension;
//   (ii) F1 = F2 = 0: each mass on its own circular Kepler orbit of radius d = (GM/ω²)^{1/3}, the
//       rod a chord of it, doing nothing; then |C|² = d² − L²/4 + ((m2 − m1) L/(2m))² and
//       u · e = (m2 − m1) L/(2 m |C|) (for m1 = m2 the rod is along the track);
//   (iii) for m1 = m2 only, u = ±E3 normal to the plane, d = (GM/ω²)^{1/3}, the rod in
//       compression. For m1 ≠ m2 a nearby steady motion has the rod tilted from E3 and C off the
//       plane through O (found by the search below; its circle is about the axis, not about O).
struct SatelliteCircle {
  Vec3 r1, r2;  // turned about E3 so that C is in the E1–E3 half plane x > 0
  Vec3 F1, F2;  // the pull and centrifugal force on each
};

SatelliteCircle satellite_circle(const Vec3& r1, const Vec3& r2, double omega, double m1, double m2,
                                 double GM) {
  const double m = m1 + m2;
  const Vec3 c = (m1 * r1 + m2 * r2) / m;
  const double turn = -std::atan2(c.y(), c.x());
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(turn, Vec3::UnitZ()).toRotationMatrix();
  const auto force = [&](const Vec3& r, double mass) -> Vec3 {
    return mass * (omega * omega * Vec3(r.x(), r.y(), 0) - GM * r / std::pow(r.norm(), 3));
  };
  return {Q * r1, Q * r2, Q * force(r1, m1), Q * force(r2, m2)};
}

// R of circle (i) by bisection on (L, 10): σ = +1 with m2 outside, −1 with m1 outside.
double radial_circle(double sigma, double omega, double m1, double m2, double L, double GM) {
  const double m = m1 + m2, a1 = m2 * L / m, a2 = m1 * L / m;
  const auto f = [&](double R) {
    return omega * omega * m * R -
           GM * (m1 / std::pow(R - sigma * a1, 2) + m2 / std::pow(R + sigma * a2, 2));
  };
  double lo = L, hi = 10;
  for (int k = 0; k < 200; ++k) ((f((lo + hi) / 2) < 0) ? lo : hi) = (lo + hi) / 2;
  return (lo + hi) / 2;
}

// Ex. 5.5(f) with the search for steady motions (θ cyclic, θ̇ = ω = 1, 0.8; the model's masses
// m1 = 0.001, m2 = 0.002, L = 0.012): every solution found satisfies the balance above, and the
// distinct ones (C turned onto E1; the chart's doubles (α + π, −β), R < 0 counted once) are six:
// the two radial circles (i) at the R typed above, the two chords (ii) with |r1| = |r2| = d, their
// |C| and tilt u · e as above and no rod force, and the two near-normal ones (iii′), the rod in
// compression, C off the plane through O.
TEST(DumbbellRod, UniformCirclesOfExercise55fBySearch) {
  const System system = parse_model(kSatellite, "satellite.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  const std::vector<double> parameters = initial_state(system, {}).parameters;
  const double m1 = 0.001, m2 = 0.002, L = 0.012, GM = 1.0, m = m1 + m2;
  for (const double omega : {1.0, 0.8}) {
    const EquilibriumSearchResult result = find_equilibria(
        system, compiled, parse_given_values(system, {"der(theta)=" + std::to_string(omega)}, true),
        parameters, {.cyclic = {"theta"}});
    const double d = std::cbrt(GM / (omega * omega)), scale = m1 * GM / (d * d);
    double balance = 0, radial = 0, chord = 0;
    std::vector<SatelliteCircle> distinct;
    int radials[2] = {0, 0}, chords = 0, normals = 0;
    for (const Equilibrium& e : result.equilibria) {
      const double R = e.point.q[0], th = e.point.q[1], z = e.point.q[2], al = e.point.q[3],
                   be = e.point.q[4];
      ASSERT_NEAR(e.point.qdot[1], omega, 1e-12);
      const Vec3 er(std::cos(th), std::sin(th), 0), et(-std::sin(th), std::cos(th), 0);
      const Vec3 u =
          std::sin(be) * (std::cos(al) * er + std::sin(al) * et) + std::cos(be) * Vec3::UnitZ();
      const Vec3 c = R * er + z * Vec3::UnitZ();
      const SatelliteCircle s =
          satellite_circle(c - m2 / m * L * u, c + m1 / m * L * u, omega, m1, m2, GM);
      const Vec3 uu = (s.r2 - s.r1) / L;
      balance = std::max({balance, (s.F1 + s.F2).norm() / scale, s.F1.cross(uu).norm() / scale});
      bool known = false;
      for (const SatelliteCircle& other : distinct) {
        known = known || ((s.r1 - other.r1).norm() + (s.r2 - other.r2).norm() < 1e-7);
      }
      if (known) continue;
      distinct.push_back(s);
      const Vec3 cc = (m1 * s.r1 + m2 * s.r2) / m;
      const double rod_on_1 = -s.F1.dot(uu);                     // μ: > 0 pulls m1 towards m2
      if (std::abs(uu.y()) < 1e-9 && std::abs(uu.z()) < 1e-9) {  // (i)
        const double sigma = uu.x() > 0 ? 1 : -1;
        ++radials[sigma > 0 ? 0 : 1];
        radial = std::max(radial, std::abs(cc.x() - radial_circle(sigma, omega, m1, m2, L, GM)));
        EXPECT_GT(rod_on_1, 0.0);
      } else if (std::abs(uu.z()) < 1e-9) {  // (ii)
        ++chords;
        const double C = std::sqrt(d * d - L * L / 4 + std::pow((m2 - m1) * L / (2 * m), 2));
        chord =
            std::max({chord, std::abs(s.r1.norm() - d), std::abs(s.r2.norm() - d),
                      std::abs(cc.norm() - C), std::abs(uu.x() - (m2 - m1) * L / (2 * m * C)) * L});
        EXPECT_LT(s.F1.norm() / scale, 1e-9);
      } else {  // (iii′)
        ++normals;
        EXPECT_GT(std::abs(uu.z()), 0.99);
        EXPECT_LT(rod_on_1, 0.0);
        EXPECT_GT(std::abs(cc.z()), 1e-9);
        std::printf("  ω = %g: near-normal circle |C| = %.12g, z_C = %.3g, tilt from E3 %.3g rad\n",
                    omega, cc.x(), cc.z(), std::acos(std::abs(uu.z())));
      }
    }
    EXPECT_EQ(distinct.size(), 6u);
    EXPECT_EQ(radials[0], 1);
    EXPECT_EQ(radials[1], 1);
    EXPECT_EQ(chords, 2);
    EXPECT_EQ(normals, 2);
    // Newton's steps to 1e-12 on the steady equations; R and the tilt from the typed conditions
    EXPECT_LT(balance, 1e-9);
    EXPECT_LT(radial, 1e-10);
    EXPECT_LT(chord, 1e-10);
    std::printf(
        "Ex. 5.5(f), ω = %g: %zu found, %zu distinct; balance %.3g (of m1 GM/d²), radial R %.3g, "
        "chord %.3g\n",
        omega, result.equilibria.size(), distinct.size(), balance, radial, chord);
  }
}

// Ex. 5.5(f) in models/dumbbell-rod.yaml itself (Cartesian, the rod a constraint): started on the
// circles derived above at ω = 1 — (i) radial with m2 outside (over the model's 20 s, ~3 turns);
// (iii) for m1 = m2 = 0.0015, the rod along E3 (over 3 s: the attitude is unstable) — C stays at
// its |C| in the plane, turning at ω, the rod keeps its attitude in the turning frame, and the
// rod's force F1 on m1 is −F1 of the balance: tension (m1 ρ1 (GM/ρ1³ − ω²) towards m2) radially,
// compression m1 ω² L/2 along the normal.
TEST(DumbbellRod, UniformCirclesOfExercise55fInTheModel) {
  const double GM = 1.0, omega = 1.0, L = 0.012;
  struct Case {
    double m1, m2, t_end;
    bool normal;
  };
  for (const Case& k : {Case{0.001, 0.002, 20.0, false}, Case{0.0015, 0.0015, 3.0, true}}) {
    const double m = k.m1 + k.m2, a1 = k.m2 * L / m, a2 = k.m1 * L / m;
    const double d = std::cbrt(GM / (omega * omega));
    const double R =
        k.normal ? std::sqrt(d * d - L * L / 4) : radial_circle(1, omega, k.m1, k.m2, L, GM);
    const Vec3 r1 = k.normal ? Vec3(R, 0, -a1) : Vec3(R - a1, 0, 0);
    const Vec3 r2 = k.normal ? Vec3(R, 0, a2) : Vec3(R + a2, 0, 0);
    const test::ModelRun run = test::run_model("dumbbell-rod",
                                               {{"m1", k.m1},
                                                {"m2", k.m2},
                                                {"L", L},
                                                {"x1", r1.x()},
                                                {"y1", 0},
                                                {"z1", r1.z()},
                                                {"x2", r2.x()},
                                                {"y2", 0},
                                                {"z2", r2.z()},
                                                {"der(x1)", 0},
                                                {"der(y1)", omega * r1.x()},
                                                {"der(z1)", 0},
                                                {"der(x2)", 0},
                                                {"der(y2)", omega * r2.x()},
                                                {"der(z2)", 0}},
                                               [&](SimulationOptions& o) { o.t_end = k.t_end; });
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    const SatelliteCircle hand = satellite_circle(r1, r2, omega, k.m1, k.m2, GM);
    double circle = 0, attitude = 0, force = 0;
    for (std::size_t i = 0; i < run.rows.size(); ++i) {
      const double t = run.at(i, "t");
      const RodRow row = rod_row(run, i);
      const Eigen::Matrix3d back =
          Eigen::AngleAxisd(-omega * t, Vec3::UnitZ()).toRotationMatrix();  // to the turning frame
      const Vec3 c = back * (k.m1 * row.r1 + k.m2 * row.r2) / m;
      circle = std::max({circle, std::abs(c.x() - (k.m1 * r1.x() + k.m2 * r2.x()) / m),
                         std::abs(c.y()), std::abs(c.z())});
      attitude = std::max(attitude, (back * (row.r2 - row.r1) - (r2 - r1)).norm());
      force = std::max(force, (back * row.F1 + hand.F1).norm() / hand.F1.norm());
    }
    EXPECT_GT(hand.F1.norm(), 1e-7);
    if (k.normal) {
      EXPECT_NEAR(hand.F1.norm(), k.m1 * omega * omega * L / 2, 1e-12 * hand.F1.norm());
    }
    EXPECT_EQ(-hand.F1.dot(r2 - r1) > 0, !k.normal);  // tension radially, compression normally
    // the run at rtol 1e-12 (an unstable attitude for (iii): 3 s only)
    EXPECT_LT(circle, 1e-9);
    EXPECT_LT(attitude, 1e-9);
    EXPECT_LT(force, 1e-9);
    std::printf(
        "Ex. 5.5(f) in the model, %s circle |C| = %.12g over %g s: off the circle %.3g, attitude "
        "%.3g, rod force %.3g (relative; |F| = %.4g)\n",
        k.normal ? "normal (m1 = m2)" : "radial", R, k.t_end, circle, attitude, force,
        hand.F1.norm());
  }
}

}  // namespace
}  // namespace unidyn
