// Exercise 3.4: a particle held at rest on a rough moving surface q3 = d(t) by static friction
// (models/rough-moving-surface.yaml), in coordinates whose bases a_1 = E1 + (q1 + q2) E3,
// a_2 = E2 + q1 E3, a_3 = E3 are not orthogonal. (b) F_c = F_f^1 a_1 + F_f^2 a_2 + N a^3 with N
// the constraint's multiplier, and its covariant components λ_i = F_c · a_i are
// [[a11, a12, 0], [a12, a22, 0], [a13, a23, 1]] [F_f^1, F_f^2, N]; (c) E is not conserved: it
// changes by the work of F_c, the surface's. Against oracles: F_c at rest against the closed form
// m (d̈ + g) E3 + K r, and (a) the particle sliding on the moving surface against Cartesian
// equations with Coulomb friction on v_rel, integrated by RK4 in this file.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include <Eigen/Dense>

#include "support/model_run.hpp"
#include "support/rk4.hpp"

namespace unidyn {
namespace {

using V = Eigen::Vector3d;

TEST(RoughMovingSurface, AtRestOnItFrictionNormalForceAndWork) {
  const test::ModelRun run = test::run_model("rough-moving-surface", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what, "contact 'surface' sticks");
  const std::vector<double> work = test::running_integral(run, "power");
  double largest_friction = 0;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t"), q1 = run.at(i, "q1"), q2 = run.at(i, "q2");
    // at rest on the surface
    EXPECT_NEAR(q1, 0.3, 1e-10) << t;
    EXPECT_NEAR(q2, -0.2, 1e-10) << t;
    const V a1(1, 0, q1 + q2), a2(0, 1, q1), a3(0, 0, 1);
    // a^3 = grad q3 = −(q1 + q2) E1 − q1 E2 + E3, with a^3 · a_1 = a^3 · a_2 = 0, a^3 · a_3 = 1
    const V upper3(-(q1 + q2), -q1, 1);
    const V F(run.at(i, "Fc.x"), run.at(i, "Fc.y"), run.at(i, "Fc.z"));
    Eigen::Matrix3d basis;
    basis << a1, a2, upper3;
    const V parts = basis.fullPivLu().solve(F);  // F_f^1, F_f^2, N
    EXPECT_NEAR(parts[2], run.at(i, "lambda(surface)"), 1e-9) << t;
    Eigen::Matrix3d metric;
    metric << a1.dot(a1), a1.dot(a2), 0, a1.dot(a2), a2.dot(a2), 0, a1.dot(a3), a2.dot(a3), 1;
    const V covariant(F.dot(a1), F.dot(a2), F.dot(a3));
    EXPECT_LT((covariant - metric * parts).norm(), 1e-12 * (1 + F.norm())) << t;
    largest_friction = std::max(largest_friction, std::hypot(parts[0], parts[1]));
    if (i % 2 == 0) {
      EXPECT_NEAR(run.at(i, "energy") - run.at(0, "energy"), work[i], 1e-9) << t;
    }
  }
  EXPECT_GT(largest_friction, 0.1) << "friction must hold it for the test to mean anything";
  EXPECT_GT(std::abs(run.summary.energy_final - run.summary.energy_initial), 0.05);
}

// The surface z = x²/2 + x y + d(t), d = A sin ωt, as the test writes it, and the applied forces
// of the model (gravity −m g E3, a spring of stiffness K and rest length 0 from the origin).
struct MovingSurface {
  double m, g, K, A, w;
  double d(double t) const { return A * std::sin(w * t); }
  double d_rate(double t) const { return A * w * std::cos(w * t); }
  double d_acceleration(double t) const { return -A * w * w * std::sin(w * t); }
  static MovingSurface of(const test::ModelRun& run) {
    return {run.parameter("m"), run.parameter("g"), run.parameter("K"), run.parameter("A"),
            run.parameter("w")};
  }
};

// Ex. 3.4(b) by hand: F_c = F_f^1 a_1 + F_f^2 a_2 + N a^3 with a_1 = E1 + (x + y) E3,
// a_2 = E2 + x E3, a^3 = −(x + y) E1 − x E2 + E3. Its components are
// (F_f^1 − N s, F_f^2 − N x, s F_f^1 + x F_f^2 + N) with s = x + y, so
// N = (F_z − s F_x − x F_y)/(1 + s² + x²) = F_c · a^3/|a^3|², F_f^1 = F_x + N s, F_f^2 = F_y + N x.
V parts_by_hand(double x, double y, const V& F) {
  const double s = x + y;
  const double N = (F.z() - s * F.x() - x * F.y()) / (1 + s * s + x * x);
  return {F.x() + N * s, F.y() + N * x, N};
}

// Ex. 3.4(b), (c): held at rest on the surface at (x, y) = (0.3, −0.2) its acceleration is d̈ E3, so
// F_c = m a − F = m (d̈ + g) E3 + K r with r = x E1 + y E2 + (x²/2 + x y + d) E3 (the book's
// m(d̈ + g) E3 plus the spring this model adds). Against this closed form: the run's F_c, its
// multiplier N (the parts of the closed form by hand, above), the book's matrix
// [λ_i] = [[a11, a12, 0], [a12, a22, 0], [a13, a23, 1]] [F_f^1, F_f^2, N] with λ_i = F_c · a_i of
// the run, Coulomb's static bound |F_f| ≤ μ_s |N a^3| that lets it stick, and the energy
// E = m ḋ²/2 + m g z + K |r|²/2 of the particle carried by the surface, which is not constant (c).
TEST(RoughMovingSurface, AtRestConstraintForceAndEnergyAgreeWithClosedForm) {
  const test::ModelRun run = test::run_model("rough-moving-surface", {}, {}, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what, "contact 'surface' sticks");
  const MovingSurface S = MovingSurface::of(run);
  const double mu_s = run.parameter("mu_s");
  const double x = 0.3, y = -0.2;  // the model's initial q1, q2
  double force_error = 0, normal_error = 0, matrix_error = 0, energy_error = 0, ratio = 0;
  double energy_min = 1e300, energy_max = -1e300;
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double t = run.at(i, "t");
    EXPECT_NEAR(run.at(i, "q3"), S.d(t), 1e-10) << t;
    const double z = x * x / 2 + x * y + S.d(t);
    const V closed(S.K * x, S.K * y, S.m * (S.d_acceleration(t) + S.g) + S.K * z);
    const V F(run.at(i, "Fc.x"), run.at(i, "Fc.y"), run.at(i, "Fc.z"));
    force_error = std::max(force_error, (F - closed).norm());
    const V parts = parts_by_hand(x, y, closed);  // F_f^1, F_f^2, N of the closed form
    normal_error = std::max(normal_error, std::abs(run.at(i, "lambda(surface)") - parts[2]));
    const V a1(1, 0, x + y), a2(0, 1, x), a3(0, 0, 1), upper3(-(x + y), -x, 1);
    Eigen::Matrix3d book;
    book << a1.dot(a1), a1.dot(a2), 0, a1.dot(a2), a2.dot(a2), 0, a1.dot(a3), a2.dot(a3), 1;
    const V covariant(F.dot(a1), F.dot(a2), F.dot(a3));
    matrix_error = std::max(matrix_error, (covariant - book * parts).norm());
    const V friction = parts[0] * a1 + parts[1] * a2;
    ratio = std::max(ratio, friction.norm() / (mu_s * std::abs(parts[2]) * upper3.norm()));
    const double rate = S.d_rate(t);
    const double E = S.m * rate * rate / 2 + S.m * S.g * z + S.K * (x * x + y * y + z * z) / 2;
    energy_error = std::max(energy_error, std::abs(run.at(i, "energy") - E));
    energy_min = std::min(energy_min, E);
    energy_max = std::max(energy_max, E);
  }
  // the closed forms are exact: only the run's error (rtol 1e-12) remains
  EXPECT_LT(force_error, 1e-8);
  EXPECT_LT(normal_error, 1e-8);
  EXPECT_LT(matrix_error, 1e-8);
  EXPECT_LT(energy_error, 1e-9);
  EXPECT_LT(ratio, 1.0) << "static friction must be able to hold it";
  EXPECT_GT(ratio, 0.05) << "friction must hold it for the test to mean anything";
  EXPECT_GT(energy_max - energy_min, 0.05) << "(c): E is not conserved";
  std::printf(
      "at rest vs closed form over 3 s: F_c %.3g N, N %.3g N, (3.4b) matrix %.3g N, E %.3g J; "
      "max |F_f|/(mu_s |N a^3|) = %.3f; E varies by %.3f J\n",
      force_error, normal_error, matrix_error, energy_error, ratio, energy_max - energy_min);
}

// Ex. 3.4(a) sliding, by hand in Cartesian coordinates: with z = x²/2 + x y + d(t) the state is
// (x, y, ẋ, ẏ); the surface's normal is n = a^3 = −(x + y) E1 − x E2 + E3, the velocity relative
// to the surface v_rel = ẋ a_1 + ẏ a_2 = (ẋ, ẏ, (x + y) ẋ + x ẏ) (tangent: n · v_rel = 0), and
// F_c = N n − μ_d |N| |n| v_rel/|v_rel|. Differentiating the constraint twice,
// n · r̈ = ẋ² + 2 ẋ ẏ + d̈, and n · F_f = 0, so m (ẋ² + 2 ẋ ẏ + d̈) = n · F_a + N |n|² gives N;
// then r̈ = (F_a + N n + F_f)/m with F_a = −m g E3 − K r.
using SlideState = std::array<double, 4>;

struct Slide {
  double z, N;
  V Fc, rdd;
};

Slide slide(double t, const SlideState& s, const MovingSurface& S, double mu_d) {
  const double x = s[0], y = s[1], xd = s[2], yd = s[3];
  const double z = x * x / 2 + x * y + S.d(t);
  const V n(-(x + y), -x, 1);
  const V v_rel(xd, yd, (x + y) * xd + x * yd);
  const V Fa = -S.m * S.g * V(0, 0, 1) - S.K * V(x, y, z);
  const double N =
      (S.m * (xd * xd + 2 * xd * yd + S.d_acceleration(t)) - n.dot(Fa)) / n.squaredNorm();
  const V Fc = N * n - mu_d * std::abs(N) * n.norm() * v_rel / v_rel.norm();
  return {z, N, Fc, (Fa + Fc) / S.m};
}

SlideState slide_rates(double t, const SlideState& s, const MovingSurface& S, double mu_d) {
  const V rdd = slide(t, s, S, mu_d).rdd;
  return {s[2], s[3], rdd.x(), rdd.y()};
}

// Ex. 3.4(a): the particle SLIDING on the moving surface (μ_s = μ_d = 0.1, thrown at
// (q̇1, q̇2) = (−2, 1) m/s from the model's start), against the Cartesian equations above
// integrated here by RK4: the coordinates q1 = x, q2 = y, q3 = z − x²/2 − x y = d(t), their rates,
// the multiplier N and the run's F_c. The oracle's |v_rel| stays well above 0 (no sticking).
TEST(RoughMovingSurface, SlidingMotionNormalForceAndFrictionAgreeWithCartesianRk4) {
  const double v1 = -2.0, v2 = 1.0;
  const test::ModelRun run = test::run_model(
      "rough-moving-surface", {{"mu_d", 0.1}, {"mu_s", 0.1}, {"der(q1)", v1}, {"der(q2)", v2}},
      [](SimulationOptions& o) { o.t_end = 2; }, true);
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  ASSERT_EQ(run.summary.phases.size(), 1u);
  EXPECT_EQ(run.summary.phases[0].what, "'surface' slides");
  const MovingSurface S = MovingSurface::of(run);
  const double mu_d = 0.1;  // as set above (run.parameter gives the file's value)
  SlideState s{0.3, -0.2, v1, v2};
  double t = 0, position_error = 0, rate_error = 0, normal_error = 0, force_error = 0;
  double slip_min = 1e300, travelled = 0;
  for (std::size_t k = 0; k < run.rows.size(); ++k) {
    const double t1 = run.at(k, "t");
    if (t1 > t) {
      const double x0 = s[0], y0 = s[1];
      s = test::rk4(s, t, t1, 10,
                    [&](double tau, const SlideState& q) { return slide_rates(tau, q, S, mu_d); });
      travelled += std::hypot(s[0] - x0, s[1] - y0);
      t = t1;
    }
    const Slide o = slide(t, s, S, mu_d);
    const double q3 = o.z - s[0] * s[0] / 2 - s[0] * s[1];
    position_error = std::max({position_error, std::abs(run.at(k, "q1") - s[0]),
                               std::abs(run.at(k, "q2") - s[1]), std::abs(run.at(k, "q3") - q3)});
    rate_error = std::max({rate_error, std::abs(run.at(k, "der(q1)") - s[2]),
                           std::abs(run.at(k, "der(q2)") - s[3]),
                           std::abs(run.at(k, "der(q3)") - S.d_rate(t))});
    normal_error = std::max(normal_error, std::abs(run.at(k, "lambda(surface)") - o.N));
    const V F(run.at(k, "Fc.x"), run.at(k, "Fc.y"), run.at(k, "Fc.z"));
    force_error = std::max(force_error, (F - o.Fc).norm());
    slip_min = std::min(slip_min, V(s[2], s[3], (s[0] + s[1]) * s[2] + s[0] * s[3]).norm());
  }
  // RK4 at h = 5e-4 s (error ~1e-11) against a run at rtol 1e-12 over 2 s
  EXPECT_LT(position_error, 1e-8);
  EXPECT_LT(rate_error, 1e-8);
  EXPECT_LT(normal_error, 1e-8);
  EXPECT_LT(force_error, 1e-8);
  EXPECT_GT(slip_min, 0.1) << "it must slide throughout";
  EXPECT_GT(travelled, 0.5);
  std::printf(
      "sliding vs Cartesian RK4 over 2 s: q %.3g, q' %.3g, N %.3g N, F_c %.3g N; min |v_rel| "
      "%.3f m/s, path %.3f m\n",
      position_error, rate_error, normal_error, force_error, slip_min, travelled);
}

}  // namespace
}  // namespace unidyn
