// Exercise 9.14: a body about a fixed point with a spring and gravity (Fig. 9.7), and
// Exercise 10.7: Lagrange's equations (10.54) in 3-1-3 angles for it are the rotational equations
// (9.36).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "support/rk4.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// H_O = (λ1 + m h²) ω1 e1 + (λ2 + m h²) ω2 e2 + λ3 ω3 e3 (9.14(b), x̄ − x_O = h e3) along the
// motion, and E (spring and gravity) is conserved.
TEST(TopSpring, AngularMomentumAboutTheFixedPoint) {
  const double m = 1.0, h = 0.2, l[3] = {0.02, 0.03, 0.015};
  const test::ModelRun run = test::run_model("top-spring");
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  EXPECT_LT(run.summary.energy_relative_drift, 1e-10);
  const double coefficient[3] = {l[0] + m * h * h, l[1] + m * h * h, l[2]};
  const char* xyz[3] = {".x", ".y", ".z"};
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    const double w[3] = {run.at(i, "w1"), run.at(i, "w2"), run.at(i, "w3")};
    for (int c = 0; c < 3; ++c) {
      double H = 0;
      for (int k = 0; k < 3; ++k) {
        H += coefficient[k] * w[k] * run.at(i, "b" + std::to_string(k + 1) + xyz[c]);
      }
      EXPECT_NEAR(run.at(i, std::string("H_O") + xyz[c]), H, 1e-13) << run.at(i, "t");
    }
  }
}

using Vec = std::array<double, 3>;
using Basis = std::array<Vec, 3>;  // e1, e2, e3 in E components

double dot(const Vec& a, const Vec& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
Vec combine(double a, const Vec& x, double b, const Vec& y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2]};
}
double norm(const Vec& a) {
  return std::sqrt(dot(a, a));
}

// The data of Fig. 9.7 (Ex. 9.14), read from a run of the model: J = Σ λ_i e_i⊗e_i about the
// centre, x̄ − x_O = h e3, a spring (K, L0) from x_s − x_O = s1 e1 + s3 e3 to x_A − x_O = L_A E1,
// gravity −m g E3.
struct Figure97 {
  double m, g, h, l1, l2, l3, K, L0, s1, s3, LA;

  static Figure97 of(const test::ModelRun& run) {
    auto p = [&](const char* name) { return run.parameter(name); };
    return {p("m"), p("g"),  p("h"),  p("l1"), p("l2"), p("l3"),
            p("K"), p("L0"), p("s1"), p("s3"), p("LA")};
  }
  // The spring's force on the body, −K (ℓ − L0) (x_s − x_A)/ℓ with ℓ = |x_s − x_A|.
  Vec spring_force(const Basis& e) const {
    const Vec xs = combine(s1, e[0], s3, e[2]);
    const Vec d{xs[0] - LA, xs[1], xs[2]};
    const double length = norm(d);
    return combine(-K * (length - L0) / length, d, 0, d);
  }
  // M_O = h e3 × (−m g E3) + (s1 e1 + s3 e3) × F_s, in the body's components M_O · e_i.
  Vec moment_about_O(const Basis& e) const {
    const Vec gravity = cross(combine(h, e[2], 0, e[2]), Vec{0, 0, -m * g});
    const Vec spring = cross(combine(s1, e[0], s3, e[2]), spring_force(e));
    const Vec M = combine(1, gravity, 1, spring);
    return {dot(M, e[0]), dot(M, e[1]), dot(M, e[2])};
  }
  // (9.36) as the book states it, each line as left − right side:
  //   (λ1 + m h²) ω̇1 = (λ2 + m h² − λ3) ω2 ω3 + M_O·e1
  //   (λ2 + m h²) ω̇2 = (λ3 − λ1 − m h²) ω1 ω3 + M_O·e2
  //   λ3 ω̇3         = (λ1 − λ2) ω1 ω2         + M_O·e3
  Vec equation_936(const Vec& w, const Vec& wdot, const Vec& M) const {
    const double mh2 = m * h * h;
    return {(l1 + mh2) * wdot[0] - (l2 + mh2 - l3) * w[1] * w[2] - M[0],
            (l2 + mh2) * wdot[1] - (l3 - l1 - mh2) * w[0] * w[2] - M[1],
            l3 * wdot[2] - (l1 - l2) * w[0] * w[1] - M[2]};
  }
  // F_c of 9.14(e): m h (ω̇2 + ω1ω3) e1 − m h (ω̇1 − ω2ω3) e2 − m h (ω1² + ω2²) e3 + m g E3 − F_s,
  // i.e. m ā − F_gravity − F_s with ā of 9.14(a).
  Vec reaction(const Basis& e, const Vec& w, const Vec& wdot) const {
    const Vec a = combine(h * (wdot[1] + w[0] * w[2]), e[0], -h * (wdot[0] - w[1] * w[2]), e[1]);
    const Vec abar = combine(1, a, -h * (w[0] * w[0] + w[1] * w[1]), e[2]);
    const Vec Fs = spring_force(e);
    return {m * abar[0] - Fs[0], m * abar[1] - Fs[1], m * abar[2] + m * g - Fs[2]};
  }
};

// Exercise 9.14(h) and (e) along the run of models/top-spring.yaml (Euler parameters, Lagrange's
// equations with the constraint e·e = 1): from each row's (e0, e) and (ė0, ė) the test computes
// e_i = Q E_i, Q a = (e0² − e·e) a + 2 (e·a) e + 2 e0 e × a, and ω = 2 (e0 ė − ė0 e + e × ė), so
// ω_i = ω·e_i; ω̇_i by the five-point central difference of ω_i over the 1 ms rows (ω̇·e_i = d(ω·e_i)
// /dt since ω·(ω × e_i) = 0). Then (9.36) typed above must hold with M_O of the spring and gravity
// typed above, and the model's body.constraint_force (m ā − F) must equal F_c of (e).
TEST(TopSpring, EulersLawAboutTheFixedPointIsEquation936AndTheReactionIsExercise914e) {
  // the model file ends with its outputs: map, to which the resultant constraint force is added
  const std::string text =
      read_model_text(test::model_path("top-spring")) + "  Fc: body.constraint_force\n";
  const double step = 1e-3;
  const test::ModelRun run =
      test::run_system(parse_model(text, "top-spring.yaml"), {}, [&](SimulationOptions& o) {
        o.t_end = 2;
        o.output_step = step;
      });
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Figure97 fig = Figure97::of(run);
  const std::size_t n = run.rows.size();
  ASSERT_EQ(n, static_cast<std::size_t>(std::lround(2 / step)) + 1);
  std::vector<Basis> basis(n);
  std::vector<Vec> w(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double e0 = run.at(k, "e0"), e0dot = run.at(k, "der(e0)");
    const Vec e{run.at(k, "e1"), run.at(k, "e2"), run.at(k, "e3")};
    const Vec edot{run.at(k, "der(e1)"), run.at(k, "der(e2)"), run.at(k, "der(e3)")};
    for (int i = 0; i < 3; ++i) {
      Vec E{0, 0, 0};
      E[static_cast<std::size_t>(i)] = 1;
      const Vec ea = cross(e, E);
      for (std::size_t j = 0; j < 3; ++j) {
        basis[k][static_cast<std::size_t>(i)][j] =
            (e0 * e0 - dot(e, e)) * E[j] + 2 * dot(e, E) * e[j] + 2 * e0 * ea[j];
      }
    }
    const Vec c = cross(e, edot);
    Vec omega{};
    for (std::size_t j = 0; j < 3; ++j) omega[j] = 2 * (e0 * edot[j] - e0dot * e[j] + c[j]);
    for (std::size_t i = 0; i < 3; ++i) w[k][i] = dot(omega, basis[k][i]);
  }
  double worst_936 = 0, worst_reaction = 0, largest_moment = 0, largest_reaction = 0;
  for (std::size_t k = 2; k + 2 < n; ++k) {
    Vec wdot{};
    for (std::size_t i = 0; i < 3; ++i) {
      wdot[i] = (w[k - 2][i] - 8 * w[k - 1][i] + 8 * w[k + 1][i] - w[k + 2][i]) / (12 * step);
    }
    const Vec M = fig.moment_about_O(basis[k]);
    const Vec residual = fig.equation_936(w[k], wdot, M);
    const Vec Fc = fig.reaction(basis[k], w[k], wdot);
    const Vec seen{run.at(k, "Fc.x"), run.at(k, "Fc.y"), run.at(k, "Fc.z")};
    worst_936 = std::max(worst_936, norm(residual));
    worst_reaction = std::max(worst_reaction, norm(combine(1, Fc, -1, seen)));
    largest_moment = std::max(largest_moment, norm(M));
    largest_reaction = std::max(largest_reaction, norm(Fc));
  }
  std::printf("  (9.36) along the run: max |residual| %.2e N m (max |M_O| %.3f N m)\n", worst_936,
              largest_moment);
  std::printf("  F_c of (e) against body.constraint_force: max error %.2e N (max |F_c| %.3f N)\n",
              worst_reaction, largest_reaction);
  // what is left is the five-point difference's truncation error step⁴/30 |ω⁽⁵⁾|: it falls 16-fold
  // per halving of the step (1.2e-6, 7.3e-8, 4.7e-9 N m at 2, 1, 0.5 ms); the rows' own error
  // (rtol 1e-12) divided by the step is below 1e-9. A wrong term would leave a residual of the
  // order of the moments.
  EXPECT_LT(worst_936, 1e-7 * largest_moment);
  EXPECT_LT(worst_reaction, 1e-7 * largest_reaction);
  EXPECT_GT(largest_moment, 0.5);  // the spring and gravity do turn the body
}

// The model of Fig. 9.7 in the book's 3-1-3 angles (ψ, θ, φ) of Ex. 9.14(f) and Ex. 10.7(a); the
// parameters are those of models/top-spring.yaml. unidyn integrates Lagrange's equations (10.54)
// d/dt(∂L/∂γ̇^i) − ∂L/∂γ^i = 0 of it; the spin keeps θ in [1.1, 2.5], away from gimbal lock.
constexpr const char* kTopSpring313 = R"yaml(unidyn: 1
name: Body about a fixed point with a spring and gravity, 3-1-3 angles
parameters: {m: 1.0, g: 9.81, h: 0.2, l1: 0.02, l2: 0.03, l3: 0.015, K: 30.0, L0: 0.25, s1: 0.1, s3: 0.15, LA: 0.4}
coordinates: [psi, theta, phi]
bodies:
  body:
    mass: m
    inertia: [l1, l2, l3]
    rotation: {euler: 3-1-3, angles: [psi, theta, phi]}
    center: h*body.e3
forces:
  - gravity: -g*E3
  - spring: {from: {on: body, point: [s1, 0, s3 - h]}, to: [LA, 0, 0], stiffness: K, rest_length: L0}
initial: {psi: 0.3, theta: 1.2, phi: 0.5, der(psi): 1.0, der(theta): -0.5, der(phi): 30.0}
simulate: {t_end: 3, output_step: 0.01, rtol: 1e-12}
)yaml";

// e_i = Q E_i for Q = R3(ψ) R1(θ) R3(φ) (§6.8.2; e3 = sθ sψ E1 − sθ cψ E2 + cθ E3 as in (9.14)).
Basis basis_313(double psi, double theta, double phi) {
  const double cs = std::cos(psi), ss = std::sin(psi), ct = std::cos(theta), st = std::sin(theta);
  const double cp = std::cos(phi), sp = std::sin(phi);
  return {Vec{cs * cp - ss * ct * sp, ss * cp + cs * ct * sp, st * sp},
          Vec{-cs * sp - ss * ct * cp, -ss * sp + cs * ct * cp, st * cp},
          Vec{st * ss, -st * cs, ct}};
}

// ω = ψ̇ g1 + θ̇ g2 + φ̇ g3 with the book's g1 = E3 = sφ sθ e1 + cφ sθ e2 + cθ e3, g2 = cφ e1 − sφ e2,
// g3 = e3 (9.14), in the body's components.
Vec omega_313(double theta, double phi, double dpsi, double dtheta, double dphi) {
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  return {dpsi * st * sp + dtheta * cp, dpsi * st * cp - dtheta * sp, dphi + dpsi * ct};
}

// The book's 3-1-3 kinematic matrix that goes with (9.36): (ψ̇, θ̇, φ̇) from ω.
Vec angle_rates_313(double theta, double phi, const Vec& w) {
  const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
  return {(sp * w[0] + cp * w[1]) / st, cp * w[0] - sp * w[1],
          -(sp * w[0] + cp * w[1]) * ct / st + w[2]};
}

// Exercise 10.7(b)–(c): Lagrange's equations (10.54) in 3-1-3 angles, as unidyn derives and solves
// them, against the book's (9.36). (1) At 20 states across the angles, q̈ from unidyn's equations
// evaluated at the state (CompiledSystem::solve) gives ω̇ by the time derivative of ω_313 (typed
// below), and (9.36) with M_O typed in Figure97 must hold to rounding. (2) An RK4 of (9.36) with
// the book's 3-1-3 kinematic matrix, written here (state ψ, θ, φ, ω1, ω2, ω3, step 0.5 ms), from
// the run's start must reproduce the run's angles and rates over 3 s.
TEST(TopSpring, LagrangesEquationsInEulerAnglesAreEquation936OfExercise107) {
  const test::ModelRun run = test::run_system(parse_model(kTopSpring313, "top-spring-313.yaml"));
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const Figure97 fig = Figure97::of(run);

  // (1) unidyn's accelerations at given states
  const CompiledSystem compiled(run.system, lagrange_equations(run.system));
  const SimulationStart start = initial_state(run.system, {});
  CompiledSystemData data = compiled.make_data();
  double worst_state = 0, largest_moment = 0;
  for (int k = 0; k < 20; ++k) {
    const double psi = 0.4 * k - 3, theta = 0.3 + 0.13 * k, phi = 1.1 * k - 5;
    const double dpsi = 2 - 0.3 * k, dtheta = 0.25 * k - 2.5, dphi = 0.9 * k - 7;
    Eigen::VectorXd q(3), qdot(3), qddot, lambda;
    q << psi, theta, phi;
    qdot << dpsi, dtheta, dphi;
    compiled.solve(0, q, qdot, start.parameters, qddot, lambda, data);
    const double st = std::sin(theta), ct = std::cos(theta), sp = std::sin(phi), cp = std::cos(phi);
    const double ddpsi = qddot[0], ddtheta = qddot[1], ddphi = qddot[2];
    const Vec w = omega_313(theta, phi, dpsi, dtheta, dphi);
    const Vec wdot{ddpsi * st * sp + dpsi * (dtheta * ct * sp + dphi * st * cp) + ddtheta * cp -
                       dtheta * dphi * sp,
                   ddpsi * st * cp + dpsi * (dtheta * ct * cp - dphi * st * sp) - ddtheta * sp -
                       dtheta * dphi * cp,
                   ddphi + ddpsi * ct - dpsi * dtheta * st};
    const Vec M = fig.moment_about_O(basis_313(psi, theta, phi));
    worst_state = std::max(worst_state, norm(fig.equation_936(w, wdot, M)));
    largest_moment = std::max(largest_moment, norm(M));
  }
  std::printf("  (9.36) at 20 states with unidyn's q'': max |residual| %.2e N m (max |M_O| %.3f)\n",
              worst_state, largest_moment);
  EXPECT_LT(worst_state, 1e-12 * std::max(1.0, largest_moment));

  // (2) an RK4 of (9.36) and the kinematic matrix
  using State = std::array<double, 6>;
  const auto rates = [&](double, const State& s) {
    const Vec w{s[3], s[4], s[5]};
    const Vec angles = angle_rates_313(s[1], s[2], w);
    const Vec M = fig.moment_about_O(basis_313(s[0], s[1], s[2]));
    const double mh2 = fig.m * fig.h * fig.h;
    return State{angles[0],
                 angles[1],
                 angles[2],
                 ((fig.l2 + mh2 - fig.l3) * w[1] * w[2] + M[0]) / (fig.l1 + mh2),
                 ((fig.l3 - fig.l1 - mh2) * w[0] * w[2] + M[1]) / (fig.l2 + mh2),
                 ((fig.l1 - fig.l2) * w[0] * w[1] + M[2]) / fig.l3};
  };
  const Vec w0 = omega_313(run.at(0, "theta"), run.at(0, "phi"), run.at(0, "der(psi)"),
                           run.at(0, "der(theta)"), run.at(0, "der(phi)"));
  State s{run.at(0, "psi"), run.at(0, "theta"), run.at(0, "phi"), w0[0], w0[1], w0[2]};
  const int substeps = 20;  // 0.5 ms
  double worst_angle = 0, worst_rate = 0;
  for (std::size_t k = 1; k < run.rows.size(); ++k) {
    s = test::rk4(s, run.at(k - 1, "t"), run.at(k, "t"), substeps, rates);
    const Vec angle_rates = angle_rates_313(s[1], s[2], Vec{s[3], s[4], s[5]});
    const char* names[3] = {"psi", "theta", "phi"};
    for (std::size_t j = 0; j < 3; ++j) {
      worst_angle = std::max(worst_angle, std::abs(run.at(k, names[j]) - s[j]));
      worst_rate = std::max(
          worst_rate, std::abs(run.at(k, std::string("der(") + names[j] + ")") - angle_rates[j]));
    }
  }
  std::printf("  RK4 of (9.36) against the run over 3 s: angles %.2e rad, rates %.2e rad/s\n",
              worst_angle, worst_rate);
  // what is left is RK4's global error: it falls 16-fold per halving of the step (2.3e-7 rad and
  // 7.3e-7 rad/s at 1 ms, 1.5e-8 and 4.6e-8 at 0.5 ms); held below what it is at twice the step
  EXPECT_LT(worst_angle, 2e-7);
  EXPECT_LT(worst_rate, 6e-7);
}

}  // namespace
}  // namespace unidyn
