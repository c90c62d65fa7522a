// Exercise 4.1(a)–(c), (e): the mass matrix M — the metric of the line element ds² = q̇ᵀ M q̇ dt²/m
// on the configuration manifold — of four systems, against M written out by hand.
#include <cmath>

#include "support/model_run.hpp"

namespace unidyn {
namespace {

// M of a model at (t, q), as the compiled equations give it.
Eigen::MatrixXd mass_matrix(const std::string& text, double t, const Eigen::VectorXd& q) {
  const System system = parse_model(text, "exercise-4-1.yaml");
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  Eigen::VectorXd qddot, lambda;
  compiled.solve(t, q, Eigen::VectorXd::Zero(q.size()), initial_state(system, {}).parameters, qddot,
                 lambda, data);
  return data.mass_matrix;
}

// (a) a particle on a spring from the fixed origin, spherical (R, φ, θ): M = m diag(1, R², R²
// sin²φ); (b) on a rod of length L(t) = L0 + a sin t (a rheonomic constraint), (φ, θ): M = m L²
// diag(1, sin²φ); (c) a harmonic oscillator: M = m.
TEST(LineElements, SpringRodAndOscillatorOfExercise41) {
  const double m = 1.5, R = 0.8, phi = 0.9, t = 0.7, L = 1.2 + 0.3 * std::sin(t);
  Eigen::VectorXd q3(3), q2(2), q1(1);
  q3 << R, phi, 0.4;
  q2 << phi, 0.4;
  q1 << 0.2;
  const Eigen::MatrixXd spring = mass_matrix(R"yaml(unidyn: 1
parameters: {m: 1.5, K: 3.0}
coordinates: [R, phi, theta]
particles:
  P: {mass: m, position: "R*[sin(phi)*cos(theta), sin(phi)*sin(theta), cos(phi)]"}
forces:
  - spring: {from: [0, 0, 0], to: P, stiffness: K, rest_length: 1}
initial: {R: 1, phi: 1}
)yaml",
                                             0, q3);
  const Eigen::Vector3d expected_spring(m, m * R * R, m * std::pow(R * std::sin(phi), 2));
  EXPECT_LT((spring - Eigen::MatrixXd(expected_spring.asDiagonal())).cwiseAbs().maxCoeff(), 1e-14);
  const Eigen::MatrixXd rod = mass_matrix(R"yaml(unidyn: 1
parameters: {m: 1.5}
coordinates: [phi, theta]
particles:
  P: {mass: m, position: "(1.2 + 0.3*sin(t))*[sin(phi)*cos(theta), sin(phi)*sin(theta), cos(phi)]"}
initial: {phi: 1}
)yaml",
                                          t, q2);
  const Eigen::Vector2d expected_rod(m * L * L, m * std::pow(L * std::sin(phi), 2));
  EXPECT_LT((rod - Eigen::MatrixXd(expected_rod.asDiagonal())).cwiseAbs().maxCoeff(), 1e-14);
  const Eigen::MatrixXd oscillator = mass_matrix(R"yaml(unidyn: 1
parameters: {m: 1.5, K: 3.0}
coordinates: [x]
particles:
  P: {mass: m, position: [x, 0, 0]}
forces:
  - spring: {from: [0, 0, 0], to: P, stiffness: K, rest_length: 0}
)yaml",
                                                 0, q1);
  EXPECT_EQ(oscillator.rows(), 1);
  EXPECT_NEAR(oscillator(0, 0), m, 1e-15);
}

// (e) the spherical double pendulum, (φ1, θ1, φ2, θ2): with u(φ, θ) the unit vector and its
// derivatives e_φ, sin φ e_θ, M = Σ m ∂r/∂q·∂r/∂q is
//   [[(m1 + m2) L1², 0, m2 L1 L2 e_φ1·e_φ2, m2 L1 L2 sin φ2 e_φ1·e_θ2],
//    [·, (m1 + m2) L1² sin²φ1, m2 L1 L2 sin φ1 e_θ1·e_φ2, m2 L1 L2 sin φ1 sin φ2 e_θ1·e_θ2],
//    [·, ·, m2 L2², 0], [·, ·, ·, m2 L2² sin²φ2]].
TEST(LineElements, SphericalDoublePendulumOfExercise41) {
  const double m1 = 1.0, m2 = 0.6, L1 = 1.1, L2 = 0.7;
  Eigen::VectorXd q(4);
  q << 0.8, 0.3, 2.1, -1.2;
  const Eigen::MatrixXd M = mass_matrix(R"yaml(unidyn: 1
parameters: {m1: 1.0, m2: 0.6, L1: 1.1, L2: 0.7}
coordinates: [phi1, theta1, phi2, theta2]
particles:
  P1: {mass: m1, position: "L1*[sin(phi1)*cos(theta1), sin(phi1)*sin(theta1), cos(phi1)]"}
  P2: {mass: m2, position: "P1.position + L2*[sin(phi2)*cos(theta2), sin(phi2)*sin(theta2), cos(phi2)]"}
initial: {phi1: 1, phi2: 1}
)yaml",
                                        0, q);
  const auto e_phi = [](double p, double t) {
    return Eigen::Vector3d(std::cos(p) * std::cos(t), std::cos(p) * std::sin(t), -std::sin(p));
  };
  const auto e_theta = [](double t) { return Eigen::Vector3d(-std::sin(t), std::cos(t), 0); };
  const double s1 = std::sin(q[0]), s2 = std::sin(q[2]), c = m2 * L1 * L2;
  Eigen::Matrix4d expected;
  expected(0, 0) = (m1 + m2) * L1 * L1;
  expected(0, 1) = 0;
  expected(0, 2) = c * e_phi(q[0], q[1]).dot(e_phi(q[2], q[3]));
  expected(0, 3) = c * s2 * e_phi(q[0], q[1]).dot(e_theta(q[3]));
  expected(1, 1) = (m1 + m2) * L1 * L1 * s1 * s1;
  expected(1, 2) = c * s1 * e_theta(q[1]).dot(e_phi(q[2], q[3]));
  expected(1, 3) = c * s1 * s2 * e_theta(q[1]).dot(e_theta(q[3]));
  expected(2, 2) = m2 * L2 * L2;
  expected(2, 3) = 0;
  expected(3, 3) = m2 * L2 * L2 * s2 * s2;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < i; ++j) expected(i, j) = expected(j, i);
  }
  EXPECT_LT((M - expected).cwiseAbs().maxCoeff(), 1e-14) << M << "\n\n" << expected;
}

}  // namespace
}  // namespace unidyn
