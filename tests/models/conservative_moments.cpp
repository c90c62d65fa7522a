// Conservative forces and moments on bodies (§8.7, (8.27)): a torsion spring's moment along the
// dual Euler basis (Ex. 8.6), and a spring at a body point (Ex. 8.8) whose force and moment π_A × F
// equal −∂U/∂x̄ and −Σ ∂U/∂γ^i g^i with g^i from the rotation layer's dual Euler basis.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "support/model_run.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

// Numbers of an expression at a state.
struct State {
  GiNaC::exmap values;
  double operator()(const Expr& e) const {
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(values))).to_double();
  }
};

const ForceElement& element_of(const System& system, ForceElement::Kind kind) {
  for (const auto& f : system.forces) {
    if (f.kind == kind) return f;
  }
  throw std::runtime_error("no such element");
}

// Ex. 8.6(e): M_con = −K ψ g^1 = −K ψ (cot θ (cos ψ E2 − sin ψ E1) + E3) for 3-1-3 angles.
TEST(ConservativeMoments, TorsionSpringMomentAlongTheDualEulerBasis) {
  const System system = load_model(test::model_path("top-torsion-spring"));
  const ForceElement& spring = element_of(system, ForceElement::Kind::torsion_spring);
  ASSERT_EQ(spring.moments.size(), 1u);
  const double K = 0.02, psi = 0.7, theta = 0.4, phi = -1.2;
  State at{system.parameter_values()};
  at.values[system.coordinates()[0].value] = psi;
  at.values[system.coordinates()[1].value] = theta;
  at.values[system.coordinates()[2].value] = phi;
  const double expected[3] = {K * psi * std::sin(psi) / std::tan(theta),
                              -K * psi * std::cos(psi) / std::tan(theta), -K * psi};
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(at(spring.moments[0].moment[i]), expected[i], 1e-15);
  EXPECT_NEAR(at(spring.potential), K * psi * psi / 2, 1e-16);
}

// Ex. 8.8(c): the spring force at A and its moment π_A × F against (8.27).
TEST(ConservativeMoments, SpringAtABodyPointIsEquation827) {
  const System system = load_model(test::model_path("body-on-spring"));
  const ForceElement& spring = element_of(system, ForceElement::Kind::spring);
  ASSERT_EQ(spring.body_forces.size(), 1u);
  const auto& q = system.coordinates();
  State at{system.parameter_values()};
  const double x[6] = {0.1, -0.2, -0.4, 0.5, 0.9, -0.3};
  for (std::size_t i = 0; i < 6; ++i) at.values[q[i].value] = x[i];
  const BodyForce& f = spring.body_forces[0];
  const VectorExpr arm = f.point - system.bodies[0].center;
  const VectorExpr moment = cross(arm, f.force);
  const Tensor dual = dual_euler_basis(*EulerSet::parse("3-1-3"), Vec3(x[3], x[4], x[5]));
  for (int i = 0; i < 3; ++i) {
    // F_con = −∂U/∂x̄ (the centre is [x1, x2, x3])
    EXPECT_NEAR(at(f.force[i]), -at(spring.potential.diff(q[static_cast<std::size_t>(i)].value)),
                1e-12);
    // M_con = −Σ ∂U/∂γ^k g^k
    double expected = 0;
    for (int k = 0; k < 3; ++k) {
      expected -= at(spring.potential.diff(q[static_cast<std::size_t>(3 + k)].value)) * dual(i, k);
    }
    EXPECT_NEAR(at(moment[i]), expected, 1e-12);
  }
}

// Both models keep E and their component of H_O: the top's H_O · e3 (g^1 ⊥ e3 and gravity's
// moment ⊥ e3) and the hanging body's H_O · E3 (the spring's line passes through O).
TEST(ConservativeMoments, EnergyAndAngularMomentumKept) {
  for (const char* model : {"top-torsion-spring", "body-on-spring"}) {
    const test::ModelRun run = test::run_model(model);
    ASSERT_TRUE(run.summary.ok) << model << ": " << run.summary.message;
    EXPECT_LT(run.summary.energy_relative_drift, 1e-11) << model;
    ASSERT_EQ(run.summary.conserved_drift.size(), 1u) << model;
    EXPECT_LT(run.summary.conserved_drift[0].max_change, 1e-12) << model;
  }
}

// Ex. 8.7 (Ziegler): a constant moment M E3 has no potential. In 3-1-3 angles its generalised
// forces Φ_i = M E3 · g_i = (M, 0, M cos θ) fail the integrability condition ∂Φ_φ/∂θ = ∂Φ_θ/∂φ,
// while the torsion spring's −K ψ g^1 passes all of them (it is −∂U/∂γ).
TEST(ConservativeMoments, ZieglersConstantMomentHasNoPotential) {
  const System system = load_model(test::model_path("ziegler-moment"));
  const auto& q = system.coordinates();
  const VectorExpr omega = system.angular_velocity(0);
  // the curl ∂Φ_i/∂γ^j − ∂Φ_j/∂γ^i of each element's generalised forces
  const auto curl = [&](const VectorExpr& moment, std::size_t i, std::size_t j) {
    const Expr phi_i = dot(moment, diff(omega, q[i].rate));
    const Expr phi_j = dot(moment, diff(omega, q[j].rate));
    return simplify(phi_i.diff(q[j].value) - phi_j.diff(q[i].value));
  };
  const VectorExpr ziegler = system.forces[0].moments[0].moment;
  const VectorExpr spring = system.forces[1].moments[0].moment;
  const Expr M = system.parameters[0].symbol, theta = q[1].value;
  EXPECT_TRUE(simplify(curl(ziegler, 2, 1) + M * GiNaC::sin(theta)).is_zero());
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = i + 1; j < 3; ++j) EXPECT_TRUE(curl(spring, i, j).is_zero()) << i << j;
  }
}

// Exercise 8.7, the work on two paths: between the same two configurations (θ, φ) = (π/2, 0) and
// (0, π) of the 3-1-3 angles, unidyn's generalised forces of M E3 do the work M π cos θ along
// φ — first θ then φ: M π; first φ then θ: 0 (the book's "Mπ against 0"). The work is the sum of
// Φ_θ dθ + Φ_φ dφ along each straight leg, by Simpson's rule here; a potential would give one
// value.
TEST(ConservativeMoments, ZieglersMomentDoesDifferentWorkOnTwoPaths) {
  const System system = load_model(test::model_path("ziegler-moment"));
  const auto& q = system.coordinates();
  const VectorExpr omega = system.angular_velocity(0);
  const VectorExpr ziegler = system.forces[0].moments[0].moment;
  const Expr M = system.parameters[0].symbol;
  const Expr Phi_theta = dot(ziegler, diff(omega, q[1].rate));
  const Expr Phi_phi = dot(ziegler, diff(omega, q[2].rate));
  const auto value = [&](const Expr& e, double theta, double phi) {
    const GiNaC::exmap at{{q[0].value, 0.3}, {q[1].value, theta}, {q[2].value, phi}, {M, 2.0}};
    return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
  };
  // ∫ along the straight leg from (θ0, φ0) to (θ1, φ1)
  const auto leg = [&](double theta0, double phi0, double theta1, double phi1) {
    const int n = 200;
    double sum = 0;
    for (int k = 0; k <= n; ++k) {
      const double s = static_cast<double>(k) / n;
      const double weight = (k == 0 || k == n) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
      const double theta = theta0 + s * (theta1 - theta0), phi = phi0 + s * (phi1 - phi0);
      sum += weight * (value(Phi_theta, theta, phi) * (theta1 - theta0) +
                       value(Phi_phi, theta, phi) * (phi1 - phi0));
    }
    return sum / (3.0 * n);
  };
  const double pi = std::acos(-1.0), half = pi / 2;
  const double theta_first = leg(half, 0, 0, 0) + leg(0, 0, 0, pi);
  const double phi_first = leg(half, 0, half, pi) + leg(half, pi, 0, pi);
  EXPECT_NEAR(theta_first, 2.0 * pi, 1e-10);  // M π with M = 2
  EXPECT_NEAR(phi_first, 0.0, 1e-10);
  std::printf("work of M E3: %.12f (theta first), %.3g (phi first)\n", theta_first, phi_first);
}

// Exercise 8.6(b)–(d): the top about its fixed point (x̄ = L1 e3, J = λ_t (I − e3⊗e3) + λ_a e3⊗e3)
// has T = ½ (λ_t + m L1²)(θ̇² + ψ̇² sin²θ) + ½ λ_a (φ̇ + ψ̇ cos θ)² in its 3-1-3 angles, at any state.
TEST(ConservativeMoments, KineticEnergyOfTheTopOfExercise86) {
  const double m = 1.0, L1 = 0.05, lt = 0.004, la = 0.002;
  const System system = load_model(test::model_path("top-torsion-spring"));
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3), no_lambda(0);
  std::vector<double> seen(compiled.observation_count());
  for (int k = 0; k < 10; ++k) {
    const double psi = 0.3 * k - 1, theta = 0.2 + 0.25 * k, phi = 0.7 * k;
    const double dpsi = 1.5 - 0.2 * k, dtheta = 0.4 * k - 2, dphi = 30 + k;
    Eigen::VectorXd q(3), qdot(3);
    q << psi, theta, phi;
    qdot << dpsi, dtheta, dphi;
    compiled.observe(0, q, qdot, none, no_lambda, start.parameters, seen, data);
    const double T =
        0.5 * (lt + m * L1 * L1) * (dtheta * dtheta + dpsi * dpsi * std::pow(std::sin(theta), 2)) +
        0.5 * la * std::pow(dphi + dpsi * std::cos(theta), 2);
    EXPECT_NEAR(seen[0], T, 1e-12 * T) << k;
  }
}

// Exercise 8.6(b)–(c): the same top's angular momenta, the model's `top.H` and
// `top.angular_momentum` (outputs added to the model's text here) at the same ten states, against
// the book's closed forms typed from the angles with e1″ = cos ψ E1 + sin ψ E2,
// e2″ = −cos θ sin ψ E1 + cos θ cos ψ E2 + sin θ E3, e3″ = e3 = sin θ sin ψ E1 − sin θ cos ψ E2 +
// cos θ E3:
//   (b) H = λ_t θ̇ e1″ + λ_t ψ̇ sin θ e2″ + λ_a (φ̇ + ψ̇ cos θ) e3″,
//   (c) H_O = H + L1 e3 × m v̄ with v̄ = ω × L1 e3 and ω of (a) = θ̇ e1″ + ψ̇ sin θ e2″ +
//       (φ̇ + ψ̇ cos θ) e3″; the book's m L1² (ω1 e1 + ω2 e2) = m L1² (θ̇ e1″ + ψ̇ sin θ e2″) too.
TEST(ConservativeMoments, AngularMomentaOfTheTopOfExercise86) {
  const double m = 1.0, L1 = 0.05, lt = 0.004, la = 0.002;
  const std::string text = read_model_text(test::model_path("top-torsion-spring")) +
                           "outputs:\n  H: top.H\n  H_O: top.angular_momentum\n";
  const System system = parse_model(text, "top-torsion-spring.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData data = compiled.make_data();
  const Eigen::VectorXd none = Eigen::VectorXd::Zero(3), no_lambda(0);
  std::vector<double> seen(compiled.observation_count());
  const auto& names = compiled.observation_names();
  const auto column = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  const std::size_t H_at = column("H.x"), HO_at = column("H_O.x");
  ASSERT_LT(H_at + 2, names.size());
  ASSERT_LT(HO_at + 2, names.size());
  using Vec = Eigen::Vector3d;
  double worst_H = 0, worst_HO = 0;
  for (int k = 0; k < 10; ++k) {
    const double psi = 0.3 * k - 1, theta = 0.2 + 0.25 * k, phi = 0.7 * k;
    const double dpsi = 1.5 - 0.2 * k, dtheta = 0.4 * k - 2, dphi = 30 + k;
    Eigen::VectorXd q(3), qdot(3);
    q << psi, theta, phi;
    qdot << dpsi, dtheta, dphi;
    compiled.observe(0, q, qdot, none, no_lambda, start.parameters, seen, data);
    const double cs = std::cos(psi), ss = std::sin(psi), ct = std::cos(theta), st = std::sin(theta);
    const Vec e1(cs, ss, 0), e2(-ct * ss, ct * cs, st), e3(st * ss, -st * cs, ct);
    const Vec H = lt * dtheta * e1 + lt * dpsi * st * e2 + la * (dphi + dpsi * ct) * e3;
    const Vec omega = dtheta * e1 + dpsi * st * e2 + (dphi + dpsi * ct) * e3;
    const Vec vbar = omega.cross(L1 * e3);
    const Vec HO = H + (L1 * e3).cross(m * vbar);
    const Vec HO_book = H + m * L1 * L1 * (dtheta * e1 + dpsi * st * e2);
    for (std::size_t i = 0; i < 3; ++i) {
      const auto c = static_cast<Eigen::Index>(i);
      worst_H = std::max(worst_H, std::abs(seen[H_at + i] - H[c]));
      worst_HO = std::max(worst_HO, std::abs(seen[HO_at + i] - HO[c]));
      EXPECT_NEAR(seen[H_at + i], H[c], 1e-15 * (1 + H.norm())) << k;
      EXPECT_NEAR(seen[HO_at + i], HO[c], 1e-15 * (1 + HO.norm())) << k;
      EXPECT_NEAR(HO_book[c], HO[c], 1e-15 * (1 + HO.norm())) << k;
    }
  }
  std::printf("  Ex. 8.6(b), (c): max |H - book| %.2e, max |H_O - book| %.2e (kg m^2/s)\n", worst_H,
              worst_HO);
}

}  // namespace
}  // namespace unidyn
