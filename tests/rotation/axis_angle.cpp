// Euler's representation L(φ, r) of a rotation (book §6.5), its extraction from a rotation tensor
// (§6.5.1) and its angular velocity (6.14).
#include "unidyn/rotation/axis_angle.hpp"

#include <Eigen/SVD>
#include <array>
#include <cmath>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

using test::derivative;
using test::kPi;
using test::max_abs_diff;

// ε_ijk for indices 0..2, written out independently of the library.
double levi_civita(int i, int j, int k) {
  if ((i == 0 && j == 1 && k == 2) || (i == 1 && j == 2 && k == 0) || (i == 2 && j == 0 && k == 1))
    return 1.0;
  if ((i == 1 && j == 0 && k == 2) || (i == 0 && j == 2 && k == 1) || (i == 2 && j == 1 && k == 0))
    return -1.0;
  return 0.0;
}

// (6.10) R_ik = cos φ (δ_ik − r_i r_k) + r_i r_k − Σ_j sin φ ε_jik r_j, for a unit r.
Tensor components_610(double phi, const Vec3& r) {
  Tensor R;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      double value = std::cos(phi) * ((i == k ? 1.0 : 0.0) - r[i] * r[k]) + r[i] * r[k];
      for (int j = 0; j < 3; ++j) value -= std::sin(phi) * levi_civita(j, i, k) * r[j];
      R(i, k) = value;
    }
  }
  return R;
}

// The axial vector w of a skew W (W a = w × a), written out: w = (W32, W13, W21).
Vec3 axial_of(const Tensor& W) {
  return Vec3(0.5 * (W(2, 1) - W(1, 2)), 0.5 * (W(0, 2) - W(2, 0)), 0.5 * (W(1, 0) - W(0, 1)));
}

// (6.11)–(6.12), as printed in §6.5.1 (valid for 0 < θ < π).
AxisAngle book_axis_angle(const Tensor& R) {
  const double angle = std::acos(0.5 * (R(0, 0) + R(1, 1) + R(2, 2) - 1.0));
  const double factor = -1.0 / (2.0 * std::sin(angle));
  return {factor * Vec3(R(1, 2) - R(2, 1), R(2, 0) - R(0, 2), R(0, 1) - R(1, 0)), angle};
}

Tensor book_matrix(std::array<double, 9> rows) {
  Tensor M;
  M << rows[0], rows[1], rows[2], rows[3], rows[4], rows[5], rows[6], rows[7], rows[8];
  return M;
}

// The W3 matrix of §6.5.1, as printed (six significant digits).
Tensor w3_matrix() {
  return book_matrix({0.835959, -0.283542, -0.469869, 0.271321, 0.957764, -0.0952472, 0.47703,
                      -0.0478627, 0.877583});
}

// max(|QᵀQ − I|, |det Q − 1|), computed here rather than by the library.
double orthogonality_defect(const Tensor& Q) {
  return std::max((Q.transpose() * Q - Tensor::Identity()).cwiseAbs().maxCoeff(),
                  std::abs(Q.determinant() - 1.0));
}

// (6.8) L(φ, r) equals the component form (6.10) written out index by index.
TEST(AxisAngle, RotationTensorMatchesComponentForm610) {
  test::Random random;
  for (int n = 0; n < 5000; ++n) {
    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(-2.0 * kPi, 2.0 * kPi);
    const Tensor expected = components_610(phi, r);
    ASSERT_LE(max_abs_diff(rotation_tensor(AxisAngle{r, phi}), expected), 1e-15 * 8) << n;
    // The axis is normalised (header): a scaled axis gives the same rotation.
    const double scale = random.uniform(0.01, 100.0);
    ASSERT_LE(max_abs_diff(rotation_tensor(AxisAngle{scale * r, phi}), expected), 1e-15 * 8) << n;
    ASSERT_LE(orthogonality_defect(rotation_tensor(AxisAngle{r, phi})), 1e-14) << n;
  }
}

// §6.5 L(π/2, E3) has the component matrix [[0, −1, 0], [1, 0, 0], [0, 0, 1]] (counter-clockwise).
TEST(AxisAngle, QuarterTurnAboutE3) {
  const Tensor expected = book_matrix({0, -1, 0, 1, 0, 0, 0, 0, 1});
  EXPECT_LE(max_abs_diff(rotation_tensor(AxisAngle{basis_vector(3), kPi / 2}), expected), 1e-16);
  EXPECT_LE(max_abs_diff(rotation_tensor(AxisAngle{basis_vector(3), kPi / 2}) * basis_vector(1),
                         basis_vector(2)),
            1e-16);
}

// §6.5 R r = r: the axis is fixed by L(φ, r).
TEST(AxisAngle, AxisIsFixed) {
  test::Random random;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(-4.0, 4.0);
    ASSERT_LE(max_abs_diff(rotation_tensor(AxisAngle{r, phi}) * r, r), 1e-15 * 4) << n;
  }
}

// §6.5 L(φ, r) = L(−φ, −r), Rᵀ = L(−φ, r) = L(φ, −r), L(0, r) = I.
TEST(AxisAngle, NonUniquenessAndInverse) {
  test::Random random;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(-4.0, 4.0);
    const Tensor R = rotation_tensor(AxisAngle{r, phi});
    ASSERT_LE(max_abs_diff(R, rotation_tensor(AxisAngle{-r, -phi})), 1e-15 * 4) << n;
    ASSERT_LE(max_abs_diff(R.transpose(), rotation_tensor(AxisAngle{r, -phi})), 1e-15 * 4) << n;
    ASSERT_LE(max_abs_diff(R.transpose(), rotation_tensor(AxisAngle{-r, phi})), 1e-15 * 4) << n;
    ASSERT_LE(max_abs_diff(R * R.transpose(), Tensor::Identity()), 1e-15 * 4) << n;
    ASSERT_EQ(max_abs_diff(rotation_tensor(AxisAngle{r, 0.0}), Tensor::Identity()), 0.0) << n;
  }
}

// (6.9) Euler's formula: L(φ, r) a = cos φ a⊥ + sin φ r × a⊥ + a∥ equals Q a.
TEST(AxisAngle, EulersFormulaEqualsTensorTimesVector) {
  test::Random random;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(-4.0, 4.0);
    const Vec3 a = random.vector(3.0);
    const Vec3 expected = components_610(phi, r) * a;
    ASSERT_LE(max_abs_diff(rotate(AxisAngle{r, phi}, a), expected), 1e-14) << n;
    // The intermediate line of §6.5: cos φ (I − r⊗r) a + sin φ r × a + (r · a) r.
    const Vec3 intermediate =
        std::cos(phi) * (a - r.dot(a) * r) + std::sin(phi) * r.cross(a) + r.dot(a) * r;
    ASSERT_LE(max_abs_diff(rotate(AxisAngle{r, phi}, a), intermediate), 1e-14) << n;
    ASSERT_LE(max_abs_diff(rotate(AxisAngle{r, phi}, a), rotation_tensor(AxisAngle{r, phi}) * a),
              1e-14)
        << n;
    // A scaled axis is normalised here too.
    ASSERT_LE(max_abs_diff(rotate(AxisAngle{7.0 * r, phi}, a), expected), 1e-14) << n;
  }
}

// (6.5) L(φ, E_i): the rotations about the basis vectors, typed as in (6.25).
TEST(AxisAngle, ElementaryRotations) {
  for (const double phi : {-2.5, -0.3, 0.0, 0.7, 1.9, 3.1}) {
    const double c = std::cos(phi), s = std::sin(phi);
    EXPECT_LE(max_abs_diff(elementary_rotation(1, phi), book_matrix({1, 0, 0, 0, c, -s, 0, s, c})),
              1e-16)
        << phi;
    EXPECT_LE(max_abs_diff(elementary_rotation(2, phi), book_matrix({c, 0, s, 0, 1, 0, -s, 0, c})),
              1e-16)
        << phi;
    EXPECT_LE(max_abs_diff(elementary_rotation(3, phi), book_matrix({c, -s, 0, s, c, 0, 0, 0, 1})),
              1e-16)
        << phi;
  }
}

// Exercise 6.7: L(π/2, E3) L(π/2, E1) = L(2π/3, (E1 + E2 + E3)/√3), mapping E1→E2→E3→E1.
TEST(AxisAngle, Exercise6_7) {
  const Tensor product = rotation_tensor(AxisAngle{basis_vector(3), kPi / 2}) *
                         rotation_tensor(AxisAngle{basis_vector(1), kPi / 2});
  const Vec3 n = Vec3(1, 1, 1) / std::sqrt(3.0);
  const Tensor cyclic = book_matrix({0, 0, 1, 1, 0, 0, 0, 1, 0});
  EXPECT_LE(max_abs_diff(product, cyclic), 1e-15);
  EXPECT_LE(max_abs_diff(rotation_tensor(AxisAngle{n, 2 * kPi / 3}), cyclic), 1e-15);
  const AxisAngle found = axis_angle(product);
  EXPECT_NEAR(found.angle, 2 * kPi / 3, 1e-15);
  EXPECT_LE(max_abs_diff(found.axis, n), 1e-15);
}

// Exercise 6.5 (6.50): the navigation frame at latitude λ and longitude θ, north e_x =
// (−cθ sλ, −sθ sλ, cλ), east e_y = (−sθ, cθ, 0), down e_z = (−cθ cλ, −sθ cλ, −sλ): R = e_x⊗E1 +
// e_y⊗E2 + e_z⊗E3 = R2 R1 with R1 = L(θ, E3), R2 = L(−π/2 − λ, e_y); [R_ik] is (6.50)ᵀ.
TEST(AxisAngle, NavigationFrameOfExercise65) {
  test::Random random;
  for (int n = 0; n < 20; ++n) {
    const double lambda = random.uniform(-1.5, 1.5), theta = random.uniform(-3.0, 3.0);
    const double cl = std::cos(lambda), sl = std::sin(lambda), ct = std::cos(theta),
                 st = std::sin(theta);
    const Vec3 e_x(-ct * sl, -st * sl, cl), e_y(-st, ct, 0), e_z(-ct * cl, -st * cl, -sl);
    Tensor R;
    R.col(0) = e_x;  // R = Σ e_k ⊗ E_k: column k is e_k
    R.col(1) = e_y;
    R.col(2) = e_z;
    const Tensor R1 = rotation_tensor(AxisAngle{basis_vector(3), theta});
    const Tensor R2 = rotation_tensor(AxisAngle{e_y, -kPi / 2 - lambda});
    EXPECT_LE(max_abs_diff(R2 * R1, R), 1e-14) << n;
    EXPECT_TRUE(is_rotation(R));
  }
}

// Exercise 6.8: L(π/2, E2) L(π/2, E3) L(−π/2, E1) = L(π/2, E3).
TEST(AxisAngle, Exercise6_8) {
  const Tensor product = rotation_tensor(AxisAngle{basis_vector(2), kPi / 2}) *
                         rotation_tensor(AxisAngle{basis_vector(3), kPi / 2}) *
                         rotation_tensor(AxisAngle{basis_vector(1), -kPi / 2});
  EXPECT_LE(max_abs_diff(product, book_matrix({0, -1, 0, 1, 0, 0, 0, 0, 1})), 1e-15);
  EXPECT_LE(max_abs_diff(product, rotation_tensor(AxisAngle{basis_vector(3), kPi / 2})), 1e-15);
}

// Exercise 6.10 (6.51) Rodrigues–Hamilton: L(π, p3) L(π, p2) L(π, p1) = I for right-handed {p_i}.
TEST(AxisAngle, Exercise6_10RodriguesHamilton) {
  test::Random random;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 p1 = random.unit_vector();
    const Vec3 p2 = random.unit_vector();
    if (p2.cross(p1).norm() < 0.1) continue;  // keep the Gram–Schmidt step well conditioned
    const Vec3 p2_orth = (p2 - p2.dot(p1) * p1).normalized();
    const Vec3 p3 = p1.cross(p2_orth);
    const Tensor product = rotation_tensor(AxisAngle{p3, kPi}) *
                           rotation_tensor(AxisAngle{p2_orth, kPi}) *
                           rotation_tensor(AxisAngle{p1, kPi});
    ASSERT_LE(max_abs_diff(product, Tensor::Identity()), 1e-14) << n;
    // Not a triviality: each factor alone is far from I.
    ASSERT_GT(max_abs_diff(rotation_tensor(AxisAngle{p1, kPi}), Tensor::Identity()), 1.0) << n;
  }
}

// §6.5.1 W3, (6.11)–(6.12): 33.3161° about (0.043135, −0.861981, 0.505103) to the printed digits.
TEST(AxisAngle, BookExampleW3) {
  const Tensor R = w3_matrix();
  const AxisAngle found = axis_angle(R);
  // Printed to 6 significant digits: half a unit in the last place.
  EXPECT_NEAR(found.angle * 180.0 / kPi, 33.3161, 0.5e-4);
  EXPECT_NEAR(found.axis.x(), 0.043135, 0.5e-6);
  EXPECT_NEAR(found.axis.y(), -0.861981, 0.5e-6);
  EXPECT_NEAR(found.axis.z(), 0.505103, 0.5e-6);
  EXPECT_NEAR(found.axis.norm(), 1.0, 1e-15);

  // The book's own formulas, written here, agree with the implementation up to the ~1e-6 defect of
  // the six-digit matrix (they treat its non-orthogonality differently).
  const AxisAngle book = book_axis_angle(R);
  EXPECT_NEAR(book.angle * 180.0 / kPi, 33.3161, 0.5e-4);
  EXPECT_NEAR(book.axis.x(), 0.043135, 0.5e-6);
  EXPECT_NEAR(book.axis.y(), -0.861981, 0.5e-6);
  EXPECT_NEAR(book.axis.z(), 0.505103, 0.5e-6);
  EXPECT_NEAR(found.angle, book.angle, 2e-6);
  EXPECT_LE(max_abs_diff(found.axis, book.axis.normalized()), 2e-6);
}

// (6.11)–(6.12) written out agree with axis_angle() on exact rotations with 0 < φ < π.
TEST(AxisAngle, AgreesWithBookFormulas611And612) {
  test::Random random;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 r = random.unit_vector();
    // sin φ ≥ sin 0.05 keeps (6.12) well conditioned (its error ≈ ε / sin φ).
    const double phi = random.uniform(0.05, kPi - 0.05);
    const Tensor R = components_610(phi, r);
    const AxisAngle book = book_axis_angle(R);
    const AxisAngle found = axis_angle(R);
    // (6.11)–(6.12) lose accuracy like ε / sin²φ (acos near ±1, then the division by sin φ).
    const double book_tolerance = 1e-15 + 1e-15 / std::pow(std::sin(phi), 2);
    ASSERT_NEAR(book.angle, phi, book_tolerance) << n;
    ASSERT_LE(max_abs_diff(book.axis, r), book_tolerance) << n;
    ASSERT_NEAR(found.angle, book.angle, 2 * book_tolerance) << n;
    ASSERT_LE(max_abs_diff(found.axis, book.axis), 2 * book_tolerance) << n;
    // The implementation itself does not lose that accuracy.
    ASSERT_NEAR(found.angle, phi, 1e-14) << n;
    ASSERT_LE(max_abs_diff(found.axis, r), 1e-14) << n;
  }
}

// §6.5.1 round trip on thousands of uniformly random rotations: φ ∈ [0, π], |r| = 1, L(φ, r) = Q.
TEST(AxisAngle, RoundTripRandomRotations) {
  test::Random random;
  for (int n = 0; n < 5000; ++n) {
    const Tensor Q = random.rotation();
    const AxisAngle found = axis_angle(Q);
    ASSERT_GE(found.angle, 0.0) << n;
    ASSERT_LE(found.angle, kPi) << n;
    ASSERT_NEAR(found.axis.norm(), 1.0, 1e-15) << n;
    ASSERT_LE(max_abs_diff(components_610(found.angle, found.axis), Q), 1e-12) << n;
    ASSERT_LE(max_abs_diff(rotation_tensor(found), Q), 1e-12) << n;
    ASSERT_LE(max_abs_diff(Q * found.axis, found.axis), 1e-14) << n;
  }
}

// §6.5.1 at the angles where (6.11)–(6.12) fail or lose accuracy: 0, tiny, near π and π exactly.
TEST(AxisAngle, RoundTripAtSpecialAngles) {
  test::Random random;
  std::vector<Vec3> axes = {basis_vector(1),
                            basis_vector(2),
                            basis_vector(3),
                            -basis_vector(2),
                            Vec3(1, 1, 1).normalized(),
                            Vec3(1, -2, 0).normalized()};
  for (int n = 0; n < 20; ++n) axes.push_back(random.unit_vector());
  const std::array<double, 7> angles = {0.0, 1e-12, 1e-8, 1e-4, kPi - 1e-4, kPi - 1e-8, kPi};
  for (const Vec3& r : axes) {
    for (const double phi : angles) {
      SCOPED_TRACE(testing::Message() << "phi = " << phi << ", r = " << r.transpose());
      const Tensor Q = components_610(phi, r);
      const AxisAngle found = axis_angle(Q);
      EXPECT_GE(found.angle, 0.0);
      EXPECT_LE(found.angle, kPi);
      EXPECT_NEAR(found.axis.norm(), 1.0, 1e-15);
      EXPECT_LE(max_abs_diff(rotation_tensor(found), Q), 1e-12);
      EXPECT_LE(max_abs_diff(components_610(found.angle, found.axis), Q), 1e-12);
      if (phi == 0.0) {
        EXPECT_EQ(found.angle, 0.0);
      } else if (phi < 1e-3) {
        // Small angles keep their relative accuracy (no acos of a number near 1).
        EXPECT_NEAR(found.angle, phi, 1e-12 * phi);
        EXPECT_LE(max_abs_diff(found.axis, r), 1e-12);
      } else if (phi < kPi) {
        EXPECT_NEAR(found.angle, phi, 1e-14);
        EXPECT_LE(max_abs_diff(found.axis, r), 1e-12);
      } else {
        // At φ = π the axis sign is not determined: L(π, r) = L(π, −r).
        EXPECT_NEAR(found.angle, kPi, 1e-14);
        EXPECT_LE(std::min(max_abs_diff(found.axis, r), max_abs_diff(found.axis, -r)), 1e-12);
      }
    }
  }
}

// §6.5.1 cross-check in the text: the eigenvector of R with eigenvalue 1 is parallel to r.
TEST(AxisAngle, AxisIsTheEigenvectorOfEigenvalueOne) {
  test::Random random;
  for (int n = 0; n < 1000; ++n) {
    const Tensor Q = random.rotation();
    const AxisAngle found = axis_angle(Q);
    if (found.angle < 0.05) continue;  // eigenvalue 1 is then nearly triple: poorly separated
    // The null vector of Q − I: right singular vector of the smallest singular value.
    const Eigen::JacobiSVD<Tensor> svd(Q - Tensor::Identity(), Eigen::ComputeFullV);
    const Vec3 u = svd.matrixV().col(2);
    ASSERT_LE(u.cross(found.axis).norm(), 1e-12 / std::sin(0.5 * found.angle)) << n;
  }
}

// A smooth path φ(t), r(t) = c(t)/|c(t)| for the finite-difference checks of (6.14).
struct AxisAnglePath {
  double a0, a1, a2;
  Vec3 c0, c1, c2;

  double angle(double t) const { return a0 + a1 * std::sin(a2 * t); }
  double angle_rate(double t) const { return a1 * a2 * std::cos(a2 * t); }
  Vec3 c(double t) const {
    return c0 + Vec3(std::sin(c1.x() * t), std::cos(c1.y() * t), std::sin(c1.z() * t + 0.3))
                    .cwiseProduct(c2);
  }
  Vec3 c_rate(double t) const {
    return Vec3(c1.x() * std::cos(c1.x() * t), -c1.y() * std::sin(c1.y() * t),
                c1.z() * std::cos(c1.z() * t + 0.3))
        .cwiseProduct(c2);
  }
  Vec3 axis(double t) const { return c(t).normalized(); }
  // ṙ = (I − r⊗r) ċ / |c|.
  Vec3 axis_rate(double t) const {
    const Vec3 r = axis(t);
    const Vec3 cd = c_rate(t);
    return (cd - r.dot(cd) * r) / c(t).norm();
  }
  Tensor rotation(double t) const { return components_610(angle(t), axis(t)); }
};

AxisAnglePath random_path(test::Random& random) {
  return {random.uniform(0.3, 2.8),
          random.uniform(0.2, 0.8),
          random.uniform(0.5, 1.5),
          Vec3(1.5, -1.0, 0.8) + random.vector(0.3),
          Vec3(random.uniform(0.5, 1.5), random.uniform(0.5, 1.5), random.uniform(0.5, 1.5)),
          random.vector(0.6)};
}

// (6.14) ω = φ̇ r + sin φ ṙ + (1 − cos φ) r × ṙ equals −½ ε[Q̇ Qᵀ] with Q̇ from finite differences.
TEST(AxisAngle, AngularVelocity614MatchesFiniteDifferences) {
  test::Random random;
  for (int n = 0; n < 50; ++n) {
    const AxisAnglePath path = random_path(random);
    for (const double t : {-1.0, 0.0, 0.4, 1.3}) {
      const Tensor Q = path.rotation(t);
      const Tensor Q_rate = derivative([&](double s) { return path.rotation(s); }, t);
      const Vec3 omega_fd = axial_of(Q_rate * Q.transpose());
      const Vec3 omega = angular_velocity(AxisAngle{path.axis(t), path.angle(t)},
                                          path.angle_rate(t), path.axis_rate(t));
      // Fourth-order differences with h = 1e-3: truncation ~h⁴ |Q⁽⁵⁾| ≲ 1e-10, round-off ~ε/h.
      ASSERT_LE(max_abs_diff(omega, omega_fd), 1e-9) << n << " t = " << t;
      // Not trivially small: the axis really moves.
      ASSERT_GT(path.axis_rate(t).norm(), 1e-3) << n;
    }
  }
}

// Inverse of (6.14): φ̇ = ω · r, ṙ = ½ (cot(φ/2) ω⊥ − r × ω⊥), recovering the path's own rates.
TEST(AxisAngle, AxisAngleRatesInvert614) {
  test::Random random;
  for (int n = 0; n < 50; ++n) {
    const AxisAnglePath path = random_path(random);
    for (const double t : {-1.0, 0.0, 0.4, 1.3}) {
      const Tensor Q = path.rotation(t);
      const Tensor Q_rate = derivative([&](double s) { return path.rotation(s); }, t);
      const Vec3 omega_fd = axial_of(Q_rate * Q.transpose());
      const AxisAngleRate rates =
          axis_angle_rates(AxisAngle{path.axis(t), path.angle(t)}, omega_fd);
      ASSERT_NEAR(rates.angle_rate, path.angle_rate(t), 1e-9) << n << " t = " << t;
      // The amplification cot(φ/2)/2 ≤ 7 for φ ≥ 0.3 on these paths.
      ASSERT_LE(max_abs_diff(rates.axis_rate, path.axis_rate(t)), 1e-8) << n << " t = " << t;
    }
  }
  for (int n = 0; n < 3000; ++n) {
    const Vec3 r = random.unit_vector();
    const double phi = random.uniform(1e-3, 2 * kPi - 1e-3);
    const Vec3 omega = random.vector(2.0);
    const AxisAngleRate rates = axis_angle_rates(AxisAngle{r, phi}, omega);
    ASSERT_LE(std::abs(r.dot(rates.axis_rate)), 1e-14 * (1.0 + rates.axis_rate.norm())) << n;
    // ω rebuilt by (6.14) written out here; ṙ is up to cot(φ/2) ≈ 2000 times ω.
    const Vec3 rebuilt = rates.angle_rate * r + std::sin(phi) * rates.axis_rate +
                         (1.0 - std::cos(phi)) * r.cross(rates.axis_rate);
    ASSERT_LE(max_abs_diff(rebuilt, omega), 1e-13 * (1.0 + rates.axis_rate.norm())) << n;
  }
}

// (6.14) ṙ does not exist at φ = 0 (mod 2π): SingularConfiguration; a zero axis is NotARotation.
TEST(AxisAngle, SingularAndInvalidInput) {
  const Vec3 omega(0.1, -0.2, 0.3);
  EXPECT_THROW(axis_angle_rates(AxisAngle{basis_vector(1), 0.0}, omega), SingularConfiguration);
  EXPECT_THROW(axis_angle_rates(AxisAngle{Vec3(1, 2, 3), 2 * kPi}, omega), SingularConfiguration);
  EXPECT_NO_THROW(axis_angle_rates(AxisAngle{basis_vector(1), 1e-6}, omega));

  const Vec3 zero = Vec3::Zero();
  EXPECT_THROW(rotation_tensor(AxisAngle{zero, 0.5}), NotARotation);
  EXPECT_THROW(rotate(AxisAngle{zero, 0.5}, omega), NotARotation);
  EXPECT_THROW(angular_velocity(AxisAngle{zero, 0.5}, 1.0, omega), NotARotation);
  EXPECT_THROW(axis_angle_rates(AxisAngle{zero, 0.5}, omega), NotARotation);
  EXPECT_THROW(rotation_tensor(AxisAngle{Vec3(std::nan(""), 0, 1), 0.5}), NotARotation);
}

}  // namespace
}  // namespace unidyn
