// Angular velocity tensors and vectors, corotational rates and the relative angular velocity
// (book §6.2, §6.4, §6.7 and Exercises 6.1, 6.3, 6.6).
#include "unidyn/rotation/angular_velocity.hpp"

#include <cmath>
#include <functional>

#include "support/oracles.hpp"
#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/euler_angles.hpp"

namespace unidyn {
namespace {

using test::derivative;
using test::kPi;
using test::max_abs_diff;

// C with C a = c × a, written out (C = −εc).
Tensor cross_matrix(const Vec3& c) {
  Tensor C;
  C << 0.0, -c.z(), c.y(),  //
      c.z(), 0.0, -c.x(),   //
      -c.y(), c.x(), 0.0;
  return C;
}

// The axial vector w of a skew W (W a = w × a): w = (W32, W13, W21), from the skew part.
Vec3 axial_of(const Tensor& W) {
  return Vec3(0.5 * (W(2, 1) - W(1, 2)), 0.5 * (W(0, 2) - W(2, 0)), 0.5 * (W(1, 0) - W(0, 1)));
}

Tensor dyad(const Vec3& a, const Vec3& b) {
  return a * b.transpose();
}

// (6.8) L(φ, r) = cos φ (I − r⊗r) − sin φ εr + r⊗r, with εr = −cross_matrix(r); r a unit vector.
Tensor L(double phi, const Vec3& r) {
  return std::cos(phi) * (Tensor::Identity() - dyad(r, r)) + std::sin(phi) * cross_matrix(r) +
         dyad(r, r);
}

// Fourth-order central difference of a vector-valued function of time.
Vec3 derivative_vector(const std::function<Vec3(double)>& f, double t, double h = 1e-3) {
  return (8.0 * (f(t + h) - f(t - h)) - (f(t + 2 * h) - f(t - 2 * h))) / (12.0 * h);
}

// A smooth rotation Q(t) = L(α(t), u1) L(β(t), u2) L(γ(t), u3) with fixed unit u_i and
// analytic rate and angular velocity: d/dt L(α, u) = α̇ [u×] L(α, u), so
//   ω = α̇ u1 + β̇ L1 u2 + γ̇ L1 L2 u3.
struct RotationPath {
  Vec3 u1, u2, u3;
  Vec3 c0, c1, c2;  // α(t) = c0.x + c1.x sin(c2.x t), likewise β (.y) and γ (.z)

  double angle(int i, double t) const { return c0[i] + c1[i] * std::sin(c2[i] * t); }
  double rate(int i, double t) const { return c1[i] * c2[i] * std::cos(c2[i] * t); }
  Tensor L1(double t) const { return L(angle(0, t), u1); }
  Tensor L2(double t) const { return L(angle(1, t), u2); }
  Tensor L3(double t) const { return L(angle(2, t), u3); }
  Tensor Q(double t) const { return L1(t) * L2(t) * L3(t); }
  Tensor Q_rate(double t) const {
    return rate(0, t) * cross_matrix(u1) * Q(t) +
           L1(t) * rate(1, t) * cross_matrix(u2) * L2(t) * L3(t) +
           L1(t) * L2(t) * rate(2, t) * cross_matrix(u3) * L3(t);
  }
  Vec3 omega(double t) const {
    return rate(0, t) * u1 + rate(1, t) * L1(t) * u2 + rate(2, t) * L1(t) * L2(t) * u3;
  }
};

RotationPath random_path(test::Random& random) {
  return {random.unit_vector(),
          random.unit_vector(),
          random.unit_vector(),
          random.vector(3.0),
          Vec3(random.uniform(0.3, 1.5), random.uniform(0.3, 1.5), random.uniform(0.3, 1.5)),
          Vec3(random.uniform(0.5, 1.5), random.uniform(0.5, 1.5), random.uniform(0.5, 1.5))};
}

// A random right-handed orthonormal basis {p1, p2, p3}.
struct Basis {
  Vec3 p1, p2, p3;
};
Basis random_basis(test::Random& random) {
  const Tensor P = random.rotation();
  return {P.col(0), P.col(1), P.col(2)};
}

// Fourth-order differences, h = 1e-3, on paths with rates ≲ 5: truncation h⁴ |f⁽⁵⁾|/30 ≲ 1e-10 and
// round-off ≈ ε/h ≈ 2e-13, so 1e-9 is safely above the error yet far below any wrong result.
constexpr double kFdTolerance = 1e-9;

// (§6.4) Ω = Q̇ Qᵀ is skew and ω = −½ ε[Q̇ Qᵀ] satisfies ω × a = Ω a.
TEST(AngularVelocity, TensorIsSkewAndActsAsCrossProduct) {
  test::Random random;
  for (int n = 0; n < 200; ++n) {
    const RotationPath path = random_path(random);
    const double t = random.uniform(-2.0, 2.0);
    const Tensor Q = path.Q(t);
    const Tensor Q_rate = path.Q_rate(t);
    const Tensor Omega = angular_velocity_tensor(Q, Q_rate);
    ASSERT_LE(max_abs_diff(Omega, Q_rate * Q.transpose()), 1e-14) << n;
    ASSERT_LE(max_abs_diff(Omega, Tensor(-Omega.transpose())), 1e-14) << n;
    const Vec3 omega = angular_velocity(Q, Q_rate);
    ASSERT_LE(max_abs_diff(omega, path.omega(t)), 1e-14) << n;
    for (int k = 0; k < 5; ++k) {
      const Vec3 a = random.vector(2.0);
      ASSERT_LE(max_abs_diff(omega.cross(a), Omega * a), 1e-14) << n;
    }
    // The analytic rate of the path agrees with finite differences.
    ASSERT_LE(max_abs_diff(derivative([&](double s) { return path.Q(s); }, t), Q_rate),
              kFdTolerance)
        << n;
    ASSERT_LE(max_abs_diff(angular_velocity(Q, derivative([&](double s) { return path.Q(s); }, t)),
                           path.omega(t)),
              kFdTolerance)
        << n;
  }
}

// (6.7) Ω0 = Qᵀ Q̇, ω0 = −½ ε[Qᵀ Q̇] with Q ω0 = ω, Q Ω0 Qᵀ = Ω, and ṫ_i = Q (ω0 × p_i).
TEST(AngularVelocity, BodyVersions67) {
  test::Random random;
  for (int n = 0; n < 200; ++n) {
    const RotationPath path = random_path(random);
    const double t = random.uniform(-2.0, 2.0);
    const Tensor Q = path.Q(t);
    const Tensor Q_rate = path.Q_rate(t);
    const Tensor Omega0 = body_angular_velocity_tensor(Q, Q_rate);
    const Vec3 omega0 = body_angular_velocity(Q, Q_rate);
    ASSERT_LE(max_abs_diff(Omega0, Q.transpose() * Q_rate), 1e-14) << n;
    ASSERT_LE(max_abs_diff(Omega0, Tensor(-Omega0.transpose())), 1e-14) << n;
    ASSERT_LE(max_abs_diff(Q * omega0, path.omega(t)), 1e-14) << n;
    ASSERT_LE(max_abs_diff(Q * Omega0 * Q.transpose(), cross_matrix(path.omega(t))), 1e-14) << n;
    ASSERT_LE(max_abs_diff(omega0, axial_of(Omega0)), 1e-15) << n;
    for (int i = 1; i <= 3; ++i) {
      const Vec3 p = basis_vector(i);
      const Vec3 t_rate = derivative_vector([&](double s) { return Vec3(path.Q(s) * p); }, t);
      ASSERT_LE(max_abs_diff(t_rate, Q * omega0.cross(p)), kFdTolerance) << n;
      ASSERT_LE(max_abs_diff(t_rate, path.omega(t).cross(Q * p)), kFdTolerance) << n;
    }
  }
}

// §6.2 W1 (6.1)–(6.5): Ṙ Rᵀ = θ̇ (p2⊗p1 − p1⊗p2), axial θ̇ p3, ṫ1 = θ̇ t2, ṫ2 = −θ̇ t1.
TEST(AngularVelocity, FixedAxisRotationW1) {
  test::Random random;
  for (int n = 0; n < 50; ++n) {
    const Basis b = random_basis(random);
    const double a0 = random.uniform(-3.0, 3.0), a1 = random.uniform(-2.0, 2.0),
                 a2 = random.uniform(-1.0, 1.0);
    const auto theta = [&](double t) { return a0 + a1 * t + a2 * t * t; };
    // (6.4) R = cos θ (p1⊗p1 + p2⊗p2) − sin θ (p1⊗p2 − p2⊗p1) + p3⊗p3
    const auto R = [&](double t) -> Tensor {
      return std::cos(theta(t)) * (dyad(b.p1, b.p1) + dyad(b.p2, b.p2)) -
             std::sin(theta(t)) * (dyad(b.p1, b.p2) - dyad(b.p2, b.p1)) + dyad(b.p3, b.p3);
    };
    const double t = random.uniform(-1.0, 1.0);
    const double theta_rate = a1 + 2.0 * a2 * t;
    // (6.5) R = L(θ, p3)
    ASSERT_LE(max_abs_diff(rotation_tensor(AxisAngle{b.p3, theta(t)}), R(t)), 1e-14) << n;
    // (6.1) t1 = cos θ p1 + sin θ p2, t2 = −sin θ p1 + cos θ p2, t3 = p3
    const Tensor Rt = R(t);
    ASSERT_LE(max_abs_diff(Rt * b.p1, std::cos(theta(t)) * b.p1 + std::sin(theta(t)) * b.p2),
              1e-14);
    ASSERT_LE(max_abs_diff(Rt * b.p2, -std::sin(theta(t)) * b.p1 + std::cos(theta(t)) * b.p2),
              1e-14);
    const Tensor R_rate = derivative(R, t);
    const Tensor Omega = angular_velocity_tensor(Rt, R_rate);
    ASSERT_LE(max_abs_diff(Omega, theta_rate * (dyad(b.p2, b.p1) - dyad(b.p1, b.p2))), kFdTolerance)
        << n;
    ASSERT_LE(max_abs_diff(angular_velocity(Rt, R_rate), theta_rate * b.p3), kFdTolerance) << n;
    // (6.2)–(6.3) ṫ1 = θ̇ t2, ṫ2 = −θ̇ t1, ṫ3 = 0
    const Vec3 t1_rate = derivative_vector([&](double s) { return Vec3(R(s) * b.p1); }, t);
    const Vec3 t2_rate = derivative_vector([&](double s) { return Vec3(R(s) * b.p2); }, t);
    ASSERT_LE(max_abs_diff(t1_rate, theta_rate * (Rt * b.p2)), kFdTolerance) << n;
    ASSERT_LE(max_abs_diff(t2_rate, -theta_rate * (Rt * b.p1)), kFdTolerance) << n;
    ASSERT_LE(max_abs_diff(Omega * (Rt * b.p1), t1_rate), kFdTolerance) << n;
  }
}

// §6.4 W2: Ω_R = Ω (E2⊗E1 − E1⊗E2) has ε[Ω_R] = −2Ω E3, so ω_R = Ω E3.
TEST(AngularVelocity, AxialVectorW2) {
  test::Random random;
  const Vec3 E1 = basis_vector(1), E2 = basis_vector(2), E3 = basis_vector(3);
  for (int n = 0; n < 100; ++n) {
    const double Omega = random.uniform(-5.0, 5.0);
    const Tensor Omega_R = Omega * (dyad(E2, E1) - dyad(E1, E2));
    const Tensor Q = random.rotation();
    // Any rotation with this spatial angular velocity tensor: Q̇ = Ω_R Q.
    const Tensor Q_rate = Omega_R * Q;
    ASSERT_LE(max_abs_diff(angular_velocity_tensor(Q, Q_rate), Omega_R), 1e-14) << n;
    ASSERT_LE(max_abs_diff(angular_velocity(Q, Q_rate), Vec3(Omega * E3)), 1e-14) << n;
    ASSERT_LE(max_abs_diff(alternator_contract(Omega_R), Vec3(-2.0 * Omega * E3)), 1e-15) << n;
    const Vec3 a = random.vector(2.0);
    ASSERT_LE(max_abs_diff(Omega_R * a, Vec3(Omega * E3.cross(a))), 1e-14) << n;
  }
}

// Exercise 6.1(b): Ω_R = θ̇ (E2⊗E1 − E1⊗E2) = θ̇ (e_θ⊗e_r − e_r⊗e_θ), ω_R = θ̇ E3; and §A.9 W9's Ȧ.
TEST(AngularVelocity, Exercise6_1b) {
  const Vec3 E1 = basis_vector(1), E2 = basis_vector(2), E3 = basis_vector(3);
  for (const double theta : {-2.0, -0.4, 0.0, 0.9, 2.7}) {
    for (const double theta_rate : {-1.5, 0.3, 4.0}) {
      const double c = std::cos(theta), s = std::sin(theta);
      const Tensor R =
          c * dyad(E1, E1) + s * dyad(E2, E1) + c * dyad(E2, E2) - s * dyad(E1, E2) + dyad(E3, E3);
      // Ṙ differentiated by hand.
      const Tensor R_rate =
          theta_rate * (-s * dyad(E1, E1) + c * dyad(E2, E1) - s * dyad(E2, E2) - c * dyad(E1, E2));
      const Vec3 e_r = c * E1 + s * E2, e_theta = -s * E1 + c * E2;
      // (a) R = e_r⊗E1 + e_θ⊗E2 + E3⊗E3 = L(θ, E3)
      EXPECT_LE(max_abs_diff(R, dyad(e_r, E1) + dyad(e_theta, E2) + dyad(E3, E3)), 1e-15);
      EXPECT_LE(max_abs_diff(rotation_tensor(AxisAngle{E3, theta}), R), 1e-15);
      const Tensor Omega = angular_velocity_tensor(R, R_rate);
      EXPECT_LE(max_abs_diff(Omega, theta_rate * (dyad(E2, E1) - dyad(E1, E2))), 1e-14);
      EXPECT_LE(max_abs_diff(Omega, theta_rate * (dyad(e_theta, e_r) - dyad(e_r, e_theta))), 1e-14);
      EXPECT_LE(max_abs_diff(angular_velocity(R, R_rate), Vec3(theta_rate * E3)), 1e-14);
      // §A.9 W9: Ȧ = θ̇ e_θ⊗E1 − θ̇ e_r⊗E2 as the book writes it, against the derivative of
      // A(θ(t)) = L(θ0 + θ̇t, E3) by finite differences and against Q̇ = ΩQ (rotation_rate)
      const Tensor book_rate = theta_rate * (dyad(e_theta, E1) - dyad(e_r, E2));
      EXPECT_LE(max_abs_diff(R_rate, book_rate), 1e-14);
      const Tensor differenced = test::derivative(
          [&](double t) {
            return rotation_tensor(AxisAngle{E3, theta + theta_rate * t});
          },
          0.0);
      EXPECT_LE(max_abs_diff(differenced, book_rate), 1e-9);
      EXPECT_LE(max_abs_diff(rotation_rate(R, Vec3(theta_rate * E3)), book_rate), 1e-14);
    }
  }
}

// §6.4 Q̇ = Ω Q: rotation_rate(Q, ω) is the rate of a rotation spinning at the constant ω.
TEST(AngularVelocity, RotationRateGivesBackOmega) {
  test::Random random;
  for (int n = 0; n < 200; ++n) {
    const Tensor Q0 = random.rotation();
    const Vec3 omega = random.vector(3.0);
    // Q(t) = L(|ω| t, ω/|ω|) Q0 has spatial angular velocity ω.
    const auto Q = [&](double t) -> Tensor { return L(omega.norm() * t, omega.normalized()) * Q0; };
    const double t = random.uniform(-1.0, 1.0);
    const Tensor Q_rate = rotation_rate(Q(t), omega);
    ASSERT_LE(max_abs_diff(Q_rate, derivative(Q, t)), kFdTolerance) << n;
    ASSERT_LE(max_abs_diff(angular_velocity(Q(t), Q_rate), omega), 1e-14) << n;
    ASSERT_LE(max_abs_diff(body_angular_velocity(Q(t), Q_rate), Vec3(Q(t).transpose() * omega)),
              1e-14)
        << n;
  }
}

// §6.4 corotational rate of a vector: a = Q a0 has å = Q ȧ0 and ȧ = å + ω × a.
TEST(AngularVelocity, CorotationalRateOfVector) {
  test::Random random;
  for (int n = 0; n < 100; ++n) {
    const RotationPath path = random_path(random);
    const Vec3 k = random.vector(2.0);
    // Components on the rotating basis.
    const auto a0 = [&](double t) -> Vec3 {
      return Vec3(std::sin(k.x() * t), std::cos(k.y() * t) + 0.5, t * t * k.z());
    };
    const auto a0_rate = [&](double t) -> Vec3 {
      return Vec3(k.x() * std::cos(k.x() * t), -k.y() * std::sin(k.y() * t), 2.0 * t * k.z());
    };
    const auto a = [&](double t) -> Vec3 { return path.Q(t) * a0(t); };
    const double t = random.uniform(-1.5, 1.5);
    const Vec3 a_rate = derivative_vector(a, t);
    const Vec3 expected = path.Q(t) * a0_rate(t);
    const Vec3 found = corotational_rate(a(t), a_rate, path.omega(t));
    ASSERT_LE(max_abs_diff(found, expected), kFdTolerance) << n;
    // And with the exact ȧ = Q ȧ0 + ω × Q a0 the identity is exact to round-off.
    const Vec3 a_rate_exact = expected + path.omega(t).cross(a(t));
    ASSERT_LE(max_abs_diff(corotational_rate(a(t), a_rate_exact, path.omega(t)), expected), 1e-13)
        << n;
    // A vector fixed in the rotating basis has zero corotational rate.
    const auto fixed = [&](double s) -> Vec3 { return path.Q(s) * k; };
    ASSERT_LE(corotational_rate(fixed(t), derivative_vector(fixed, t), path.omega(t)).norm(),
              kFdTolerance)
        << n;
  }
}

// §6.4 corotational rate of a tensor: A = Q A0 Qᵀ has Å = Q Ȧ0 Qᵀ and Ȧ = Å + Ω A − A Ω.
TEST(AngularVelocity, CorotationalRateOfTensor) {
  test::Random random;
  for (int n = 0; n < 100; ++n) {
    const RotationPath path = random_path(random);
    Tensor K, M;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        K(i, j) = random.uniform(-1.0, 1.0);
        M(i, j) = random.uniform(0.3, 1.5);
      }
    }
    // A0_ij(t) = K_ij sin(M_ij t) + j − i: not symmetric.
    const auto A0 = [&](double t) -> Tensor {
      Tensor A;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(i, j) = K(i, j) * std::sin(M(i, j) * t) + (j - i);
      return A;
    };
    const auto A0_rate = [&](double t) -> Tensor {
      Tensor A;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) A(i, j) = K(i, j) * M(i, j) * std::cos(M(i, j) * t);
      return A;
    };
    const auto A = [&](double t) -> Tensor { return path.Q(t) * A0(t) * path.Q(t).transpose(); };
    const double t = random.uniform(-1.5, 1.5);
    const Tensor expected = path.Q(t) * A0_rate(t) * path.Q(t).transpose();
    const Tensor found = corotational_rate(A(t), derivative(A, t), path.omega(t));
    ASSERT_LE(max_abs_diff(found, expected), kFdTolerance) << n;
    // A tensor with constant components on the rotating basis has zero corotational rate.
    const auto fixed = [&](double s) -> Tensor { return path.Q(s) * K * path.Q(s).transpose(); };
    ASSERT_LE(
        corotational_rate(fixed(t), derivative(fixed, t), path.omega(t)).cwiseAbs().maxCoeff(),
        kFdTolerance)
        << n;
  }
}

// (6.17)–(6.18) ω̂_R2 = ω_R − ω_R1 for R = R2 R1, with both sides from finite differences.
TEST(AngularVelocity, RelativeAngularVelocity617) {
  test::Random random;
  for (int n = 0; n < 100; ++n) {
    const RotationPath p1 = random_path(random);
    const RotationPath p2 = random_path(random);
    const double t = random.uniform(-1.5, 1.5);
    const auto R = [&](double s) -> Tensor { return p2.Q(s) * p1.Q(s); };
    const Vec3 omega_R = axial_of(derivative(R, t) * R(t).transpose());
    const Vec3 omega_R1 =
        axial_of(derivative([&](double s) { return p1.Q(s); }, t) * p1.Q(t).transpose());
    const Vec3 found = relative_angular_velocity(p1.Q(t), p1.Q_rate(t), p2.Q(t), p2.Q_rate(t));
    ASSERT_LE(max_abs_diff(found, Vec3(omega_R - omega_R1)), kFdTolerance) << n;
    // In general it is not the angular velocity of R2 alone.
    ASSERT_GT(max_abs_diff(found, p2.omega(t)), 1e-3) << n;
  }
}

// (6.17) ω̂_R2 = φ̇2 r2 + sin φ2 r̊2 + (1 − cos φ2) r2 × r̊2 for R2 = L(φ2, R1 n(t)).
TEST(AngularVelocity, RelativeAngularVelocityAxisAngleForm617) {
  test::Random random;
  for (int n = 0; n < 100; ++n) {
    const RotationPath p1 = random_path(random);
    const Vec3 k = random.vector(1.0), c = Vec3(1.0, -0.5, 0.7) + random.vector(0.3);
    const double a = random.uniform(0.3, 2.5), b = random.uniform(-1.0, 1.0);
    const auto nvec = [&](double t) -> Vec3 {
      return Vec3(c.x() + k.x() * std::sin(t), c.y() + k.y() * std::cos(t), c.z() + k.z() * t)
          .normalized();
    };
    const auto phi2 = [&](double t) { return a + b * t; };
    const auto R2 = [&](double t) -> Tensor { return L(phi2(t), Vec3(p1.Q(t) * nvec(t))); };
    const double t = random.uniform(-1.0, 1.0);
    const Vec3 r2 = p1.Q(t) * nvec(t);
    const Vec3 r2_corotational = p1.Q(t) * derivative_vector(nvec, t);
    const Vec3 expected = b * r2 + std::sin(phi2(t)) * r2_corotational +
                          (1.0 - std::cos(phi2(t))) * r2.cross(r2_corotational);
    const Vec3 found = relative_angular_velocity(p1.Q(t), p1.Q_rate(t), R2(t), derivative(R2, t));
    ASSERT_LE(max_abs_diff(found, expected), kFdTolerance) << n;
  }
}

// §6.7.1 W4 (6.19): ω̂_R2 = θ̇ t2, ω_R = θ̇ t2 + ψ̇ E3, and ω_R2 ≠ ω̂_R2.
TEST(AngularVelocity, RelativeAngularVelocityW4) {
  const Vec3 E1 = basis_vector(1), E2 = basis_vector(2), E3 = basis_vector(3);
  for (const double t : {-0.7, 0.0, 0.3, 1.1}) {
    const auto psi = [](double s) { return 0.4 + 0.8 * s; };
    const auto theta = [](double s) { return 1.1 - 0.6 * s; };
    const double psi_rate = 0.8, theta_rate = -0.6;
    const auto t1 = [&](double s) -> Vec3 { return std::cos(psi(s)) * E1 + std::sin(psi(s)) * E2; };
    const auto t2 = [&](double s) -> Vec3 { return std::cos(psi(s)) * E2 - std::sin(psi(s)) * E1; };
    const auto R1 = [&](double s) -> Tensor { return L(psi(s), E3); };
    const auto R2 = [&](double s) -> Tensor { return L(theta(s), t2(s)); };
    const auto R = [&](double s) -> Tensor { return R2(s) * R1(s); };

    const Vec3 omega_R = axial_of(derivative(R, t) * R(t).transpose());
    EXPECT_LE(max_abs_diff(omega_R, Vec3(theta_rate * t2(t) + psi_rate * E3)), kFdTolerance);

    const Vec3 relative =
        relative_angular_velocity(R1(t), derivative(R1, t), R2(t), derivative(R2, t));
    EXPECT_LE(max_abs_diff(relative, Vec3(theta_rate * t2(t))), kFdTolerance) << t;

    // ω_R2 by (6.14) with ṫ2 = −ψ̇ t1: θ̇ t2 − sin θ ψ̇ t1 + (1 − cos θ) t2 × (−ψ̇ t1).
    const Vec3 t2_rate = -psi_rate * t1(t);
    const Vec3 omega_R2_expected = theta_rate * t2(t) + std::sin(theta(t)) * t2_rate +
                                   (1.0 - std::cos(theta(t))) * t2(t).cross(t2_rate);
    const Vec3 omega_R2 = angular_velocity(R2(t), derivative(R2, t));
    EXPECT_LE(max_abs_diff(omega_R2, omega_R2_expected), kFdTolerance) << t;
    EXPECT_GT((omega_R2 - relative).norm(), 0.3) << t;
  }
}

// Exercise 6.3(c)–(d): ω_R2 = φ̇ e1 + sin φ θ̇ e2 + (1 − cos φ) θ̇ e3, ω̂_R2 = φ̇ e1.
TEST(AngularVelocity, Exercise6_3) {
  const Vec3 E1 = basis_vector(1), E2 = basis_vector(2), E3 = basis_vector(3);
  const auto theta = [](double s) { return -0.3 + 1.2 * s + 0.2 * s * s; };
  const auto phi = [](double s) { return 0.8 + 0.5 * std::sin(1.3 * s); };
  for (const double t : {-1.0, 0.2, 0.9}) {
    const double theta_rate = 1.2 + 0.4 * t;
    const double phi_rate = 0.5 * 1.3 * std::cos(1.3 * t);
    const auto e1 = [&](double s) -> Vec3 {
      return std::cos(theta(s)) * E1 + std::sin(theta(s)) * E2;
    };
    const Vec3 e2 = std::cos(theta(t)) * E2 - std::sin(theta(t)) * E1, e3 = E3;
    const auto Q1 = [&](double s) -> Tensor { return L(theta(s), E3); };
    const auto R2 = [&](double s) -> Tensor { return L(phi(s), e1(s)); };
    const auto Q2 = [&](double s) -> Tensor { return R2(s) * Q1(s); };
    // (a) Q1 = e1⊗E1 + e2⊗E2 + e3⊗E3
    EXPECT_LE(max_abs_diff(Q1(t), dyad(e1(t), E1) + dyad(e2, E2) + dyad(e3, E3)), 1e-15);
    // (c)
    const Vec3 omega_R2 = angular_velocity(R2(t), derivative(R2, t));
    const Vec3 expected = phi_rate * e1(t) + std::sin(phi(t)) * theta_rate * e2 +
                          (1.0 - std::cos(phi(t))) * theta_rate * e3;
    EXPECT_LE(max_abs_diff(omega_R2, expected), kFdTolerance) << t;
    // (d)
    const Vec3 relative =
        relative_angular_velocity(Q1(t), derivative(Q1, t), R2(t), derivative(R2, t));
    const Vec3 omega_Q2 = axial_of(derivative(Q2, t) * Q2(t).transpose());
    const Vec3 omega_Q1 = axial_of(derivative(Q1, t) * Q1(t).transpose());
    EXPECT_LE(max_abs_diff(relative, Vec3(omega_Q2 - omega_Q1)), kFdTolerance) << t;
    EXPECT_LE(max_abs_diff(relative, Vec3(phi_rate * e1(t))), kFdTolerance) << t;
    // |ω_R2 − ω̂_R2| = 2 |θ̇ sin(φ/2)| ≥ 0.25 on this path.
    EXPECT_GT((omega_R2 - relative).norm(), 0.1) << t;
  }
}

// Exercise 6.6(a), (c): B̊, ω_A = ψ̇ E3, ω̂_B = θ̇ t1, ω_B = θ̇ t1 − ψ̇ (cθ E3 − sθ t2) + ψ̇ E3.
TEST(AngularVelocity, Exercise6_6c) {
  const Vec3 E1 = basis_vector(1), E2 = basis_vector(2), E3 = basis_vector(3);
  const auto psi = [](double s) { return 0.5 + 0.7 * s; };
  const auto theta = [](double s) { return 0.9 + 0.3 * std::cos(2.0 * s); };
  for (const double t : {-0.6, 0.1, 0.8}) {
    const double psi_rate = 0.7, theta_rate = -0.6 * std::sin(2.0 * t);
    const auto t1 = [&](double s) -> Vec3 { return std::cos(psi(s)) * E1 + std::sin(psi(s)) * E2; };
    const Vec3 t2 = -std::sin(psi(t)) * E1 + std::cos(psi(t)) * E2;
    const auto A = [&](double s) -> Tensor { return L(psi(s), E3); };
    const auto B = [&](double s) -> Tensor { return L(theta(s), t1(s)); };
    const auto C = [&](double s) -> Tensor { return B(s) * A(s); };
    const Tensor A_rate = derivative(A, t), B_rate = derivative(B, t);

    const Vec3 omega_A = angular_velocity(A(t), A_rate);
    EXPECT_LE(max_abs_diff(omega_A, Vec3(psi_rate * E3)), kFdTolerance) << t;

    // (a) B = A L(θ, E1) Aᵀ has constant-axis components on {t_i}: B̊ = A (θ̇ [E1×] L(θ, E1)) Aᵀ.
    const Tensor B_corotational_expected =
        A(t) * (theta_rate * cross_matrix(E1) * L(theta(t), E1)) * A(t).transpose();
    EXPECT_LE(max_abs_diff(corotational_rate(B(t), B_rate, omega_A), B_corotational_expected),
              kFdTolerance)
        << t;

    const Vec3 relative = relative_angular_velocity(A(t), A_rate, B(t), B_rate);
    EXPECT_LE(max_abs_diff(relative, Vec3(theta_rate * t1(t))), kFdTolerance) << t;
    // (b) ω̂_B = ω_C − ω_A
    const Vec3 omega_C = axial_of(derivative(C, t) * C(t).transpose());
    EXPECT_LE(max_abs_diff(relative, Vec3(omega_C - omega_A)), kFdTolerance) << t;

    // (iii) the ω meant is that of B alone, −½ ε[Ḃ Bᵀ], i.e. (6.14) with ṫ1 = ψ̇ t2 (not ω̂_B, ω_C).
    const Vec3 omega_B = angular_velocity(B(t), B_rate);
    const Vec3 expected = theta_rate * t1(t) -
                          psi_rate * (std::cos(theta(t)) * E3 - std::sin(theta(t)) * t2) +
                          psi_rate * E3;
    EXPECT_LE(max_abs_diff(omega_B, expected), kFdTolerance) << t;
    EXPECT_GT((omega_B - relative).norm(), 0.1) << t;
  }
}

// §7.5, first example: Q(t) = L(ν̇0 t, E3) turns about its fixed axis: the axis q of Q, the axis s
// of Q(t) Qᵀ(t0) and the instantaneous axis ω/‖ω‖ are all E3, with ω = ν̇0 E3.
TEST(AngularVelocity, UniformRotationOfSection75) {
  const double rate = 1.7, t0 = 0.2;
  const auto Q = [&](double t) { return rotation_tensor(AxisAngle{basis_vector(3), rate * t}); };
  for (const double t : {0.5, 1.1, 1.6}) {
    const Vec3 omega = angular_velocity(Q(t), derivative(Q, t));
    EXPECT_LE(max_abs_diff(omega, rate * basis_vector(3)), kFdTolerance) << t;
    EXPECT_LE(max_abs_diff(axis_angle(Q(t)).axis, basis_vector(3)), 1e-15) << t;
    const AxisAngle s = axis_angle(Q(t) * Q(t0).transpose());
    EXPECT_LE(max_abs_diff(s.axis, basis_vector(3)), 1e-15) << t;
    EXPECT_NEAR(s.angle, rate * (t - t0), 1e-14) << t;
  }
}

// §7.5, (7.9): Q(t) = 2 q⊗q − I with q = cos(ν/2) E1 + sin(ν/2) E2, ν = ν̇0 (t − t0) + ν0, turns
// at the constant ω = ν̇0 E3 (= 2 q × q̇) though its axis q moves and its angle stays π; the
// rotation since t0 is Q(t) Qᵀ(t0) = L(ν − ν0, E3) (the translation's sign is wrong).
TEST(AngularVelocity, ConstantOmegaWithAMovingAxisOf79) {
  const double rate = 0.8, nu0 = 0.3, t0 = 0.0;
  const auto nu = [&](double t) { return rate * (t - t0) + nu0; };
  const auto q = [&](double t) { return Vec3(std::cos(nu(t) / 2), std::sin(nu(t) / 2), 0); };
  const auto Q = [&](double t) -> Tensor { return 2 * dyad(q(t), q(t)) - Tensor::Identity(); };
  for (const double t : {0.4, 1.3, 2.9}) {
    ASSERT_TRUE(is_rotation(Q(t)));
    const Vec3 omega = angular_velocity(Q(t), derivative(Q, t));
    EXPECT_LE(max_abs_diff(omega, rate * basis_vector(3)), kFdTolerance) << t;
    const AxisAngle own = axis_angle(Q(t));
    EXPECT_NEAR(own.angle, kPi, 1e-7) << t;
    EXPECT_NEAR(std::abs(own.axis.dot(q(t))), 1.0, 1e-12) << t;
    EXPECT_NEAR(own.axis.dot(basis_vector(3)), 0.0, 1e-12) << t;  // q ⊥ ω
    EXPECT_LE(max_abs_diff(Q(t) * Q(t0).transpose(),
                           rotation_tensor(AxisAngle{basis_vector(3), nu(t) - nu0})),
              1e-15)
        << t;
  }
}

// Exercise 11.5: in 3-1-3 angles e3 depends on ψ and θ alone; when they return, e3(t1) = e3(t0)
// and the rotation since t0 is Q(t1) Qᵀ(t0) = L(φ(t1) − φ(t0), e3(t0)) whatever happened between.
TEST(AngularVelocity, ReturnOfTheAxisOfExercise115) {
  test::Random random;
  const EulerSet set{3, 1, 3};
  for (int n = 0; n < 20; ++n) {
    const double psi = random.uniform(-3.0, 3.0), theta = random.uniform(0.2, 2.9);
    const double phi0 = random.uniform(-3.0, 3.0), phi1 = random.uniform(-3.0, 3.0);
    const Tensor Q0 = rotation_tensor(set, Vec3(psi, theta, phi0));
    const Tensor Q1 = rotation_tensor(set, Vec3(psi, theta, phi1));
    const Vec3 e3 = Q0 * basis_vector(3);
    EXPECT_LE(max_abs_diff(Q1 * basis_vector(3), e3), 1e-15);
    EXPECT_LE(max_abs_diff(Q1 * Q0.transpose(), rotation_tensor(AxisAngle{e3, phi1 - phi0})), 1e-14)
        << n;
  }
}

// Exercise 11.5(d), the geometric phase: e3 goes once around a loop on the unit sphere (3-1-3 set,
// ψ = 2πt, θ = θ0 + a sin 2πt, φ arbitrary, 0 ≤ t ≤ 1). The turn about e3 is the gyro's reading
// plus the solid angle the loop encloses about E3: φ(1) − φ(0) = ∫ ω·e3 dt − ∮ cos θ dψ
// = ∫ ω·e3 dt + A − 2π, with A = ∮ (1 − cos θ) dψ. ω and e3 from unidyn, the integrals by Simpson
// here, and the turn read off Q(1)Q(0)ᵀ = L(Δφ, e3(0)).
TEST(AngularVelocity, GeometricPhaseOfExercise115IsTheEnclosedArea) {
  const EulerSet set{3, 1, 3};
  const double theta0 = 0.8, a = 0.3, two_pi = 2 * kPi;
  const auto angles = [&](double t) {
    return Vec3(two_pi * t, theta0 + a * std::sin(two_pi * t),
                0.5 * std::sin(two_pi * t) + 0.7 * t);
  };
  const auto rates = [&](double t) {
    return Vec3(two_pi, a * two_pi * std::cos(two_pi * t),
                0.5 * two_pi * std::cos(two_pi * t) + 0.7);
  };
  const int steps = 2000;  // even, for Simpson
  double gyro = 0, area = 0;
  for (int k = 0; k <= steps; ++k) {
    const double t = static_cast<double>(k) / steps;
    const double weight = (k == 0 || k == steps) ? 1.0 : (k % 2 == 1 ? 4.0 : 2.0);
    const Vec3 e3 = rotation_tensor(set, angles(t)) * basis_vector(3);
    gyro += weight * angular_velocity(set, angles(t), rates(t)).dot(e3);
    area += weight * (1 - std::cos(angles(t)[1])) * rates(t)[0];
  }
  gyro /= 3.0 * steps;
  area /= 3.0 * steps;
  const Tensor Q0 = rotation_tensor(set, angles(0)), Q1 = rotation_tensor(set, angles(1));
  const Vec3 e3 = Q0 * basis_vector(3);
  EXPECT_LE(max_abs_diff(Q1 * basis_vector(3), e3), 1e-14);  // the loop closes
  const double turn = angles(1)[2] - angles(0)[2];
  EXPECT_NEAR(turn, gyro + area - two_pi, 1e-10);
  EXPECT_LE(max_abs_diff(Q1 * Q0.transpose(), test::book_L(gyro + area, e3)), 1e-10);
  // the enclosed area is what makes the difference: the gyro alone misses it by far
  EXPECT_GT(std::abs(std::remainder(turn - gyro, two_pi)), 0.5);
  std::printf("gyro %.12f, area %.12f, turn %.12f\n", gyro, area, turn);
}

}  // namespace
}  // namespace unidyn
