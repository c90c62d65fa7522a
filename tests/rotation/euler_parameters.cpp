// Euler–Rodrigues symmetric parameters (unit quaternions), book §6.9 and Exercise 6.4.
#include "unidyn/rotation/euler_parameters.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

using test::book_L;

using test::kPi;
using Vec4 = Eigen::Vector4d;

// (6.36) in components, typed from the book:
// [R] = (e0² − e1² − e2² − e3²) I + 2 [e_i e_k] + [[0, −2e0e3, 2e0e2], [2e0e3, 0, −2e0e1],
// [−2e0e2, 2e0e1, 0]].
Tensor component_form(double e0, const Vec3& e) {
  const double e1 = e(0), e2 = e(1), e3 = e(2);
  const double d = e0 * e0 - e1 * e1 - e2 * e2 - e3 * e3;
  Tensor R;
  R << d + 2 * e1 * e1, 2 * e1 * e2 - 2 * e0 * e3, 2 * e1 * e3 + 2 * e0 * e2,  //
      2 * e2 * e1 + 2 * e0 * e3, d + 2 * e2 * e2, 2 * e2 * e3 - 2 * e0 * e1,   //
      2 * e3 * e1 - 2 * e0 * e2, 2 * e3 * e2 + 2 * e0 * e1, d + 2 * e3 * e3;
  return R;
}

// The axial vector of the skew part of W: W a = w × a for skew W, so w = (W32, W13, W21).
Vec3 axial_of(const Tensor& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// C a = c × a, typed from the cross product.
Tensor cross_matrix(const Vec3& c) {
  Tensor C;
  C << 0, -c(2), c(1),  //
      c(2), 0, -c(0),   //
      -c(1), c(0), 0;
  return C;
}

Vec4 as_vec4(const EulerParameters& p) {
  return Vec4(p.e0, p.e(0), p.e(1), p.e(2));
}

EulerParameters from_vec4(const Vec4& q) {
  return {q(0), Vec3(q(1), q(2), q(3))};
}

// A random unit quaternion (cos(θ/2), sin(θ/2) r), θ ∈ (0, 2π), so both signs of e0 occur.
EulerParameters random_unit(test::Random& rng) {
  const double theta = rng.uniform(0.0, 2.0 * kPi);
  return {std::cos(0.5 * theta), std::sin(0.5 * theta) * rng.unit_vector()};
}

// Distance between two quaternions up to the sign ±p, which give the same rotation.
double distance_up_to_sign(const EulerParameters& p, const EulerParameters& q) {
  return std::min((as_vec4(p) - as_vec4(q)).cwiseAbs().maxCoeff(),
                  (as_vec4(p) + as_vec4(q)).cwiseAbs().maxCoeff());
}

// (6.36): R̄(e0, e) equals the component form of (6.36) typed out, unit or not.
TEST(EulerParameters, RotationTensorEqualsComponentForm636) {
  test::Random rng(101);
  for (int n = 0; n < 2000; ++n) {
    const EulerParameters p = random_unit(rng);
    EXPECT_LT(test::max_abs_diff(rotation_tensor(p), component_form(p.e0, p.e)), 1e-15);
    // (6.36) is a quadratic form, also for non-unit (e0, e).
    const EulerParameters q{rng.uniform(-2.0, 2.0), rng.vector(2.0)};
    EXPECT_LT(test::max_abs_diff(rotation_tensor(q), component_form(q.e0, q.e)), 1e-14);
  }
}

// (6.36) with e0 = cos(φ/2), e = sin(φ/2) r is L(φ, r) of (6.8), proper orthogonal (6.6).
TEST(EulerParameters, RotationTensorEqualsAxisAngleForm) {
  test::Random rng(102);
  for (int n = 0; n < 2000; ++n) {
    const Vec3 r = rng.unit_vector();
    const double phi = rng.uniform(-2.0 * kPi, 2.0 * kPi);
    const EulerParameters p{std::cos(0.5 * phi), std::sin(0.5 * phi) * r};
    const Tensor Q = rotation_tensor(p);
    EXPECT_LT(test::max_abs_diff(Q, book_L(phi, r)), 1e-14);
    EXPECT_LT(test::max_abs_diff(Q, rotation_tensor(AxisAngle{r, phi})), 1e-14);
    EXPECT_LT(test::max_abs_diff(Tensor(Q * Q.transpose()), Tensor::Identity()), 1e-14);
    EXPECT_NEAR(Q.determinant(), 1.0, 1e-14);
  }
}

// (6.36) inverted: thousands of random rotations give back ±p with e0 ≥ 0.
TEST(EulerParameters, RoundTripRandomRotations) {
  // Q entries carry round-off ~1e-16 and Shepperd's method divides by no less than ½.
  test::Random rng(103);
  for (int n = 0; n < 5000; ++n) {
    const EulerParameters q = random_unit(rng);
    const Tensor Q = component_form(q.e0, q.e);
    const EulerParameters p = euler_parameters(Q);
    EXPECT_GE(p.e0, 0.0);
    EXPECT_NEAR(p.e0 * p.e0 + p.e.squaredNorm(), 1.0, 1e-15);
    EXPECT_LT(distance_up_to_sign(p, q), 2e-15);
    // e0 ≥ 0 fixes the sign: p = sign(q0) q.
    const double sign = q.e0 >= 0.0 ? 1.0 : -1.0;
    EXPECT_LT((as_vec4(p) - sign * as_vec4(q)).cwiseAbs().maxCoeff(), 2e-15) << "q0 = " << q.e0;
    EXPECT_LT(test::max_abs_diff(rotation_tensor(p), Q), 1e-14);

    // Shoemake-uniform rotations built independently in the oracles.
    const Tensor R = rng.rotation();
    const EulerParameters pr = euler_parameters(R);
    EXPECT_GE(pr.e0, 0.0);
    EXPECT_NEAR(pr.e0 * pr.e0 + pr.e.squaredNorm(), 1.0, 1e-15);
    EXPECT_LT(test::max_abs_diff(component_form(pr.e0, pr.e), R), 1e-14);
  }
}

// (6.36) inverted at φ = 0, tiny φ, and at and near π (e0 → 0) about several axes.
TEST(EulerParameters, RoundTripSpecialAngles) {
  // Absolute tolerance 2e-15: Q carries round-off ~1e-16; compare ±p at π where the sign is free.
  test::Random rng(104);
  std::vector<Vec3> axes = {Vec3::UnitX(), Vec3::UnitY(), Vec3::UnitZ(),
                            Vec3(1.0, 1.0, 1.0).normalized(), -Vec3(1.0, 1.0, 1.0).normalized()};
  for (int n = 0; n < 20; ++n) axes.push_back(rng.unit_vector());
  const std::vector<double> angles = {0.0, 1e-9,  1e-6,          kPi - 1e-6, kPi - 1e-9,
                                      kPi, -1e-9, -(kPi - 1e-9), kPi + 1e-9, 2.0 * kPi - 1e-9};
  for (const Vec3& r : axes) {
    for (const double phi : angles) {
      const Tensor Q = book_L(phi, r);
      const EulerParameters p = euler_parameters(Q);
      const EulerParameters expected{std::cos(0.5 * phi), std::sin(0.5 * phi) * r};
      SCOPED_TRACE(testing::Message() << "phi = " << phi << ", r = " << r.transpose());
      EXPECT_GE(p.e0, 0.0);
      EXPECT_NEAR(p.e0 * p.e0 + p.e.squaredNorm(), 1.0, 1e-15);
      EXPECT_LT(distance_up_to_sign(p, expected), 2e-15);
      EXPECT_LT(test::max_abs_diff(rotation_tensor(p), Q), 1e-12);
      EXPECT_LT(test::max_abs_diff(component_form(p.e0, p.e), Q), 4e-15);
      // The angle 2 atan2(|e|, e0) ∈ [0, π] is |φ| reduced to [0, π].
      const double reduced = std::abs(std::remainder(phi, 2.0 * kPi));
      EXPECT_NEAR(axis_angle(p).angle, reduced, 4e-15);
    }
  }
}

// §6.5.1 example W3: e0 = 0.9580326, e = (0.0123650, −0.2470948, 0.1447925).
TEST(EulerParameters, BookExampleW3) {
  // The matrix is printed to 6 digits, which limits agreement to ~1e-6.
  Tensor Q;
  Q << 0.835959, -0.283542, -0.469869,  //
      0.271321, 0.957764, -0.0952472,   //
      0.47703, -0.0478627, 0.877583;
  const EulerParameters p = euler_parameters(Q);
  EXPECT_NEAR(p.e0, 0.9580326, 1e-6);
  EXPECT_NEAR(p.e(0), 0.0123650, 1e-6);
  EXPECT_NEAR(p.e(1), -0.2470948, 1e-6);
  EXPECT_NEAR(p.e(2), 0.1447925, 1e-6);
  // and the axis and angle of W3: θ = 33.3161°, r = (0.043135, −0.861981, 0.505103).
  const AxisAngle aa = axis_angle(p);
  EXPECT_NEAR(aa.angle * 180.0 / kPi, 33.3161, 1e-4);
  EXPECT_LT(test::max_abs_diff(aa.axis, Vec3(0.043135, -0.861981, 0.505103)), 2e-6);
}

// (6.48)–(6.49): C = B A ↔ (e0 f0 − e·f, e0 f + f0 e + f × e), and Ex. 6.4(d).
TEST(EulerParameters, CompositionIsTensorProduct649) {
  test::Random rng(105);
  for (int n = 0; n < 3000; ++n) {
    const EulerParameters A = random_unit(rng), B = random_unit(rng);
    const EulerParameters C = compose(B, A);
    const Tensor expected = component_form(B.e0, B.e) * component_form(A.e0, A.e);
    EXPECT_LT(test::max_abs_diff(component_form(C.e0, C.e), expected), 1e-14);
    EXPECT_NEAR(C.e0 * C.e0 + C.e.squaredNorm(), 1.0, 1e-14);
    // Ex. 6.4(d): A B swaps the roles, and (A B)ᵀ = Bᵀ Aᵀ is the conjugate (e0, −e).
    const EulerParameters AB = compose(A, B);
    EXPECT_LT(test::max_abs_diff(component_form(AB.e0, AB.e),
                                 Tensor(component_form(A.e0, A.e) * component_form(B.e0, B.e))),
              1e-14);
    const EulerParameters BtAt = compose(EulerParameters{B.e0, -B.e}, EulerParameters{A.e0, -A.e});
    EXPECT_NEAR(BtAt.e0, AB.e0, 1e-15);
    EXPECT_LT(test::max_abs_diff(BtAt.e, Vec3(-AB.e)), 1e-15);
  }
}

// Ex. 6.4(e) / (6.49): A B ≠ B A, the two differing by the sign of f × e.
TEST(EulerParameters, CompositionIsNotCommutativeEx64e) {
  test::Random rng(106);
  for (int n = 0; n < 1000; ++n) {
    const EulerParameters A = random_unit(rng), B = random_unit(rng);
    const EulerParameters BA = compose(B, A), AB = compose(A, B);
    EXPECT_NEAR(BA.e0, AB.e0, 1e-15);
    EXPECT_LT(test::max_abs_diff(Vec3(BA.e - AB.e), Vec3(2.0 * B.e.cross(A.e))), 1e-15);
    if (B.e.cross(A.e).norm() > 1e-2) {
      EXPECT_GT(test::max_abs_diff(rotation_tensor(BA), rotation_tensor(AB)), 1e-3);
    }
    // Same axis: the rotations commute.
    const Vec3 r = rng.unit_vector();
    const double a = rng.uniform(-kPi, kPi), b = rng.uniform(-kPi, kPi);
    const EulerParameters P{std::cos(a / 2), std::sin(a / 2) * r};
    const EulerParameters R{std::cos(b / 2), std::sin(b / 2) * r};
    EXPECT_LT(test::max_abs_diff(as_vec4(compose(P, R)), as_vec4(compose(R, P))), 1e-15);
    // and the result is the rotation by a + b about r.
    EXPECT_LT(test::max_abs_diff(rotation_tensor(compose(P, R)), book_L(a + b, r)), 1e-14);
  }
}

// Ex. 6.4(g) / (6.49): L(π/2, E2) L(π/2, E3) ↔ g0 = ½, g = ½(1, 1, 1), C = L(2π/3, (1,1,1)/√3).
TEST(EulerParameters, Exercise64g) {
  const double h = 1.0 / std::sqrt(2.0);
  const EulerParameters A{h, h * Vec3::UnitZ()};
  const EulerParameters B{h, h * Vec3::UnitY()};
  const EulerParameters C = compose(B, A);
  EXPECT_NEAR(C.e0, 0.5, 1e-15);
  EXPECT_LT(test::max_abs_diff(C.e, Vec3(0.5, 0.5, 0.5)), 1e-15);
  Tensor expected;
  expected << 0, 0, 1,  //
      1, 0, 0,          //
      0, 1, 0;
  EXPECT_LT(test::max_abs_diff(rotation_tensor(C), expected), 1e-15);
  EXPECT_LT(test::max_abs_diff(rotation_tensor(C),
                               book_L(2.0 * kPi / 3.0, Vec3(1, 1, 1) / std::sqrt(3.0))),
            1e-15);
  // Item 9: L(π/2, E3) has components [[0,−1,0],[1,0,0],[0,0,1]].
  Tensor L3;
  L3 << 0, -1, 0,  //
      1, 0, 0,     //
      0, 0, 1;
  EXPECT_LT(test::max_abs_diff(rotation_tensor(A), L3), 1e-15);
}

// §6.9: e0 = cos(φ/2), e = sin(φ/2) r and back, φ ∈ [0, 2π) following the sign of e0.
TEST(EulerParameters, AxisAngleRoundTrip) {
  test::Random rng(107);
  for (int n = 0; n < 3000; ++n) {
    const Vec3 r = rng.unit_vector();
    const double phi = rng.uniform(1e-3, 2.0 * kPi - 1e-3);
    const double scale = rng.uniform(0.1, 10.0);
    // A non-unit axis is normalised.
    const EulerParameters p = euler_parameters(AxisAngle{scale * r, phi});
    EXPECT_NEAR(p.e0, std::cos(0.5 * phi), 1e-15);
    EXPECT_LT(test::max_abs_diff(p.e, Vec3(std::sin(0.5 * phi) * r)), 1e-15);
    const AxisAngle back = axis_angle(p);
    EXPECT_NEAR(back.angle, phi, 1e-13);
    EXPECT_LT(test::max_abs_diff(back.axis, r), 1e-12);
    EXPECT_LT(test::max_abs_diff(rotation_tensor(back), book_L(phi, r)), 1e-14);
  }
  // e = 0: the axis is E3, the angle 0 for e0 = 1 and 2π for e0 = −1.
  const AxisAngle identity = axis_angle(EulerParameters{1.0, Vec3::Zero()});
  EXPECT_EQ(identity.angle, 0.0);
  EXPECT_EQ(identity.axis, Vec3::UnitZ());
  const AxisAngle full_turn = axis_angle(EulerParameters{-1.0, Vec3::Zero()});
  EXPECT_NEAR(full_turn.angle, 2.0 * kPi, 1e-15);
  EXPECT_EQ(full_turn.axis, Vec3::UnitZ());
  EXPECT_THROW(euler_parameters(AxisAngle{Vec3::Zero(), 1.0}), NotARotation);
}

// §6.9 e0² + e·e = 1: normalised() scales onto the unit sphere without turning p.
TEST(EulerParameters, Normalised) {
  test::Random rng(108);
  for (int n = 0; n < 2000; ++n) {
    const EulerParameters q{rng.uniform(-3.0, 3.0), rng.vector(3.0)};
    const double norm = as_vec4(q).norm();
    const EulerParameters p = normalised(q);
    EXPECT_NEAR(as_vec4(p).norm(), 1.0, 1e-15);
    EXPECT_LT(test::max_abs_diff(Vec4(norm * as_vec4(p)), as_vec4(q)), 1e-14);
    EXPECT_LT(test::max_abs_diff(as_vec4(normalised(p)), as_vec4(p)), 1e-15);
  }
  EXPECT_THROW(normalised(EulerParameters{0.0, Vec3::Zero()}), NotARotation);
  EXPECT_THROW(normalised(EulerParameters{std::numeric_limits<double>::quiet_NaN(), Vec3::Zero()}),
               NotARotation);
}

// §6.9 e0² + e·e = 1: finite non-zero p is normalised even if |p|² under/overflows.
TEST(EulerParameters, NormalisedExtremeScales) {
  // The header promises NotARotation only for a zero quaternion.
  for (const double scale : {1e-200, 1e-160, 1e160, 1e200}) {
    const EulerParameters q{0.6 * scale, Vec3(0.0, 0.8 * scale, 0.0)};
    SCOPED_TRACE(testing::Message() << "scale = " << scale);
    EulerParameters p{};
    try {
      p = normalised(q);
    } catch (const std::exception& error) {
      ADD_FAILURE() << "normalised threw: " << error.what();
      continue;
    }
    EXPECT_NEAR(p.e0, 0.6, 1e-15);
    EXPECT_LT(test::max_abs_diff(p.e, Vec3(0.0, 0.8, 0.0)), 1e-15);
  }
}

// (6.38): ω = 2 (e0 ė − ė0 e + e × ė) equals −½ ε[Q̇ Qᵀ] by finite differences.
TEST(EulerParameters, AngularVelocityMatchesFiniteDifferences638) {
  // Paths p(t) = q(t)/|q(t)|, q = p0 + t v; fourth-order differences, error O(h⁴) ~ 1e-12.
  test::Random rng(109);
  for (int n = 0; n < 300; ++n) {
    const Vec4 p0 = as_vec4(random_unit(rng));
    const Vec4 v(rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5),
                 rng.uniform(-0.5, 0.5));
    const auto path = [&](double t) -> Vec4 { return (p0 + t * v).normalized(); };
    const auto Q_of = [&](double t) -> Tensor {
      const Vec4 p = path(t);
      return component_form(p(0), p.tail<3>());
    };
    const double t = rng.uniform(-0.3, 0.3);
    const Vec4 q = p0 + t * v;
    const Vec4 p = q.normalized();
    const Vec4 p_rate = (v - p.dot(v) * p) / q.norm();  // d/dt (q/|q|)
    const Tensor Q = Q_of(t);
    const Vec3 expected = axial_of(test::derivative(Q_of, t) * Q.transpose());
    const Vec3 omega = angular_velocity(from_vec4(p), from_vec4(p_rate));
    EXPECT_LT(test::max_abs_diff(omega, expected), 1e-10) << "n = " << n;
  }
}

// (6.38) inverted: ṗ(p, ω) gives ω back, keeps d/dt (e0² + e·e) = 0.
TEST(EulerParameters, RatesInvertAngularVelocity638) {
  test::Random rng(110);
  for (int n = 0; n < 3000; ++n) {
    const EulerParameters p = random_unit(rng);
    const Vec3 omega = rng.vector(5.0);
    const EulerParameters rate = euler_parameter_rates(p, omega);
    EXPECT_LT(test::max_abs_diff(angular_velocity(p, rate), omega), 1e-14);
    EXPECT_NEAR(p.e0 * rate.e0 + p.e.dot(rate.e), 0.0, 1e-15);
    // A tangent ṗ (⊥ p in R⁴) is recovered from its ω.
    Vec4 tangent(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    tangent -= tangent.dot(as_vec4(p)) * as_vec4(p);
    const EulerParameters back = euler_parameter_rates(p, angular_velocity(p, from_vec4(tangent)));
    EXPECT_LT(test::max_abs_diff(as_vec4(back), tangent), 1e-14);
  }
}

// Classical fourth-order Runge–Kutta step for y' = f(t, y).
template <class Y, class F>
Y rk4_step(const F& f, double t, const Y& y, double h) {
  const Y k1 = f(t, y);
  const Y k2 = f(t + h / 2, Y(y + h / 2 * k1));
  const Y k3 = f(t + h / 2, Y(y + h / 2 * k2));
  const Y k4 = f(t + h, Y(y + h * k3));
  return y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

// (6.38) inverted and integrated (RK4) reproduces Q from Q̇ = Ω Q.
TEST(EulerParameters, IntegratedRatesReproduceRotation) {
  // RK4 global error O(h⁴) ~ 1e-12 at h = 1e-3; for constant ω the exact L(|ω| t, ω/|ω|) Q0.
  test::Random rng(111);
  for (int run = 0; run < 5; ++run) {
    const Vec3 w0 = rng.vector(2.0), w1 = rng.vector(2.0), w2 = rng.vector(1.0);
    const auto omega = [&](double t) -> Vec3 {
      return Vec3(w0(0) + w1(0) * std::sin(1.3 * t), w0(1) + w1(1) * std::cos(0.7 * t),
                  w0(2) + w1(2) * t) +
             w2 * t * t;
    };
    const EulerParameters start = random_unit(rng);
    Vec4 p = as_vec4(start);
    Tensor Q = component_form(start.e0, start.e);
    const auto p_rhs = [&](double t, const Vec4& y) -> Vec4 {
      return as_vec4(euler_parameter_rates(from_vec4(y), omega(t)));
    };
    const auto Q_rhs = [&](double t, const Tensor& Y) -> Tensor {
      return cross_matrix(omega(t)) * Y;
    };
    const double h = 1e-3;
    const int steps = 2000;
    for (int k = 0; k < steps; ++k) {
      const double t = k * h;
      p = rk4_step(p_rhs, t, p, h);
      Q = rk4_step(Q_rhs, t, Q, h);
    }
    EXPECT_NEAR(p.norm(), 1.0, 1e-11);
    EXPECT_LT(test::max_abs_diff(component_form(p(0), p.tail<3>()), Q), 1e-10) << "run " << run;
  }
  // Constant ω: the exact solution is L(|ω| t, ω/|ω|) Q0.
  const Vec3 w = rng.vector(3.0);
  const EulerParameters start = random_unit(rng);
  Vec4 p = as_vec4(start);
  const auto p_rhs = [&](double, const Vec4& y) -> Vec4 {
    return as_vec4(euler_parameter_rates(from_vec4(y), w));
  };
  const double h = 1e-3;
  for (int k = 0; k < 2000; ++k) p = rk4_step(p_rhs, k * h, p, h);
  const Tensor exact = book_L(w.norm() * 2.0, w.normalized()) * component_form(start.e0, start.e);
  EXPECT_LT(test::max_abs_diff(component_form(p(0), p.tail<3>()), exact), 1e-10);
}

}  // namespace
}  // namespace unidyn
