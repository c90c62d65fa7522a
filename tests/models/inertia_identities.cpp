// Exercise 7.4(d): the inertia tensor's rate and the rate of angular momentum along a run,
// J̇ = ΩJ − JΩ, Ḣ = Jω̇ + ω × Jω and d/dt(Jω·ω) = 2 Ḣ·ω, with Ḣ = M (Euler's law) as the check
// that the run is the body's motion.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <vector>

#include "support/model_run.hpp"
#include "support/rigid_kinematics.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// A body (Euler parameters, centre fixed) turned by M = M0 e1 + M0 cos t E3 from Q(0) = I with
// ω(0) = 0.5 E2 + 5 E3 (the case of Fig. 9.2); M0 = 0 is the torque-free body of §9.5.
constexpr const char* kTurnedBody = R"yaml(unidyn: 1
name: Turned body
parameters: {m: 1.0, l1: 2.0, l2: 4.0, l3: 5.0, M0: 1.5}
coordinates: [e0, e1, e2, e3]
bodies:
  body:
    mass: m
    inertia: [l1, l2, l3]
    rotation: {quaternion: [e0, e1, e2, e3]}
    center: [0, 0, 0]
forces:
  - moment: {on: body, value: M0*body.e1 + M0*cos(t)*E3}
initial: {e0: 1, der(e2): 0.25, der(e3): 2.5}
simulate: {t_end: 4, output_step: 0.001, rtol: 1e-12}
)yaml";

using Vec = std::array<double, 3>;
using Mat = std::array<Vec, 3>;  // rows

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec times(const Mat& A, const Vec& a) {
  return {dot(A[0], a), dot(A[1], a), dot(A[2], a)};
}
Mat product(const Mat& A, const Mat& B) {
  Mat C{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) C[i][j] += A[i][k] * B[k][j];
    }
  }
  return C;
}

// What the test computes from one row: e_i and ω from the Euler parameters and their rates alone
// (support/rigid_kinematics.hpp), J = Σ λ_i e_i ⊗ e_i (7.23) and H = Jω.
struct RowInertia {
  std::array<Vec, 3> basis;
  Vec omega, H;
  Mat J;
};

RowInertia inertia(const test::ModelRun& run, std::size_t k, const Vec& lambda) {
  const test::EulerParameterKinematics q = test::euler_parameter_kinematics(run, k);
  RowInertia r;
  r.basis = q.basis;
  r.omega = q.omega;
  for (int p = 0; p < 3; ++p) {
    for (int n = 0; n < 3; ++n) {
      r.J[p][n] = 0;
      for (int i = 0; i < 3; ++i) r.J[p][n] += lambda[i] * r.basis[i][p] * r.basis[i][n];
    }
  }
  r.H = times(r.J, r.omega);
  return r;
}

// Fourth-order central difference over rows k−2 … k+2 (step h): error O(h⁴).
template <class F>
double rate(const F& f, std::size_t k, double h) {
  return (8 * (f(k + 1) - f(k - 1)) - (f(k + 2) - f(k - 2))) / (12 * h);
}

struct Residuals {
  double J_rate = 0, H_rate = 0, energy_rate = 0, euler_law = 0, H_rate_size = 0;
};

// Along the run of kTurnedBody with `overrides`, at every row away from the ends: the rates by
// finite differences of the quantities computed in the test, against the right-hand sides of
// Ex. 7.4(d) and against M (Euler's law Ḣ = M).
Residuals check_identities(const std::vector<std::pair<std::string, double>>& overrides) {
  const test::ModelRun run =
      test::run_system(parse_model(kTurnedBody, "turned-body.yaml"), overrides);
  EXPECT_TRUE(run.summary.ok) << run.summary.message;
  // the parameters' values in the run: the overrides, else the model text's
  auto value = [&](const std::string& name) {
    for (const auto& [key, v] : overrides) {
      if (key == name) return v;
    }
    return run.parameter(name);
  };
  const Vec lambda{value("l1"), value("l2"), value("l3")};
  const double M0 = value("M0");
  std::vector<RowInertia> rows;
  for (std::size_t k = 0; k < run.rows.size(); ++k) rows.push_back(inertia(run, k, lambda));
  const double h = run.at(1, "t") - run.at(0, "t");
  Residuals res;
  for (std::size_t k = 2; k + 2 < rows.size(); ++k) {
    const RowInertia& r = rows[k];
    Vec Hdot, wdot;
    for (int j = 0; j < 3; ++j) {
      Hdot[j] = rate([&](std::size_t i) { return rows[i].H[j]; }, k, h);
      wdot[j] = rate([&](std::size_t i) { return rows[i].omega[j]; }, k, h);
    }
    // J̇ = ΩJ − JΩ with Ω a = ω × a
    Mat Omega{};
    for (int j = 0; j < 3; ++j) {
      Vec E{0, 0, 0};
      E[j] = 1;
      const Vec column = cross(r.omega, E);
      for (int i = 0; i < 3; ++i) Omega[i][j] = column[i];
    }
    const Mat OJ = product(Omega, r.J), JO = product(r.J, Omega);
    for (int p = 0; p < 3; ++p) {
      for (int n = 0; n < 3; ++n) {
        const double Jdot = rate([&](std::size_t i) { return rows[i].J[p][n]; }, k, h);
        res.J_rate = std::max(res.J_rate, std::abs(Jdot - (OJ[p][n] - JO[p][n])));
      }
    }
    // Ḣ = Jω̇ + ω × Jω
    const Vec Jwdot = times(r.J, wdot), gyroscopic = cross(r.omega, r.H);
    for (int j = 0; j < 3; ++j) {
      res.H_rate = std::max(res.H_rate, std::abs(Hdot[j] - (Jwdot[j] + gyroscopic[j])));
    }
    // d/dt(Jω·ω) = 2 Ḣ·ω
    const double energy_rate =
        rate([&](std::size_t i) { return dot(rows[i].H, rows[i].omega); }, k, h);
    res.energy_rate = std::max(res.energy_rate, std::abs(energy_rate - 2 * dot(Hdot, r.omega)));
    // Euler's law Ḣ = M = M0 e1 + M0 cos t E3
    const double t = run.at(k, "t");
    const Vec M{M0 * r.basis[0][0], M0 * r.basis[0][1], M0 * r.basis[0][2] + M0 * std::cos(t)};
    for (int j = 0; j < 3; ++j) {
      res.euler_law = std::max(res.euler_law, std::abs(Hdot[j] - M[j]));
      res.H_rate_size = std::max(res.H_rate_size, std::abs(Hdot[j]));
    }
  }
  return res;
}

// Ex. 7.4(d) with a moment acting (Ḣ ≠ 0, |Ḣ| up to 3 N m): J̇ = ΩJ − JΩ, Ḣ = Jω̇ + ω × Jω and
// d/dt(Jω·ω) = 2 Ḣ·ω, the left sides by finite differences (h = 1 ms) of J, H and Jω·ω computed
// in the test from the rows' Euler parameters, the right sides from ω and ω̇ (also by finite
// differences); and Ḣ = M (Euler's law) with M computed in the test.
TEST(InertiaIdentities, RatesOfInertiaAndAngularMomentumWithAMoment) {
  const Residuals res = check_identities({});
  // the differences' error h⁴/30 · |ω|⁵ |H| ≈ 3e-9 at h = 1 ms, |ω| ≈ 5 rad/s, |H| ≈ 25 N m s,
  // plus the run's error (rtol 1e-12) over h: bound 1e-7
  EXPECT_GT(res.H_rate_size, 1.0);
  EXPECT_LT(res.J_rate, 1e-7);
  EXPECT_LT(res.H_rate, 1e-7);
  EXPECT_LT(res.energy_rate, 1e-7);
  EXPECT_LT(res.euler_law, 1e-7);
  std::printf(
      "with a moment (max |Hdot| %.3g): Jdot %.3g, Hdot %.3g, d(Jw.w)/dt %.3g, Hdot - M %.3g\n",
      res.H_rate_size, res.J_rate, res.H_rate, res.energy_rate, res.euler_law);
}

// The torque-free body of §9.5 (M0 = 0): the same identities with Ḣ = 0, so Jω̇ = −ω × Jω
// (Euler's equations) and d/dt(Jω·ω) = 0.
TEST(InertiaIdentities, RatesOfInertiaAndAngularMomentumTorqueFree) {
  const Residuals res = check_identities({{"M0", 0.0}});
  EXPECT_LT(res.J_rate, 1e-7);
  EXPECT_LT(res.H_rate, 1e-7);
  EXPECT_LT(res.energy_rate, 1e-7);
  EXPECT_LT(res.euler_law, 1e-7);
  std::printf("torque-free: Jdot %.3g, Hdot %.3g, d(Jw.w)/dt %.3g, |Hdot| %.3g\n", res.J_rate,
              res.H_rate, res.energy_rate, res.euler_law);
}

// The special case J0 = μI (λ1 = λ2 = λ3 = 3): J = μI, so J̇ = 0 and Ḣ = μω̇ (ω × Jω = 0), here
// with the moment acting: μω̇ = M.
TEST(InertiaIdentities, RatesForASphericalInertia) {
  const Residuals res = check_identities({{"l1", 3.0}, {"l2", 3.0}, {"l3", 3.0}});
  EXPECT_GT(res.H_rate_size, 1.0);
  EXPECT_LT(res.J_rate, 1e-7);
  EXPECT_LT(res.H_rate, 1e-7);
  EXPECT_LT(res.energy_rate, 1e-7);
  EXPECT_LT(res.euler_law, 1e-7);
  std::printf("J0 = mu I: Jdot %.3g, Hdot %.3g, d(Jw.w)/dt %.3g, Hdot - M %.3g\n", res.J_rate,
              res.H_rate, res.energy_rate, res.euler_law);
}

}  // namespace
}  // namespace unidyn
