// The Rodrigues (Gibbs) vector λ = tan(φ/2) r, book §6.9.
#include "unidyn/rotation/rodrigues_vector.hpp"

#include <cmath>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"
#include "unidyn/rotation/euler_parameters.hpp"

namespace unidyn {
namespace {

using test::kPi;

// (6.8) typed from the book, applied to each E_k: L(φ, r) a = cos φ (a − (r·a) r) − sin φ (a × r)
// + (r·a) r, since (εr) a = a × r.
Tensor book_L(double phi, const Vec3& r) {
  Tensor L;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = Vec3::Unit(k);
    L.col(k) = std::cos(phi) * (a - r.dot(a) * r) - std::sin(phi) * a.cross(r) + r.dot(a) * r;
  }
  return L;
}

// (6.36) R̃(λ) = ((1 − λ·λ) I + 2 λ⊗λ − 2 ελ) / (1 + λ·λ), typed column by column with
// (ελ) a = a × λ.
Tensor book_R_tilde(const Vec3& l) {
  const double ll = l.dot(l);
  Tensor R;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = Vec3::Unit(k);
    R.col(k) = ((1.0 - ll) * a + 2.0 * l.dot(a) * l - 2.0 * a.cross(l)) / (1.0 + ll);
  }
  return R;
}

// The axial vector of the skew part of W: W a = w × a for skew W, so w = (W32, W13, W21).
Vec3 axial_of(const Tensor& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// (6.36): R̃(λ) with λ = tan(φ/2) r is L(φ, r), proper orthogonal.
TEST(RodriguesVector, RotationTensorEqualsBookFormAndAxisAngle636) {
  test::Random rng(201);
  for (int n = 0; n < 3000; ++n) {
    const Vec3 r = rng.unit_vector();
    const double phi = rng.uniform(-kPi + 1e-3, kPi - 1e-3);
    const RodriguesVector v{std::tan(0.5 * phi) * r};
    const Tensor Q = rotation_tensor(v);
    EXPECT_LT(test::max_abs_diff(Q, book_R_tilde(v.lambda)), 1e-14);
    EXPECT_LT(test::max_abs_diff(Q, book_L(phi, r)), 1e-13);
    EXPECT_LT(test::max_abs_diff(Tensor(Q * Q.transpose()), Tensor::Identity()), 1e-14);
    EXPECT_NEAR(Q.determinant(), 1.0, 1e-14);
  }
  // λ = 0 is the identity.
  EXPECT_EQ(rotation_tensor(RodriguesVector{Vec3::Zero()}), Tensor::Identity());
}

// §6.9 / item 19: cos φ = (1 − λ·λ)/(1 + λ·λ), sin φ = 2 λ·r/(1 + λ·λ).
TEST(RodriguesVector, HalfAngleIdentities) {
  // λ's condition number grows like 1 + λ·λ, hence the relative tolerance on λ.
  test::Random rng(202);
  for (int n = 0; n < 3000; ++n) {
    const Vec3 r = rng.unit_vector();
    const double phi = rng.uniform(1e-3, kPi - 1e-3);
    const Vec3 l = rodrigues_vector(book_L(phi, r)).lambda;
    const double ll = l.dot(l);
    EXPECT_NEAR((1.0 - ll) / (1.0 + ll), std::cos(phi), 1e-14);
    EXPECT_NEAR(2.0 * l.dot(r) / (1.0 + ll), std::sin(phi), 1e-14);
    EXPECT_NEAR(rotation_tensor(RodriguesVector{l}).trace(), 1.0 + 2.0 * std::cos(phi), 1e-14);
    // λ = tan(φ/2) r, relative to its size (its condition number grows like 1 + λ·λ).
    EXPECT_LT(test::max_abs_diff(l, Vec3(std::tan(0.5 * phi) * r)), 1e-15 * (1.0 + ll));
  }
}

// §6.9 λ = e/e0: round trips through rotation tensors and Euler parameters.
TEST(RodriguesVector, RoundTrips) {
  test::Random rng(203);
  for (int n = 0; n < 5000; ++n) {
    // A unit quaternion (e0, e) built here, e0 ≠ 0, with its rotation tensor in components (6.36).
    const double theta = rng.uniform(-kPi + 1e-3, kPi - 1e-3);
    const double e0 = std::cos(0.5 * theta);
    const Vec3 e = std::sin(0.5 * theta) * rng.unit_vector();
    const Tensor Q = book_R_tilde(e / e0);
    const Vec3 expected = e / e0;
    const double size = 1.0 + expected.squaredNorm();

    const RodriguesVector v = rodrigues_vector(Q);
    EXPECT_LT(test::max_abs_diff(v.lambda, expected), 1e-15 * size);
    EXPECT_LT(test::max_abs_diff(rotation_tensor(v), Q), 1e-14);

    // e0 = 1/√(1 + λ·λ), e = λ e0; and back, for both signs ±p of the quaternion.
    const EulerParameters p = euler_parameters(v);
    const double norm = std::sqrt(1.0 + v.lambda.squaredNorm());
    EXPECT_NEAR(p.e0, 1.0 / norm, 1e-15);
    EXPECT_LT(test::max_abs_diff(p.e, Vec3(v.lambda / norm)), 1e-15);
    EXPECT_NEAR(p.e0 * p.e0 + p.e.squaredNorm(), 1.0, 1e-15);
    EXPECT_LT(test::max_abs_diff(rotation_tensor(p), Q), 1e-14);
    EXPECT_LT(test::max_abs_diff(rodrigues_vector(p).lambda, v.lambda), 1e-15 * size);
    EXPECT_LT(test::max_abs_diff(rodrigues_vector(EulerParameters{-e0, -e}).lambda, expected),
              1e-15 * size);

    // Shoemake-uniform rotations from the oracles.
    const Tensor R = rng.rotation();
    EXPECT_LT(test::max_abs_diff(book_R_tilde(rodrigues_vector(R).lambda), R), 1e-12);
  }
}

// §6.5.1 example W3: λ = (0.0129067, −0.2579190, 0.1511352) to the printed ~1e-6.
TEST(RodriguesVector, BookExampleW3) {
  Tensor Q;
  Q << 0.835959, -0.283542, -0.469869,  //
      0.271321, 0.957764, -0.0952472,   //
      0.47703, -0.0478627, 0.877583;
  const Vec3 l = rodrigues_vector(Q).lambda;
  EXPECT_NEAR(l(0), 0.0129067, 1e-6);
  EXPECT_NEAR(l(1), -0.2579190, 1e-6);
  EXPECT_NEAR(l(2), 0.1511352, 1e-6);
}

// §6.9: λ is undefined at φ = π; rodrigues_vector throws SingularConfiguration.
TEST(RodriguesVector, ThrowsAtHalfTurn) {
  test::Random rng(204);
  std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                            Vec3(1.0, 1.0, 1.0).normalized()};
  for (int n = 0; n < 20; ++n) axes.push_back(rng.unit_vector());
  for (const Vec3& r : axes) {
    SCOPED_TRACE(testing::Message() << "r = " << r.transpose());
    EXPECT_THROW(rodrigues_vector(book_L(kPi, r)), SingularConfiguration);
    EXPECT_THROW(rodrigues_vector(book_L(-kPi, r)), SingularConfiguration);
    EXPECT_THROW(rodrigues_vector(EulerParameters{0.0, r}), SingularConfiguration);
  }
}

// §6.9 near φ = π: λ is large but defined, and round trips relative to its size.
TEST(RodriguesVector, NearHalfTurnRoundTrips) {
  // Q carries round-off ~1e-16, so e0 = cos(φ/2) is known to ~1e-16 and λ = e/e0 to ~1e-16/e0
  // relatively.
  test::Random rng(205);
  std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                            Vec3(1.0, 1.0, 1.0).normalized()};
  for (int n = 0; n < 20; ++n) axes.push_back(rng.unit_vector());
  for (const Vec3& r : axes) {
    for (const double phi : {kPi - 1e-6, kPi - 1e-9, -(kPi - 1e-6)}) {
      SCOPED_TRACE(testing::Message() << "phi = " << phi << ", r = " << r.transpose());
      const Tensor Q = book_L(phi, r);
      const Vec3 expected = std::tan(0.5 * phi) * r;
      const double e0 = std::cos(0.5 * phi);
      RodriguesVector v{};
      ASSERT_NO_THROW(v = rodrigues_vector(Q));
      EXPECT_LT((v.lambda - expected).norm() / expected.norm(), 1e-15 / e0);
      EXPECT_LT(test::max_abs_diff(rotation_tensor(v), Q), 1e-12);
    }
  }
}

// (6.38): ω = 2 (λ̇ − λ̇ × λ)/(1 + λ·λ) equals −½ ε[Q̇ Qᵀ] by finite differences.
TEST(RodriguesVector, AngularVelocityMatchesFiniteDifferences638) {
  // Fourth-order differences of R̃(λ(t)): error O(h⁴) ~ 1e-12 for these smooth paths.
  test::Random rng(206);
  for (int n = 0; n < 300; ++n) {
    const Vec3 l0 = rng.vector(2.0), l1 = rng.vector(1.0), l2 = rng.vector(0.5);
    const auto lambda = [&](double t) -> Vec3 { return l0 + t * l1 + t * t * l2; };
    const auto Q_of = [&](double t) -> Tensor { return book_R_tilde(lambda(t)); };
    const double t = rng.uniform(-0.5, 0.5);
    const Vec3 lambda_rate = l1 + 2.0 * t * l2;
    const Tensor Q = Q_of(t);
    const Vec3 expected = axial_of(test::derivative(Q_of, t) * Q.transpose());
    const Vec3 omega = angular_velocity(RodriguesVector{lambda(t)}, lambda_rate);
    EXPECT_LT(test::max_abs_diff(omega, expected), 1e-10) << "n = " << n;
  }
}

// (6.38) inverted: λ̇ = ½ (ω + ω × λ + (λ·ω) λ), algebraically and by finite differences.
TEST(RodriguesVector, RateInvertsAngularVelocity638) {
  // Along Q(t) = L(φ(t), r(t)): ω from differences of Q, λ̇ from differences of tan(φ/2) r.
  test::Random rng(207);
  for (int n = 0; n < 3000; ++n) {
    const RodriguesVector v{rng.vector(3.0)};
    const double size = 1.0 + v.lambda.squaredNorm();
    const Vec3 omega = rng.vector(5.0);
    EXPECT_LT(test::max_abs_diff(angular_velocity(v, rodrigues_vector_rate(v, omega)), omega),
              1e-14 * size);
    const Vec3 lambda_rate = rng.vector(5.0);
    EXPECT_LT(
        test::max_abs_diff(rodrigues_vector_rate(v, angular_velocity(v, lambda_rate)), lambda_rate),
        1e-14 * size);
  }
  for (int n = 0; n < 300; ++n) {
    const double phi0 = rng.uniform(-2.5, 2.5), phi1 = rng.uniform(-1.0, 1.0);
    const Vec3 r0 = rng.unit_vector(), r1 = rng.vector(0.5);
    const auto phi = [&](double t) { return phi0 + phi1 * t; };
    const auto axis = [&](double t) -> Vec3 { return (r0 + t * r1).normalized(); };
    const auto Q_of = [&](double t) -> Tensor { return book_L(phi(t), axis(t)); };
    const double t = rng.uniform(-0.2, 0.2);
    const Tensor Q = Q_of(t);
    const Vec3 omega = axial_of(test::derivative(Q_of, t) * Q.transpose());
    Vec3 lambda_rate;
    for (int i = 0; i < 3; ++i) {
      lambda_rate(i) =
          test::derivative([&](double s) { return std::tan(0.5 * phi(s)) * axis(s)(i); }, t);
    }
    const RodriguesVector v{std::tan(0.5 * phi(t)) * axis(t)};
    EXPECT_LT(test::max_abs_diff(rodrigues_vector_rate(v, omega), lambda_rate), 1e-9)
        << "n = " << n;
  }
}

}  // namespace
}  // namespace unidyn
