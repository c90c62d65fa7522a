// Derivatives of a scalar function of a rotation, book §6.10, eqs. (6.39)–(6.42).
#include "unidyn/rotation/scalar_function.hpp"

#include <Eigen/Core>
#include <cmath>
#include <functional>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

using test::book_L;

using test::kPi;
using Vec4 = Eigen::Vector4d;

// (6.36) R̄(e0, e) = (e0² − e·e) I + 2 e⊗e − 2 e0 εe typed column by column, also for non-unit
// (e0, e) (then it is |p|² times a rotation).
Tensor book_R_bar(double e0, const Vec3& e) {
  Tensor R;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = Vec3::Unit(k);
    R.col(k) = (e0 * e0 - e.dot(e)) * a + 2.0 * e.dot(a) * e - 2.0 * e0 * a.cross(e);
  }
  return R;
}

// (6.36) R̃(λ) = ((1 − λ·λ) I + 2 λ⊗λ − 2 ελ) / (1 + λ·λ).
Tensor book_R_tilde(const Vec3& l) {
  return book_R_bar(1.0, l) / (1.0 + l.dot(l));
}

// (6.20) Q = L(γ¹, E_I) L(γ², E_J) L(γ³, E_K).
Tensor euler_rotation(const EulerSet& set, const Vec3& g) {
  return book_L(g(0), Vec3::Unit(set.first - 1)) * book_L(g(1), Vec3::Unit(set.second - 1)) *
         book_L(g(2), Vec3::Unit(set.third - 1));
}

// The axial vector of the skew part of W: W a = w × a for skew W, so w = (W32, W13, W21).
Vec3 axial_of(const Tensor& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// (εc) as a matrix, column k = E_k × c.
Tensor eps_times(const Vec3& c) {
  Tensor A;
  for (int k = 0; k < 3; ++k) A.col(k) = Vec3::Unit(k).cross(c);
  return A;
}

// Test function of §4 item 20 with a non-linear term: U(Q) = a·(Q b) + (c·(Q d))², whose
// ∂U/∂Q = Σ ∂U/∂Q_ik E_i⊗E_k = a⊗b + 2 (c·Q d) c⊗d.
struct TestFunction {
  Vec3 a, b, c, d;
  double value(const Tensor& Q) const {
    const double s = c.dot(Q * d);
    return a.dot(Q * b) + s * s;
  }
  Tensor partials(const Tensor& Q) const {
    return a * b.transpose() + 2.0 * c.dot(Q * d) * c * d.transpose();
  }
};

TestFunction random_function(test::Random& rng) {
  return {rng.vector(), rng.vector(), rng.vector(), rng.vector()};
}

// ∂f/∂x_i at x by a fourth-order central difference: truncation O(h⁴) ~ 6e-14 times the fifth
// derivative, round-off ~1e-16 |f|/h ~ 1e-12 at h = 5e-4.
template <class V, class F>
double partial(const F& f, const V& x, int i) {
  return test::derivative(
      [&](double s) {
        V y = x;
        y(i) += s;
        return f(y);
      },
      0.0, 5e-4);
}

// (6.39): for U = a·(Q b), u_Q = −ε[U_Q] = (Q b) × a.
TEST(ScalarFunction, GradientOfLinearFunction639) {
  // U̇ = a·(ω × Q b) = ((Q b) × a)·ω.
  test::Random rng(301);
  for (int n = 0; n < 3000; ++n) {
    const Tensor Q = rng.rotation();
    const Vec3 a = rng.vector(2.0), b = rng.vector(2.0);
    const Vec3 u = rotation_gradient(Q, a * b.transpose());
    EXPECT_LT(test::max_abs_diff(u, Vec3((Q * b).cross(a))), 1e-14);
  }
}

// (6.39): symmetric parts S Q of ∂U/∂Q drop out; ∂U/∂Q = −½ (εu) Q gives u.
TEST(ScalarFunction, GradientIgnoresSymmetricPart639) {
  // The printed inverse −(εu_Q) Q would double u (see the notes on §6.10), so the consistent form
  // is used.
  test::Random rng(302);
  for (int n = 0; n < 3000; ++n) {
    const Tensor Q = rng.rotation();
    const TestFunction U = random_function(rng);
    Tensor M;
    M << rng.vector(), rng.vector(), rng.vector();
    const Tensor S = M + M.transpose();
    const Vec3 u = rotation_gradient(Q, U.partials(Q));
    EXPECT_LT(test::max_abs_diff(rotation_gradient(Q, Tensor(U.partials(Q) + S * Q)), u), 1e-14);
    const Vec3 w = rng.vector(3.0);
    EXPECT_LT(test::max_abs_diff(rotation_gradient(Q, Tensor(-0.5 * eps_times(w) * Q)), w), 1e-14);
  }
}

// (6.40): U̇ = u_Q · ω along smooth paths, both sides by finite differences.
TEST(ScalarFunction, RateEqualsGradientDotAngularVelocity640) {
  // Q(t) = R0 L(φ(t), r(t)); fourth-order differences, error O(h⁴) ~ 1e-12.
  test::Random rng(303);
  for (int n = 0; n < 500; ++n) {
    const TestFunction U = random_function(rng);
    const Tensor R0 = rng.rotation();
    const double phi0 = rng.uniform(-kPi, kPi), phi1 = rng.uniform(-2.0, 2.0);
    const Vec3 r0 = rng.unit_vector(), r1 = rng.vector(0.5);
    const auto Q_of = [&](double t) -> Tensor {
      return R0 * book_L(phi0 + phi1 * t, (r0 + t * r1).normalized());
    };
    const double t = rng.uniform(-0.2, 0.2);
    const Tensor Q = Q_of(t);
    const Vec3 omega = axial_of(test::derivative(Q_of, t) * Q.transpose());
    const double rate = test::derivative([&](double s) { return U.value(Q_of(s)); }, t);
    const Vec3 u = rotation_gradient(Q, U.partials(Q));
    EXPECT_NEAR(u.dot(omega), rate, 1e-10) << "n = " << n;
  }
}

// (6.41): Σ ∂Û/∂γ^i g^i, partials by finite differences of U(Q̂(γ)), equals (6.39).
TEST(ScalarFunction, EulerAngleForm641) {
  // Q̂ is built here from (6.20); the dual basis scales the ~1e-12 difference error by ≤ 1/|sin
  // 0.3|.
  test::Random rng(304);
  for (const char* name : {"3-1-3", "3-2-1", "1-2-3", "3-2-3", "1-3-1", "2-3-1"}) {
    const EulerSet set = *EulerSet::parse(name);
    SCOPED_TRACE(name);
    for (int n = 0; n < 200; ++n) {
      const TestFunction U = random_function(rng);
      const double middle = set.symmetric() ? rng.uniform(0.3, kPi - 0.3)
                                            : rng.uniform(-kPi / 2 + 0.3, kPi / 2 - 0.3);
      const Vec3 gamma(rng.uniform(-kPi, kPi), middle, rng.uniform(-kPi, kPi));
      const auto U_hat = [&](const Vec3& g) { return U.value(euler_rotation(set, g)); };
      Vec3 dU;
      for (int i = 0; i < 3; ++i) dU(i) = partial(U_hat, gamma, i);
      const Tensor Q = euler_rotation(set, gamma);
      const Vec3 expected = rotation_gradient(Q, U.partials(Q));
      EXPECT_LT(test::max_abs_diff(rotation_gradient(set, gamma, dU), expected), 1e-10)
          << "n = " << n;
    }
  }
}

// (6.42)₂: ∂Ũ/∂φ r + ½ (cot(φ/2)(I − r⊗r) − εr) ∂Ũ/∂r equals (6.39).
TEST(ScalarFunction, AxisAngleForm642) {
  // Partials of U(L(φ, r)) with (6.8) written for any r carry a normal component along r; it drops
  // out, and tangential partials (r normalised first) give the same u_Q.
  test::Random rng(305);
  int with_normal_component = 0;
  for (int n = 0; n < 1000; ++n) {
    const TestFunction U = random_function(rng);
    const Vec3 r = rng.unit_vector();
    const double phi = (n % 2 == 0 ? 1.0 : -1.0) * rng.uniform(0.3, 2.0 * kPi - 0.3);
    const Tensor Q = book_L(phi, r);
    const Vec3 expected = rotation_gradient(Q, U.partials(Q));

    const auto U_tilde = [&](const Vec4& x) { return U.value(book_L(x(0), x.tail<3>())); };
    const auto U_tangential = [&](const Vec4& x) {
      return U.value(book_L(x(0), x.tail<3>().normalized()));
    };
    const Vec4 x(phi, r(0), r(1), r(2));
    Vec4 d, dt;
    for (int i = 0; i < 4; ++i) {
      d(i) = partial(U_tilde, x, i);
      dt(i) = partial(U_tangential, x, i);
    }
    // The normal component of the unconstrained partials: ∂L/∂r along r is 2(1 − cos φ) r⊗r − sin φ
    // εr.
    const Tensor dL =
        2.0 * (1.0 - std::cos(phi)) * r * r.transpose() - std::sin(phi) * eps_times(r);
    const double normal = U.partials(Q).cwiseProduct(dL).sum();
    EXPECT_NEAR(d.tail<3>().dot(r), normal, 1e-10);
    EXPECT_NEAR(dt.tail<3>().dot(r), 0.0, 1e-10);
    if (std::abs(normal) > 0.1) ++with_normal_component;

    EXPECT_LT(test::max_abs_diff(rotation_gradient(AxisAngle{r, phi}, d(0), d.tail<3>()), expected),
              1e-10)
        << "n = " << n;
    EXPECT_LT(
        test::max_abs_diff(rotation_gradient(AxisAngle{r, phi}, dt(0), dt.tail<3>()), expected),
        1e-10)
        << "n = " << n;
  }
  // The check above is not vacuous: most samples had a sizeable normal component.
  EXPECT_GT(with_normal_component, 500);
}

// (6.42)₃: ½ ((e0 I − εe) ∂Ū/∂e − ∂Ū/∂e0 e) equals (6.39), for ±p.
TEST(ScalarFunction, EulerParameterForm642) {
  // Partials of U(R̄(e0, e)) with (6.36) written for any p carry a normal component (R̄ is quadratic:
  // p·∇Ū = 2 Q : ∂U/∂Q); it drops out, and tangential partials give the same u_Q.
  test::Random rng(306);
  for (int n = 0; n < 1000; ++n) {
    const TestFunction U = random_function(rng);
    const double theta = rng.uniform(0.0, 2.0 * kPi);
    const Vec3 r = rng.unit_vector();
    const Vec4 x(std::cos(theta / 2), std::sin(theta / 2) * r(0), std::sin(theta / 2) * r(1),
                 std::sin(theta / 2) * r(2));
    const Tensor Q = book_R_bar(x(0), x.tail<3>());
    const Vec3 expected = rotation_gradient(Q, U.partials(Q));

    const auto U_bar = [&](const Vec4& y) { return U.value(book_R_bar(y(0), y.tail<3>())); };
    const auto U_tangential = [&](const Vec4& y) {
      const Vec4 z = y.normalized();
      return U.value(book_R_bar(z(0), z.tail<3>()));
    };
    for (const double sign : {1.0, -1.0}) {
      const Vec4 y = sign * x;
      Vec4 d, dt;
      for (int i = 0; i < 4; ++i) {
        d(i) = partial(U_bar, y, i);
        dt(i) = partial(U_tangential, y, i);
      }
      EXPECT_NEAR(d.dot(y), 2.0 * Q.cwiseProduct(U.partials(Q)).sum(), 1e-10);
      EXPECT_NEAR(dt.dot(y), 0.0, 1e-10);
      const EulerParameters ep{y(0), y.tail<3>()};
      EXPECT_LT(test::max_abs_diff(rotation_gradient(ep, d(0), d.tail<3>()), expected), 1e-10)
          << "n = " << n << ", sign " << sign;
      EXPECT_LT(test::max_abs_diff(rotation_gradient(ep, dt(0), dt.tail<3>()), expected), 1e-10)
          << "n = " << n << ", sign " << sign;
    }
  }
}

// (6.42)₄: ½ (I + λ⊗λ − ελ) ∂Ǔ/∂λ, partials by finite differences of U(R̃(λ)), equals (6.39).
TEST(ScalarFunction, RodriguesForm642) {
  test::Random rng(307);
  for (int n = 0; n < 1000; ++n) {
    const TestFunction U = random_function(rng);
    const double phi = rng.uniform(-kPi + 0.3, kPi - 0.3);
    const Vec3 l = std::tan(phi / 2) * rng.unit_vector();
    const Tensor Q = book_R_tilde(l);
    const Vec3 expected = rotation_gradient(Q, U.partials(Q));
    const auto U_check = [&](const Vec3& y) { return U.value(book_R_tilde(y)); };
    Vec3 d;
    for (int i = 0; i < 3; ++i) d(i) = partial(U_check, l, i);
    EXPECT_LT(test::max_abs_diff(rotation_gradient(RodriguesVector{l}, d), expected), 1e-10)
        << "n = " << n;
  }
}

// (6.42) inverted, consistent form: ∂Ũ/∂φ = u·r, ∂Ū/∂e0 = −2 u·e (printed +), etc.
TEST(ScalarFunction, InverseRelations642) {
  // Tangential partials: ∂Ũ/∂r = (sin φ (I − r⊗r) + 2 sin²(φ/2) εr) u and ∂Ū/∂e = 2 (e0 I + εe) u.
  test::Random rng(308);
  for (int n = 0; n < 500; ++n) {
    const TestFunction U = random_function(rng);
    const Vec3 r = rng.unit_vector();
    const double phi = rng.uniform(-kPi, kPi);
    const Tensor Q = book_L(phi, r);
    const Vec3 u = rotation_gradient(Q, U.partials(Q));

    const auto U_tilde = [&](const Vec4& x) {
      return U.value(book_L(x(0), x.tail<3>().normalized()));
    };
    const Vec4 x(phi, r(0), r(1), r(2));
    Vec4 d;
    for (int i = 0; i < 4; ++i) d(i) = partial(U_tilde, x, i);
    const Tensor P = Tensor::Identity() - r * r.transpose();
    const double s = std::sin(phi / 2);
    EXPECT_NEAR(d(0), u.dot(r), 1e-10);
    EXPECT_LT(test::max_abs_diff(Vec3(d.tail<3>()),
                                 Vec3((std::sin(phi) * P + 2.0 * s * s * eps_times(r)) * u)),
              1e-10);

    const double e0 = std::cos(phi / 2);
    const Vec3 e = s * r;
    const auto U_bar = [&](const Vec4& y) {
      const Vec4 z = y.normalized();
      return U.value(book_R_bar(z(0), z.tail<3>()));
    };
    const Vec4 y(e0, e(0), e(1), e(2));
    Vec4 de;
    for (int i = 0; i < 4; ++i) de(i) = partial(U_bar, y, i);
    EXPECT_NEAR(de(0), -2.0 * u.dot(e), 1e-10);
    EXPECT_LT(test::max_abs_diff(Vec3(de.tail<3>()),
                                 Vec3(2.0 * (e0 * Tensor::Identity() + eps_times(e)) * u)),
              1e-10);
  }
}

// (6.42)₂ needs cot(φ/2): no axis–angle gradient at φ = 0 (mod 2π).
TEST(ScalarFunction, AxisAngleGradientSingularAtZeroAngle) {
  const Vec3 r = Vec3(1.0, 2.0, 2.0) / 3.0;
  EXPECT_THROW(rotation_gradient(AxisAngle{r, 0.0}, 1.0, Vec3(0.1, 0.2, 0.3)),
               SingularConfiguration);
  EXPECT_THROW(rotation_gradient(AxisAngle{r, 2.0 * kPi}, 1.0, Vec3(0.1, 0.2, 0.3)),
               SingularConfiguration);
  EXPECT_NO_THROW(rotation_gradient(AxisAngle{r, 1e-3}, 1.0, Vec3(0.1, 0.2, 0.3)));
}

// (6.41) needs the dual Euler basis, which does not exist at gimbal lock (§6.8).
TEST(ScalarFunction, EulerAngleGradientSingularAtGimbalLock) {
  const Vec3 dU(0.3, -0.2, 0.5);
  const EulerSet s313{3, 1, 3}, s321{3, 2, 1}, s123{1, 2, 3};
  EXPECT_THROW(rotation_gradient(s313, Vec3(0.4, 0.0, -0.7), dU), SingularConfiguration);
  EXPECT_THROW(rotation_gradient(s313, Vec3(0.4, kPi, -0.7), dU), SingularConfiguration);
  EXPECT_THROW(rotation_gradient(s321, Vec3(0.4, kPi / 2, -0.7), dU), SingularConfiguration);
  EXPECT_THROW(rotation_gradient(s321, Vec3(0.4, -kPi / 2, -0.7), dU), SingularConfiguration);
  EXPECT_THROW(rotation_gradient(s123, Vec3(0.4, kPi / 2, -0.7), dU), SingularConfiguration);
  EXPECT_NO_THROW(rotation_gradient(s313, Vec3(0.4, 0.1, -0.7), dU));
}

}  // namespace
}  // namespace unidyn
