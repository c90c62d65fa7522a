// Exercise 10.6: the rigid satellite of §10.4 in the coordinates of satellite dynamics — the centre
// x̄ = R e_R by the radius R, the longitude θ about E3 and the latitude β, the rotation Q = Q2 Q1
// with Q1 the turn by θ about E3 and Q2 a 1-2-3 set about e_r, cos ν¹ e_θ + sin ν¹ E3 and e3
// (models/satellite-latitude-longitude.yaml). Everything below is typed from the exercise's text
// in the test: the kinematics (a)–(d), (10.53), T, MacCullagh's U (10.11), and the force and
// moment of (8.25).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

// u = (R, θ, β, ν¹, ν², ν³) and their rates, as Ex. 10.6(e) orders them.
using Coordinates = std::array<double, 6>;

struct Satellite {
  double m, GM;
  std::array<double, 3> lambda;  // principal moments along e1, e2, e3
};

const Vec3 kE3(0, 0, 1);

Vec3 e_r(const Coordinates& u) {
  return {std::cos(u[1]), std::sin(u[1]), 0};
}
Vec3 e_theta(const Coordinates& u) {
  return {-std::sin(u[1]), std::cos(u[1]), 0};
}
Vec3 e_R(const Coordinates& u) {
  return std::cos(u[2]) * e_r(u) + std::sin(u[2]) * kE3;
}
Vec3 e_beta(const Coordinates& u) {
  return std::cos(u[2]) * kE3 - std::sin(u[2]) * e_r(u);
}
Vec3 centre(const Coordinates& u) {
  return u[0] * e_R(u);
}

// Q2 as the exercise builds it: ν¹ counter-clockwise about e_r, then ν² about the turned e_θ
// (cos ν¹ e_θ + sin ν¹ E3), then ν³ about e3 = Q2 E3 (which the last turn leaves fixed); each turn
// is the book's L(φ, r) of (6.8) (support/oracles.hpp), not the code under test.
Tensor book_Q2(const Coordinates& u) {
  const Tensor A = test::book_L(u[3], e_r(u));
  const Tensor B = test::book_L(u[4], std::cos(u[3]) * e_theta(u) + std::sin(u[3]) * kE3);
  const Tensor C = test::book_L(u[5], B * A * kE3);
  return C * B * A;
}
// Q = Q2 Q1, Q1 = L(θ, E3).
Tensor book_Q(const Coordinates& u) {
  return book_Q2(u) * test::book_L(u[1], kE3);
}

// Ex. 10.6(a): v̄ = Ṙ e_R + R cos β θ̇ e_θ + R β̇ e_β.
Vec3 book_velocity(const Coordinates& u, const Coordinates& ud) {
  return ud[0] * e_R(u) + u[0] * std::cos(u[2]) * ud[1] * e_theta(u) + u[0] * ud[2] * e_beta(u);
}

// Ex. 10.6(d): ω = ω_i e_i, with the coefficient of θ̇ in ω_i kept apart (it is ∂ω_i/∂θ̇).
struct BodyRates {
  std::array<double, 3> omega, dtheta;
};
BodyRates book_body_rates(const Coordinates& u, const Coordinates& ud) {
  const double s1 = std::sin(u[3]), c1 = std::cos(u[3]), s2 = std::sin(u[4]), c2 = std::cos(u[4]),
               s3 = std::sin(u[5]), c3 = std::cos(u[5]);
  BodyRates r;
  r.dtheta = {s1 * s3 - c1 * s2 * c3, s1 * c3 + c1 * s2 * s3, c1 * c2};
  r.omega = {ud[1] * r.dtheta[0] + ud[4] * s3 + ud[3] * c2 * c3,
             ud[1] * r.dtheta[1] + ud[4] * c3 - ud[3] * c2 * s3,
             ud[1] * r.dtheta[2] + ud[3] * s2 + ud[5]};
  return r;
}

// T = ½ m v̄·v̄ + ½ Σ λ_i ω_i² from (a) and (d):
// T = m/2 (Ṙ² + R² cos²β θ̇² + R² β̇²) + ½ Σ λ_i ω_i².
double book_T(const Satellite& s, const Coordinates& u, const Coordinates& ud) {
  const BodyRates w = book_body_rates(u, ud);
  double T = 0.5 * s.m * book_velocity(u, ud).squaredNorm();
  for (int i = 0; i < 3; ++i) T += 0.5 * s.lambda[i] * w.omega[i] * w.omega[i];
  return T;
}

// ∂T/∂θ̇ of that T: m R² cos²β θ̇ + Σ λ_i ω_i ∂ω_i/∂θ̇.
double book_p_theta(const Satellite& s, const Coordinates& u, const Coordinates& ud) {
  const BodyRates w = book_body_rates(u, ud);
  double p = s.m * u[0] * u[0] * std::cos(u[2]) * std::cos(u[2]) * ud[1];
  for (int i = 0; i < 3; ++i) p += s.lambda[i] * w.omega[i] * w.dtheta[i];
  return p;
}

// J = Σ λ_i e_i ⊗ e_i with e_i = Q E_i.
Tensor inertia(const Satellite& s, const Tensor& Q) {
  Tensor J = Tensor::Zero();
  for (int i = 0; i < 3; ++i) J += s.lambda[i] * Q.col(i) * Q.col(i).transpose();
  return J;
}

// (10.11): U = −GMm/R − (GM/(2R³)) tr J + (3GM/(2R³)) e_R·J e_R.
double book_U(const Satellite& s, const Coordinates& u) {
  const Tensor J = inertia(s, book_Q(u));
  const double R = u[0];
  return -s.GM * s.m / R - s.GM / (2 * R * R * R) * J.trace() +
         3 * s.GM / (2 * R * R * R) * e_R(u).dot(J * e_R(u));
}

Coordinates along(const Coordinates& u, const Coordinates& ud, double eps) {
  Coordinates v = u;
  for (int i = 0; i < 6; ++i) v[i] += eps * ud[i];
  return v;
}

// The state of one row.
void row_state(const test::ModelRun& run, std::size_t k, Coordinates& u, Coordinates& ud) {
  static const std::array<const char*, 6> names{"R", "theta", "beta", "nu1", "nu2", "nu3"};
  for (int i = 0; i < 6; ++i) {
    u[i] = run.at(k, names[i]);
    ud[i] = run.at(k, std::string("der(") + names[i] + ")");
  }
}

// At random states, with no run: the exercise's kinematics against derivatives taken in the test
// of x̄(u) and of the Q = Q2 Q1 it describes (fourth-order differences along u̇):
// (a) v̄ = d x̄/dt; (b) e1 = Q2 e_r, e2 = Q2 e_θ, e3 = Q2 E3; (c) (10.53) and (d) ω = ω_i e_i
// against the axial vector of Q̇ Qᵀ; (f) ∂U/∂θ = 0 for U of (10.11), and ∂T/∂θ̇ — the closed form
// from (d) and a central difference of T in θ̇ — against H_O·E3 = (x̄ × m v̄ + J ω)·E3 with v̄ and ω
// the differences of x̄ and Q (the book's formulas not used there).
TEST(SatelliteLatitudeLongitude, KinematicsAndThetaMomentumOfExercise106) {
  test::Random random(106);
  const Satellite s{2.0, 1.5, {0.3, 0.5, 0.7}};
  double error_v = 0, error_basis = 0, error_omega = 0, error_dU = 0, error_p = 0, error_fd = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Coordinates u{random.uniform(0.7, 1.5),  random.uniform(-3.1, 3.1),
                        random.uniform(-1.3, 1.3), random.uniform(-3.1, 3.1),
                        random.uniform(-1.3, 1.3), random.uniform(-3.1, 3.1)};
    Coordinates ud;
    for (double& r : ud) r = random.uniform(-2, 2);
    const Tensor Q = book_Q(u), Q2 = book_Q2(u);
    const Vec3 v = test::derivative(
                       [&](double e) -> Tensor {
                         Tensor x = Tensor::Zero();
                         x.col(0) = centre(along(u, ud, e));
                         return x;
                       },
                       0.0)
                       .col(0);
    const Tensor W =
        test::derivative([&](double e) { return book_Q(along(u, ud, e)); }, 0.0) * Q.transpose();
    const Vec3 omega(W(2, 1), W(0, 2), W(1, 0));
    error_v = std::max(error_v, test::max_abs_diff(book_velocity(u, ud), v));
    error_basis = std::max({error_basis, test::max_abs_diff(Q.col(0), Q2 * e_r(u)),
                            test::max_abs_diff(Q.col(1), Q2 * e_theta(u)),
                            test::max_abs_diff(Q.col(2), Q2 * kE3)});
    const Vec3 omega_1053 = ud[1] * kE3 + ud[3] * e_r(u) +
                            ud[4] * (std::cos(u[3]) * e_theta(u) + std::sin(u[3]) * kE3) +
                            ud[5] * Q.col(2);
    const BodyRates w = book_body_rates(u, ud);
    const Vec3 omega_d = w.omega[0] * Q.col(0) + w.omega[1] * Q.col(1) + w.omega[2] * Q.col(2);
    error_omega = std::max(
        {error_omega, test::max_abs_diff(omega_1053, omega), test::max_abs_diff(omega_d, omega)});
    const double dU = test::derivative(
        [&](double e) {
          Coordinates x = u;
          x[1] += e;
          return book_U(s, x);
        },
        0.0);
    error_dU = std::max(error_dU, std::abs(dU));
    const double H_O3 = (centre(u).cross(s.m * v) + inertia(s, Q) * omega).dot(kE3);
    const double dT = test::derivative(
        [&](double e) {
          Coordinates x = ud;
          x[1] += e;
          return book_T(s, u, x);
        },
        0.0);
    const double scale = 1 + std::abs(H_O3);
    error_p = std::max(error_p, std::abs(book_p_theta(s, u, ud) - H_O3) / scale);
    error_fd = std::max(error_fd, std::abs(dT - H_O3) / scale);
  }
  // differences at h = 1e-3, fourth order: ~1e-12 truncation and ~1e-13 rounding
  EXPECT_LT(error_v, 1e-10);
  EXPECT_LT(error_basis, 1e-13);
  EXPECT_LT(error_omega, 1e-10);
  EXPECT_LT(error_dU, 1e-10);
  EXPECT_LT(error_p, 1e-10);
  EXPECT_LT(error_fd, 1e-10);
  std::printf(
      "(a) v %.3g, (b) e_i %.3g, (c)/(d) omega %.3g, (f) dU/dtheta %.3g, "
      "dT/dthetadot - H_O.E3: closed form %.3g, difference of T %.3g\n",
      error_v, error_basis, error_omega, error_dU, error_p, error_fd);
}

// Along runs of models/satellite-latitude-longitude.yaml (its inclined, librating orbit, and the
// same with inertias 20 times larger, so that the orbit and the attitude exchange more momentum; at
// 100 times the gravity-gradient terms, ~tr J/(m R²) of the central attraction, are no longer small
// and the orbit falls in): the energy column against T + U of the test (T from (a), (d); U from
// (10.11)), the test's ∂T/∂θ̇ against H_O·E3 = (x̄ × m v̄ + J ω)·E3 of the test and against unidyn's
// column H_O3, and that ∂T/∂θ̇ conserved (Ex. 10.6(f)) with
// the energy. θ is cyclic — U of (10.11) depends on θ only through e_R·J e_R, which a turn of the
// whole system about E3 leaves as it is (∂U/∂θ = 0, checked above), and T has no θ either — so
// Lagrange's θ equation is d/dt ∂T/∂θ̇ = 0. The orbital part m R² cos²β θ̇ alone is not conserved: it
// changes by more than the error allowed.
TEST(SatelliteLatitudeLongitude, ThetaMomentumConservedAlongARun) {
  for (const double scale : {1.0, 20.0}) {
    const Satellite s{1.0, 1.0, {0.001 * scale, 0.002 * scale, 0.0025 * scale}};
    const test::ModelRun run =
        test::run_model("satellite-latitude-longitude",
                        {{"l1", s.lambda[0]}, {"l2", s.lambda[1]}, {"l3", s.lambda[2]}});
    ASSERT_TRUE(run.summary.ok) << run.summary.message;
    Coordinates u, ud;
    row_state(run, 0, u, ud);
    const double p0 = book_p_theta(s, u, ud), E0 = book_T(s, u, ud) + book_U(s, u);
    const double orbital0 = s.m * std::pow(u[0] * std::cos(u[2]), 2) * ud[1];
    double error_E = 0, error_H = 0, error_identity = 0, drift_p = 0, drift_E = 0,
           orbital_change = 0, largest_beta = 0;
    for (std::size_t k = 0; k < run.rows.size(); ++k) {
      row_state(run, k, u, ud);
      const double p = book_p_theta(s, u, ud), E = book_T(s, u, ud) + book_U(s, u);
      error_E = std::max(error_E, std::abs(E - run.at(k, "energy")));
      error_H = std::max(error_H, std::abs(p - run.at(k, "H_O3")));
      const Tensor Q = book_Q(u);
      const BodyRates w = book_body_rates(u, ud);
      const Vec3 omega = w.omega[0] * Q.col(0) + w.omega[1] * Q.col(1) + w.omega[2] * Q.col(2);
      const Vec3 H_O = centre(u).cross(s.m * book_velocity(u, ud)) + inertia(s, Q) * omega;
      error_identity = std::max(error_identity, std::abs(p - H_O.dot(kE3)));
      drift_p = std::max(drift_p, std::abs(p - p0));
      drift_E = std::max(drift_E, std::abs(E - E0));
      orbital_change = std::max(
          orbital_change, std::abs(s.m * std::pow(u[0] * std::cos(u[2]), 2) * ud[1] - orbital0));
      largest_beta = std::max(largest_beta, std::abs(u[2]));
    }
    // one state, two computations: rounding only
    EXPECT_LT(error_E, 1e-13);
    EXPECT_LT(error_H, 1e-13);
    EXPECT_LT(error_identity, 1e-13);
    // rtol 1e-12 over ~1.5e3 steps
    EXPECT_LT(drift_p, 1e-10);
    EXPECT_LT(drift_E, 1e-10);
    EXPECT_GT(orbital_change, 1e3 * drift_p);  // the attitude takes part
    EXPECT_GT(largest_beta, 0.05);             // the orbit leaves the E1-E2 plane
    std::printf(
        "inertia x%g: |E - energy| %.3g, |dT/dthetadot - H_O3| %.3g, - H_O.E3 of the test %.3g; "
        "drift of dT/dthetadot %.3g, of E %.3g; change of m R^2 cos^2(beta) thetadot %.3g\n",
        scale, error_E, error_H, error_identity, drift_p, drift_E, orbital_change);
  }
}

// Part (g), the equations of motion, by their equivalence with the balance laws (§10.4): along the
// run (inertias 20 times the model's), m dv̄/dt = F and dH/dt = M with H = J ω about x̄, v̄ and
// ω from (a) and (d), the derivatives by fourth-order central differences over the 0.01 s rows, F
// and M typed from (8.25):
//   F = −(GMm/R²) e_R − (3GM/(2R⁴)) (2J + (tr J − 5 e_R·J e_R) I) e_R,
//   M = (3GM/R³) e_R × (J e_R).
TEST(SatelliteLatitudeLongitude, MotionSatisfiesTheBalanceLawsOf825) {
  const Satellite s{1.0, 1.0, {0.02, 0.04, 0.05}};
  const test::ModelRun full =
      test::run_model("satellite-latitude-longitude",
                      {{"l1", s.lambda[0]}, {"l2", s.lambda[1]}, {"l3", s.lambda[2]}});
  ASSERT_TRUE(full.summary.ok) << full.summary.message;
  const test::ModelRun run = full.on_grid(0.01);  // equally spaced: without the row at t_end
  const std::size_t n = run.rows.size();
  std::vector<Vec3> momentum(n), H(n), F(n), M(n);
  for (std::size_t k = 0; k < n; ++k) {
    Coordinates u, ud;
    row_state(run, k, u, ud);
    const Tensor Q = book_Q(u), J = inertia(s, Q);
    const BodyRates w = book_body_rates(u, ud);
    const Vec3 omega = w.omega[0] * Q.col(0) + w.omega[1] * Q.col(1) + w.omega[2] * Q.col(2);
    momentum[k] = s.m * book_velocity(u, ud);
    H[k] = J * omega;
    const double R = u[0];
    const Vec3 c = e_R(u), Jc = J * c;
    F[k] = -s.GM * s.m / (R * R) * c -
           3 * s.GM / (2 * R * R * R * R) * (2 * Jc + (J.trace() - 5 * c.dot(Jc)) * c);
    M[k] = 3 * s.GM / (R * R * R) * c.cross(Jc);
  }
  const double h = run.at(1, "t") - run.at(0, "t");
  const auto rate = [&](const std::vector<Vec3>& x, std::size_t k) -> Vec3 {
    return (8.0 * (x[k + 1] - x[k - 1]) - (x[k + 2] - x[k - 2])) / (12.0 * h);
  };
  double error_F = 0, error_M = 0, largest_M = 0;
  for (std::size_t k = 2; k + 2 < n; ++k) {
    error_F = std::max(error_F, test::max_abs_diff(rate(momentum, k), F[k]));
    error_M = std::max(error_M, test::max_abs_diff(rate(H, k), M[k]));
    largest_M = std::max(largest_M, M[k].cwiseAbs().maxCoeff());
  }
  // the differences' truncation at h = 0.01 (~h⁴/30 of the fifth derivative) and the run's
  // interpolated rows (rtol 1e-12) magnified by ~1/h; |F| ≈ 1
  EXPECT_LT(error_F, 1e-8);
  EXPECT_LT(error_M, 1e-9);    // H ≈ 0.05: the errors scale with it
  EXPECT_GT(largest_M, 1e-3);  // the gravity-gradient moment is not negligible
  std::printf("|m dv/dt - F| %.3g, |dH/dt - M| %.3g (|M| up to %.3g)\n", error_F, error_M,
              largest_M);
}

}  // namespace
}  // namespace unidyn
