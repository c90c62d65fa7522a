// Euler angles of all twelve sets (book §6.8, Exercises 6.2, 6.11, 6.12). Oracles: the book's
// printed matrices typed in here, elementary matrices written out here, finite differences,
// independent integration, and identities checked on seeded random inputs.
#include "unidyn/rotation/euler_angles.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "support/oracles.hpp"
#include "unidyn/rotation/angular_velocity.hpp"
#include "unidyn/rotation/axis_angle.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

using test::derivative;
using test::kPi;
using test::max_abs_diff;
using test::Random;

// ---------------------------------------------------------------------------------------------
// Oracles written out here, independent of the library.

// (6.25) elementary component matrices, as printed in the book.
Tensor Rx(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Tensor R;
  R << 1, 0, 0,  //
      0, c, -s,  //
      0, s, c;
  return R;
}
Tensor Ry(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Tensor R;
  R << c, 0, s,  //
      0, 1, 0,   //
      -s, 0, c;
  return R;
}
Tensor Rz(double a) {
  const double c = std::cos(a), s = std::sin(a);
  Tensor R;
  R << c, -s, 0,  //
      s, c, 0,    //
      0, 0, 1;
  return R;
}
Tensor R_axis(int axis, double a) {
  switch (axis) {
    case 1:
      return Rx(a);
    case 2:
      return Ry(a);
    default:
      return Rz(a);
  }
}

// Q = R_I(γ1) R_J(γ2) R_K(γ3) for the set I-J-K.
Tensor product_of_elementary(const EulerSet& set, const Vec3& g) {
  return R_axis(set.first, g[0]) * R_axis(set.second, g[1]) * R_axis(set.third, g[2]);
}

// ε_ijk for i, j, k ∈ {1, 2, 3}.
int levi_civita(int i, int j, int k) {
  return (i - j) * (j - k) * (k - i) / 2;
}

// Axial vector of the skew part of W: W a = w × a.
Vec3 axial_of(const Tensor& W) {
  return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
}

// Skew tensor W with W a = w × a.
Tensor skew_of(const Vec3& w) {
  Tensor W;
  W << 0, -w[2], w[1],  //
      w[2], 0, -w[0],   //
      -w[1], w[0], 0;
  return W;
}

// Rotation by |w| t about w/|w| (Rodrigues' formula exp(t skew(w))).
Tensor exp_skew(const Vec3& w, double t) {
  const double n = w.norm();
  const Tensor K = skew_of(w / n);
  return Tensor::Identity() + std::sin(n * t) * K + (1.0 - std::cos(n * t)) * K * K;
}

// Nearest rotation through the SVD, written here.
Tensor orthonormalise(const Tensor& A) {
  Eigen::JacobiSVD<Tensor> svd(A, Eigen::ComputeFullU | Eigen::ComputeFullV);
  return svd.matrixU() * svd.matrixV().transpose();
}

// a − b reduced to (−π, π].
double angle_diff(double a, double b) {
  return std::remainder(a - b, 2.0 * kPi);
}

EulerSet set_of(const char* name) {
  return EulerSet::parse(name).value();
}

// Singular values of the second angle: 0, π (symmetric) or ±π/2 (Tait–Bryan).
std::array<double, 2> singular_second_angles(const EulerSet& set) {
  if (set.symmetric()) return {0.0, kPi};
  return {-kPi / 2, kPi / 2};
}

// Random angles with γ1, γ3 ∈ (−π, π) and γ2 at least `margin` inside its documented range.
Vec3 random_angles(Random& rng, const EulerSet& set, double margin) {
  const double lo = set.symmetric() ? margin : -kPi / 2 + margin;
  const double hi = set.symmetric() ? kPi - margin : kPi / 2 - margin;
  return Vec3(rng.uniform(-kPi, kPi), rng.uniform(lo, hi), rng.uniform(-kPi, kPi));
}

// [g1, g2, g3] derived by hand: rotating by L(γ1, E_I) leaves the triple product unchanged, so it
// equals [E_I, E_J, L(γ2, E_J) E_K]. Tait–Bryan (K ≠ I): L(γ2,E_J)E_K = cos γ2 E_K + sin γ2 E_J×E_K
// gives ε_IJK cos γ2. Symmetric (K = I): L(γ2,E_J)E_I = cos γ2 E_I + sin γ2 E_J×E_I gives −sin γ2.
double expected_volume(const EulerSet& set, double second) {
  if (set.symmetric()) return -std::sin(second);
  return levi_civita(set.first, set.second, set.third) * std::cos(second);
}

bool in_documented_range(const EulerSet& set, const Vec3& a) {
  const bool outer = a[0] > -kPi && a[0] <= kPi && a[2] > -kPi && a[2] <= kPi;
  const bool middle =
      set.symmetric() ? (a[1] >= 0.0 && a[1] <= kPi) : (a[1] >= -kPi / 2 && a[1] <= kPi / 2);
  return outer && middle;
}

// Build a 3×3 from rows typed as in the book ("rows give components").
Tensor rows(const Vec3& r1, const Vec3& r2, const Vec3& r3) {
  Tensor M;
  M.row(0) = r1.transpose();
  M.row(1) = r2.transpose();
  M.row(2) = r3.transpose();
  return M;
}

// ---------------------------------------------------------------------------------------------
// EulerSet

// §6.8: 3 × 2 × 2 = 12 sets "I-J-K" with I ≠ J ≠ K; symmetric iff I = K.
TEST(EulerSet, ParseAcceptsExactlyTheTwelveSets) {
  int accepted = 0;
  for (int a = 1; a <= 3; ++a) {
    for (int b = 1; b <= 3; ++b) {
      for (int c = 1; c <= 3; ++c) {
        const std::string text =
            std::to_string(a) + "-" + std::to_string(b) + "-" + std::to_string(c);
        const auto set = EulerSet::parse(text);
        const bool valid = a != b && b != c;
        ASSERT_EQ(set.has_value(), valid) << text;
        if (!set) continue;
        ++accepted;
        EXPECT_EQ(set->first, a) << text;
        EXPECT_EQ(set->second, b) << text;
        EXPECT_EQ(set->third, c) << text;
        EXPECT_EQ(set->name(), text);
        EXPECT_EQ(set->symmetric(), a == c) << text;
        EXPECT_EQ(EulerSet::parse(set->name()), set);
      }
    }
  }
  EXPECT_EQ(accepted, 12);
}

// §6.8: anything that is not "I-J-K" with I ≠ J ≠ K is rejected.
TEST(EulerSet, ParseRejectsMalformedText) {
  for (const char* text : {"1-1-2", "3-3-1", "1-2-2", "4-1-2", "0-1-2", "1-2-4", "313", "3-1-3 ",
                           " 3-1-3", "", "a-b-c", "3_1_3", "3-1-3-1", "3--1-3", "-3-1-"}) {
    EXPECT_FALSE(EulerSet::parse(text).has_value()) << '"' << text << '"';
  }
}

// §6.8 "Other Euler-angle sets": the twelve sets in the book's order (3-2-1 for the misprint).
TEST(EulerSet, AllSetsAreTwelveDistinctValidSetsInBookOrder) {
  const auto& sets = all_euler_sets();
  const std::array<const char*, 12> book = {"1-2-3", "3-2-3", "1-2-1", "1-3-1", "1-3-2", "2-3-1",
                                            "2-3-2", "2-1-2", "2-1-3", "3-1-3", "3-2-1", "3-1-2"};
  std::set<std::string> names;
  int symmetric = 0;
  for (std::size_t n = 0; n < sets.size(); ++n) {
    const EulerSet& set = sets[n];
    EXPECT_EQ(set.name(), book[n]);
    EXPECT_EQ(EulerSet::parse(set.name()), set);
    EXPECT_NE(set.first, set.second);
    EXPECT_NE(set.second, set.third);
    names.insert(set.name());
    if (set.symmetric()) ++symmetric;
  }
  EXPECT_EQ(names.size(), 12u);
  EXPECT_EQ(symmetric, 6);
}

// ---------------------------------------------------------------------------------------------
// Rotation tensor

// (6.20) Q = L(γ1,E_I) L(γ2,E_J) L(γ3,E_K) ⇒ [Q] = R_I R_J R_K with the (6.25) matrices.
TEST(EulerRotationTensor, EqualsProductOfElementaryMatrices) {
  Random rng(101);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 500; ++n) {
      const Vec3 g = rng.vector(4.0);  // any angles, not only the documented ranges
      // Products of three matrices with entries ≤ 1: round-off of a few ulps.
      EXPECT_LT(max_abs_diff(rotation_tensor(set, g), product_of_elementary(set, g)), 1e-14)
          << set.name() << " " << g.transpose();
    }
  }
}

// (6.25) 3-2-1 and §1.9 3-1-3 component matrices, multiplied out by hand.
TEST(EulerRotationTensor, BookComponentMatrices321And313) {
  Random rng(102);
  for (int n = 0; n < 500; ++n) {
    const Vec3 g = rng.vector(kPi);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    Tensor Q321;  // Rz(ψ) Ry(θ) Rx(φ)
    Q321 << cps * cth, -sps * cph + cps * sth * sph, sps * sph + cps * sth * cph,  //
        sps * cth, cps * cph + sps * sth * sph, -cps * sph + sps * sth * cph,      //
        -sth, cth * sph, cth * cph;
    Tensor Q313;  // Rz(ψ) Rx(θ) Rz(φ)
    Q313 << cps * cph - sps * cth * sph, -cps * sph - sps * cth * cph, sps * sth,  //
        sps * cph + cps * cth * sph, -sps * sph + cps * cth * cph, -cps * sth,     //
        sth * sph, sth * cph, cth;
    EXPECT_LT(max_abs_diff(rotation_tensor(set_of("3-2-1"), g), Q321), 1e-14);
    EXPECT_LT(max_abs_diff(rotation_tensor(set_of("3-1-3"), g), Q313), 1e-14);
    EXPECT_LT(max_abs_diff(rotation_tensor(set_of("3-2-3"), g), Rz(g[0]) * Ry(g[1]) * Rz(g[2])),
              1e-14);
  }
}

// (6.43) [t] = A(φ) B(θ) C(ψ) [E] for 3-2-3; rows are t_i, so [Q] = (A B C)ᵀ since Q_ik = t_k·E_i.
TEST(EulerRotationTensor, Book323BasisForm643) {
  Random rng(103);
  for (int n = 0; n < 500; ++n) {
    const Vec3 g = rng.vector(kPi);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    const Tensor A = rows(Vec3(cph, sph, 0), Vec3(-sph, cph, 0), Vec3(0, 0, 1));
    const Tensor B = rows(Vec3(cth, 0, -sth), Vec3(0, 1, 0), Vec3(sth, 0, cth));
    const Tensor C = rows(Vec3(cps, sps, 0), Vec3(-sps, cps, 0), Vec3(0, 0, 1));
    const Tensor t = A * B * C;
    EXPECT_LT(max_abs_diff(rotation_tensor(set_of("3-2-3"), g), t.transpose()), 1e-14);
  }
}

// (6.6) QQᵀ = I, det Q = 1 for every set.
TEST(EulerRotationTensor, IsProperOrthogonal) {
  Random rng(104);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 300; ++n) {
      const Tensor Q = rotation_tensor(set, rng.vector(10.0));
      EXPECT_LT(max_abs_diff(Q * Q.transpose(), Tensor::Identity()), 1e-14) << set.name();
      EXPECT_NEAR(Q.determinant(), 1.0, 1e-14) << set.name();
    }
  }
}

// §6.5.1 example (W3): the printed matrix is the 3-2-3 rotation (0.2, −0.5, 0.1).
TEST(EulerBookExample, W3MatrixIs323Set) {
  Tensor book;
  book << 0.835959, -0.283542, -0.469869,  //
      0.271321, 0.957764, -0.0952472,      //
      0.47703, -0.0478627, 0.877583;
  const EulerSet s323 = set_of("3-2-3");
  const Tensor Q = rotation_tensor(s323, Vec3(0.2, -0.5, 0.1));
  // Printed to 6 significant digits: half a unit in the last place is ≤ 5e-7.
  EXPECT_LT(max_abs_diff(Q, book), 1e-6);

  // 3-2-1 angles of the same rotation (reference §2, printed to 7 decimals: rounding ≤ 5e-8).
  const EulerAngles a321 = euler_angles(set_of("3-2-1"), Q);
  EXPECT_NEAR(a321.angles[0], 0.3138365, 1e-7);
  EXPECT_NEAR(a321.angles[1], -0.4972728, 1e-7);
  EXPECT_NEAR(a321.angles[2], -0.0544853, 1e-7);
  EXPECT_FALSE(a321.singular);
  EXPECT_LT(max_abs_diff(rotation_tensor(set_of("3-2-1"), a321.angles), Q), 1e-12);
  // The same from the printed (rounded, not quite orthogonal) matrix: each angle depends on two
  // or three entries, each rounded by ≤ 5e-7, with factors ≤ 1/cos θ ≈ 1.14: ≲ 1.2e-6 (5e-7 seen).
  const EulerAngles printed = euler_angles(set_of("3-2-1"), book);
  EXPECT_NEAR(printed.angles[0], 0.3138365, 2e-6);
  EXPECT_NEAR(printed.angles[1], -0.4972728, 2e-6);
  EXPECT_NEAR(printed.angles[2], -0.0544853, 2e-6);

  // With θ ∈ [0, π] the 3-2-3 angles are (0.2 + π, 0.5, 0.1 + π), reduced to (−π, π].
  const EulerAngles a323 = euler_angles(s323, Q);
  EXPECT_NEAR(a323.angles[1], 0.5, 1e-12);
  EXPECT_NEAR(angle_diff(a323.angles[0], 0.2 + kPi), 0.0, 1e-12);
  EXPECT_NEAR(angle_diff(a323.angles[2], 0.1 + kPi), 0.0, 1e-12);
  EXPECT_TRUE(in_documented_range(s323, a323.angles)) << a323.angles.transpose();
  EXPECT_FALSE(a323.singular);
  EXPECT_LT(max_abs_diff(rotation_tensor(s323, a323.angles), Q), 1e-12);
}

// ---------------------------------------------------------------------------------------------
// Euler basis and its dual

// (6.26)–(6.27) 3-2-1 Euler basis in p and in t; rows of the book's matrices are g1, g2, g3.
TEST(EulerBasis, Book321Equations626And627) {
  Random rng(201);
  const EulerSet set = set_of("3-2-1");
  for (int n = 0; n < 300; ++n) {
    const Vec3 g = rng.vector(kPi);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    const Tensor in_p = rows(Vec3(0, 0, 1), Vec3(-sps, cps, 0), Vec3(cth * cps, cth * sps, -sth));
    const Tensor in_t = rows(Vec3(-sth, sph * cth, cph * cth), Vec3(0, cph, -sph), Vec3(1, 0, 0));
    const Tensor basis = euler_basis(set, g);  // columns g_i on E
    const Tensor Q = product_of_elementary(set, g);
    EXPECT_LT(max_abs_diff(basis, in_p.transpose()), 1e-14);
    // components on t: g_i · t_k = (Qᵀ g_i)_k
    EXPECT_LT(max_abs_diff(Q.transpose() * basis, in_t.transpose()), 1e-14);
  }
}

// (6.33) 3-1-3 and (6.2c) 3-2-3 Euler bases in p and in t.
TEST(EulerBasis, Book313Equation633And323Exercise62c) {
  Random rng(202);
  const EulerSet s313 = set_of("3-1-3");
  const EulerSet s323 = set_of("3-2-3");
  for (int n = 0; n < 300; ++n) {
    const Vec3 g = rng.vector(kPi);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    const Tensor p313 = rows(Vec3(0, 0, 1), Vec3(cps, sps, 0), Vec3(sth * sps, -sth * cps, cth));
    const Tensor t313 = rows(Vec3(sph * sth, cph * sth, cth), Vec3(cph, -sph, 0), Vec3(0, 0, 1));
    const Tensor p323 = rows(Vec3(0, 0, 1), Vec3(-sps, cps, 0), Vec3(cps * sth, sps * sth, cth));
    const Tensor t323 = rows(Vec3(-sth * cph, sph * sth, cth), Vec3(sph, cph, 0), Vec3(0, 0, 1));
    const Tensor b313 = euler_basis(s313, g);
    const Tensor b323 = euler_basis(s323, g);
    EXPECT_LT(max_abs_diff(b313, p313.transpose()), 1e-14);
    EXPECT_LT(max_abs_diff(b323, p323.transpose()), 1e-14);
    EXPECT_LT(max_abs_diff(product_of_elementary(s313, g).transpose() * b313, t313.transpose()),
              1e-14);
    EXPECT_LT(max_abs_diff(product_of_elementary(s323, g).transpose() * b323, t323.transpose()),
              1e-14);
  }
}

// (6.28)–(6.30) 3-2-1 dual basis in t and in p.
TEST(DualEulerBasis, Book321Equations629And630) {
  Random rng(203);
  const EulerSet set = set_of("3-2-1");
  for (int n = 0; n < 300; ++n) {
    const Vec3 g = random_angles(rng, set, 0.05);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    const double sec = 1.0 / cth, tan = sth / cth;
    const Tensor in_t =
        rows(Vec3(0, sph * sec, cph * sec), Vec3(0, cph, -sph), Vec3(1, sph * tan, cph * tan));
    const Tensor in_p =
        rows(Vec3(cps * tan, sps * tan, 1), Vec3(-sps, cps, 0), Vec3(cps * sec, sps * sec, 0));
    const Tensor dual = dual_euler_basis(set, g);
    // Entries up to sec θ ≤ 20: round-off ≈ 20 ulps.
    EXPECT_LT(max_abs_diff(dual, in_p.transpose()), 1e-13);
    EXPECT_LT(max_abs_diff(product_of_elementary(set, g).transpose() * dual, in_t.transpose()),
              1e-13);
  }
}

// (6.34) 3-1-3 dual basis and (6.2f) 3-2-3 dual basis in t, in p, and in g.
TEST(DualEulerBasis, Book313Equation634And323Exercise62f) {
  Random rng(204);
  const EulerSet s313 = set_of("3-1-3");
  const EulerSet s323 = set_of("3-2-3");
  for (int n = 0; n < 300; ++n) {
    const Vec3 g = random_angles(rng, s313, 0.05);
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);
    const double csc = 1.0 / sth, cot = cth / sth;
    const Tensor t313 =
        rows(Vec3(sph * csc, cph * csc, 0), Vec3(cph, -sph, 0), Vec3(-sph * cot, -cph * cot, 1));
    const Tensor p313 =
        rows(Vec3(-sps * cot, cps * cot, 1), Vec3(cps, sps, 0), Vec3(sps * csc, -cps * csc, 0));
    const Tensor t323 =
        rows(Vec3(-cph * csc, sph * csc, 0), Vec3(sph, cph, 0), Vec3(cph * cot, -sph * cot, 1));
    const Tensor p323 =
        rows(Vec3(-cps * cot, -sps * cot, 1), Vec3(-sps, cps, 0), Vec3(cps * csc, sps * csc, 0));
    const Tensor d313 = dual_euler_basis(s313, g);
    const Tensor d323 = dual_euler_basis(s323, g);
    EXPECT_LT(max_abs_diff(d313, p313.transpose()), 1e-13);
    EXPECT_LT(max_abs_diff(d323, p323.transpose()), 1e-13);
    EXPECT_LT(max_abs_diff(product_of_elementary(s313, g).transpose() * d313, t313.transpose()),
              1e-13);
    EXPECT_LT(max_abs_diff(product_of_elementary(s323, g).transpose() * d323, t323.transpose()),
              1e-13);
    // (6.2f) in g: g^1 = csc²θ g1 − cotθ cscθ g3, g^2 = g2, g^3 = −cotθ cscθ g1 + csc²θ g3.
    const Tensor b323 = euler_basis(s323, g);
    EXPECT_LT(max_abs_diff(d323.col(0), csc * csc * b323.col(0) - cot * csc * b323.col(2)), 1e-12);
    EXPECT_LT(max_abs_diff(d323.col(1), b323.col(1)), 1e-15);
    EXPECT_LT(max_abs_diff(d323.col(2), -cot * csc * b323.col(0) + csc * csc * b323.col(2)), 1e-12);
  }
}

// (6.22) g^i · g_j = δ^i_j and g^2 = g_2 for every set, and g_i = (g_i · g_j) g^j.
TEST(DualEulerBasis, IsReciprocalForAllSets) {
  Random rng(205);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 300; ++n) {
      const Vec3 g = random_angles(rng, set, 0.05);
      const Tensor basis = euler_basis(set, g);
      const Tensor dual = dual_euler_basis(set, g);
      // |g^i| ≤ 1/|[g1,g2,g3]| ≤ 1/sin 0.05 ≈ 20: round-off ≈ 20 ulps.
      EXPECT_LT(max_abs_diff(dual.transpose() * basis, Tensor::Identity()), 1e-13) << set.name();
      EXPECT_LT(max_abs_diff(dual.col(1), basis.col(1)), 1e-15) << set.name();
      const Tensor gram = basis.transpose() * basis;
      EXPECT_LT(max_abs_diff(dual * gram, basis), 1e-13) << set.name();
    }
  }
}

// (6.31) 3-2-1: g1 = g^1 − sθ g^3, g3 = −sθ g^1 + g^3; (6.35) 3-1-3: g1 = g^1 + cθ g^3, g3 = cθ g^1
// + g^3 (3-2-3 has the same Gram matrix as 3-1-3).
TEST(DualEulerBasis, BookRelations631And635) {
  Random rng(206);
  for (int n = 0; n < 300; ++n) {
    {
      const EulerSet set = set_of("3-2-1");
      const Vec3 g = random_angles(rng, set, 0.05);
      const Tensor b = euler_basis(set, g);
      const Tensor d = dual_euler_basis(set, g);
      const double s = std::sin(g[1]);
      EXPECT_LT(max_abs_diff(b.col(0), d.col(0) - s * d.col(2)), 1e-13);
      EXPECT_LT(max_abs_diff(b.col(2), -s * d.col(0) + d.col(2)), 1e-13);
    }
    for (const char* name : {"3-1-3", "3-2-3"}) {
      const EulerSet set = set_of(name);
      const Vec3 g = random_angles(rng, set, 0.05);
      const Tensor b = euler_basis(set, g);
      const Tensor d = dual_euler_basis(set, g);
      const double c = std::cos(g[1]);
      EXPECT_LT(max_abs_diff(b.col(0), d.col(0) + c * d.col(2)), 1e-13) << name;
      EXPECT_LT(max_abs_diff(b.col(2), c * d.col(0) + d.col(2)), 1e-13) << name;
    }
  }
}

// [g1, g2, g3] = ε_IJK cos γ2 (Tait–Bryan) or −sin γ2 (symmetric), derived in expected_volume.
TEST(EulerBasisVolume, IsSignedCosineOrSineOfSecondAngle) {
  Random rng(207);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 300; ++n) {
      const Vec3 g = rng.vector(4.0);
      const double volume = euler_basis_volume(set, g);
      EXPECT_NEAR(volume, expected_volume(set, g[1]), 1e-14) << set.name();
      EXPECT_NEAR(volume, euler_basis(set, g).determinant(), 1e-14) << set.name();
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Angular velocity and the kinematic differential equations

// (6.21) ω = γ̇^i g_i equals axial(Q̇ Qᵀ) (§6.4) with Q̇ by 4th-order finite differences.
TEST(EulerAngularVelocity, MatchesFiniteDifferenceOfRotationTensor) {
  Random rng(301);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 300; ++n) {
      const Vec3 g0 = rng.vector(kPi);
      const Vec3 rates = rng.vector(1.0);
      const std::function<Tensor(double)> Q_of_t = [&](double t) {
        return rotation_tensor(set, g0 + t * rates);
      };
      const Tensor Q = Q_of_t(0.0);
      const Tensor Q_rate = derivative(Q_of_t, 0.0, 1e-3);
      // Truncation h⁴/30 |Q⁽⁵⁾| with |Q⁽⁵⁾| ≲ (Σ|γ̇|)⁵ ≤ 3⁵ gives ≲ 1e-11; round-off ≈ ε/h ≈ 1e-13.
      const Vec3 expected = axial_of(Q_rate * Q.transpose());
      const Vec3 omega = angular_velocity(set, g0, rates);
      EXPECT_LT(max_abs_diff(omega, expected), 1e-9) << set.name();
      EXPECT_LT(max_abs_diff(unidyn::angular_velocity(Q, Q_rate), expected), 1e-12);
    }
  }
}

// §1.8 ω·t_k for 3-2-1, the 3-1-3 components following (6.32)–(6.33), and (6.2h) Ω_i for 3-2-3.
TEST(EulerAngularVelocity, BookClosedForms) {
  Random rng(302);
  for (int n = 0; n < 500; ++n) {
    const Vec3 g = rng.vector(kPi);
    const Vec3 r = rng.vector(2.0);  // (ψ̇, θ̇, φ̇)
    const double cps = std::cos(g[0]), sps = std::sin(g[0]);
    const double cth = std::cos(g[1]), sth = std::sin(g[1]);
    const double cph = std::cos(g[2]), sph = std::sin(g[2]);

    const EulerSet s321 = set_of("3-2-1");
    const Vec3 body321(-r[0] * sth + r[2], r[0] * sph * cth + r[1] * cph,
                       r[0] * cph * cth - r[1] * sph);
    const Vec3 w321 = angular_velocity(s321, g, r);
    EXPECT_LT(max_abs_diff(product_of_elementary(s321, g).transpose() * w321, body321), 1e-14);

    const EulerSet s313 = set_of("3-1-3");
    const Vec3 body313(r[0] * sph * sth + r[1] * cph, r[0] * cph * sth - r[1] * sph,
                       r[0] * cth + r[2]);
    const Vec3 w313 = angular_velocity(s313, g, r);
    EXPECT_LT(max_abs_diff(product_of_elementary(s313, g).transpose() * w313, body313), 1e-14);

    const EulerSet s323 = set_of("3-2-3");
    const Vec3 space323(r[2] * sth * cps - r[1] * sps, r[2] * sth * sps + r[1] * cps,
                        r[2] * cth + r[0]);
    EXPECT_LT(max_abs_diff(angular_velocity(s323, g, r), space323), 1e-14);
  }
}

// (6.22) γ̇^i = ω·g^i inverts (6.21) away from gimbal lock, for every set.
TEST(EulerAngleRates, InvertsAngularVelocity) {
  Random rng(303);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 300; ++n) {
      const Vec3 g = random_angles(rng, set, 0.05);
      const Vec3 rates = rng.vector(2.0);
      const Vec3 omega = rng.vector(2.0);
      // Condition number ≲ 1/sin 0.05 ≈ 20.
      EXPECT_LT(max_abs_diff(euler_angle_rates(set, g, angular_velocity(set, g, rates)), rates),
                1e-13)
          << set.name();
      EXPECT_LT(max_abs_diff(angular_velocity(set, g, euler_angle_rates(set, g, omega)), omega),
                1e-13)
          << set.name();
    }
  }
}

// Kinematic ODEs: §1.8 (3-2-1), §1.9 (3-1-3) and (6.45) (3-2-3), with ω_k = ω·t_k.
TEST(EulerAngleRates, BookKinematicEquations) {
  Random rng(304);
  for (int n = 0; n < 500; ++n) {
    const Vec3 wb = rng.vector(2.0);
    {
      const EulerSet set = set_of("3-2-1");
      const Vec3 g = random_angles(rng, set, 0.05);
      const double cth = std::cos(g[1]), sth = std::sin(g[1]);
      const double cph = std::cos(g[2]), sph = std::sin(g[2]);
      const double k = sph * wb[1] + cph * wb[2];
      const Vec3 expected(k / cth, cph * wb[1] - sph * wb[2], wb[0] + k * sth / cth);
      const Vec3 omega = product_of_elementary(set, g) * wb;
      EXPECT_LT(max_abs_diff(euler_angle_rates(set, g, omega), expected), 1e-12);
    }
    {
      const EulerSet set = set_of("3-1-3");
      const Vec3 g = random_angles(rng, set, 0.05);
      const double cth = std::cos(g[1]), sth = std::sin(g[1]);
      const double cph = std::cos(g[2]), sph = std::sin(g[2]);
      const double k = sph * wb[0] + cph * wb[1];
      const Vec3 expected(k / sth, cph * wb[0] - sph * wb[1], wb[2] - k * cth / sth);
      const Vec3 omega = product_of_elementary(set, g) * wb;
      EXPECT_LT(max_abs_diff(euler_angle_rates(set, g, omega), expected), 1e-12);
    }
    {
      const EulerSet set = set_of("3-2-3");
      const Vec3 g = random_angles(rng, set, 0.05);
      const double cth = std::cos(g[1]), sth = std::sin(g[1]);
      const double cph = std::cos(g[2]), sph = std::sin(g[2]);
      const double csc = 1.0 / sth, cot = cth / sth;
      Tensor M;                       // (6.45)
      M << -cph * csc, sph * csc, 0,  //
          sph, cph, 0,                //
          cph * cot, -sph * cot, 1;
      const Vec3 omega = product_of_elementary(set, g) * wb;
      EXPECT_LT(max_abs_diff(euler_angle_rates(set, g, omega), M * wb), 1e-12);
    }
  }
}

// (6.22) against finite differences of the angles extracted along Q(t) = Q0 exp(t skew(w)).
TEST(EulerAngleRates, MatchFiniteDifferenceOfExtractedAngles) {
  Random rng(305);
  int checked = 0;
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 100; ++n) {
      const Tensor Q0 = rng.rotation();
      const Vec3 w = rng.vector(1.0);  // body angular velocity; spatial ω(0) = Q0 w
      const EulerAngles start = euler_angles(set, Q0);
      if (std::abs(start.volume) < 0.2) continue;  // stay away from gimbal lock
      ++checked;
      Vec3 fd;
      for (int i = 0; i < 3; ++i) {
        // Unwrapped angle i along the motion.
        const std::function<double(double)> angle = [&](double t) {
          const double a = euler_angles(set, Q0 * exp_skew(w, t)).angles[i];
          return start.angles[i] + angle_diff(a, start.angles[i]);
        };
        fd[i] = derivative(angle, 0.0, 1e-3);
      }
      // Truncation h⁴/30 |γ⁽⁵⁾| with |γ⁽⁵⁾| ≲ (|w|/0.2)⁵ ≲ 1e4: ≲ 1e-9.
      EXPECT_LT(max_abs_diff(euler_angle_rates(set, start.angles, Q0 * w), fd), 1e-8)
          << set.name() << " " << start.angles.transpose();
    }
  }
  EXPECT_GT(checked, 1100);  // ≈ 98% of uniform rotations have |volume| ≥ 0.2
}

// ---------------------------------------------------------------------------------------------
// Angles of a rotation

// Inverse of (6.20): angles reproduce Q, lie in the documented ranges, and report their volume.
TEST(EulerAnglesOfRotation, RoundTripRandomRotations) {
  Random rng(401);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 1000; ++n) {
      const Tensor Q = rng.rotation();
      const EulerAngles a = euler_angles(set, Q);
      EXPECT_LT(max_abs_diff(rotation_tensor(set, a.angles), Q), 1e-12) << set.name();
      EXPECT_LT(max_abs_diff(product_of_elementary(set, a.angles), Q), 1e-12) << set.name();
      EXPECT_TRUE(in_documented_range(set, a.angles)) << set.name() << " " << a.angles.transpose();
      EXPECT_NEAR(a.volume, expected_volume(set, a.angles[1]), 1e-14) << set.name();
      EXPECT_EQ(a.singular, std::abs(a.volume) <= kGimbalLockTolerance) << set.name();
    }
  }
}

// Inverse of (6.20): angles drawn inside the ranges, away from gimbal lock, are recovered.
TEST(EulerAnglesOfRotation, AnglesRoundTripInsideRanges) {
  Random rng(402);
  for (const EulerSet& set : all_euler_sets()) {
    for (int n = 0; n < 1000; ++n) {
      const Vec3 g = random_angles(rng, set, 0.01);
      const EulerAngles a = euler_angles(set, product_of_elementary(set, g));
      // γ1 and γ3 are found to ≈ ε / sin(margin) ≈ 2e-14.
      EXPECT_NEAR(angle_diff(a.angles[0], g[0]), 0.0, 1e-12) << set.name();
      EXPECT_NEAR(a.angles[1], g[1], 1e-12) << set.name();
      EXPECT_NEAR(angle_diff(a.angles[2], g[2]), 0.0, 1e-12) << set.name();
      EXPECT_FALSE(a.singular) << set.name();
    }
  }
}

// Documented ranges at exact quarter and half turns: the 24 rotations that permute ±E_i.
TEST(EulerAnglesOfRotation, SignedPermutationRotationsStayInRange) {
  const std::array<std::array<int, 3>, 6> perms = {
      {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}}};
  int rotations = 0;
  for (const auto& p : perms) {
    for (int signs = 0; signs < 8; ++signs) {
      Tensor Q = Tensor::Zero();
      for (int c = 0; c < 3; ++c) Q(p[c], c) = ((signs >> c) & 1) ? -1.0 : 1.0;
      if (Q.determinant() < 0) continue;
      ++rotations;
      for (const EulerSet& set : all_euler_sets()) {
        const EulerAngles a = euler_angles(set, Q);
        EXPECT_LT(max_abs_diff(rotation_tensor(set, a.angles), Q), 1e-12) << set.name() << "\n"
                                                                          << Q;
        EXPECT_TRUE(in_documented_range(set, a.angles))
            << set.name() << " angles " << a.angles.transpose() << "\n"
            << Q;
      }
    }
  }
  EXPECT_EQ(rotations, 24);
}

// §6.8 gimbal lock: at and near the singular second angle (g1 = ±g3, [g1,g2,g3] → 0).
TEST(EulerAnglesOfRotation, GimbalLockAtAndNearSingularSecondAngle) {
  Random rng(403);
  // Lock is declared only within round-off of the singular angle: above the ~1e-16 error of a
  // computed [g1,g2,g3], and below 1e-10 so that 1e-10, 1e-8, … are not locked.
  EXPECT_GE(kGimbalLockTolerance, 1e-14);
  EXPECT_LE(kGimbalLockTolerance, 1e-11);
  const std::array<double, 6> distances = {0.0, 1e-13, 1e-10, 1e-8, 1e-6, 1e-3};
  for (const EulerSet& set : all_euler_sets()) {
    for (const double singular_angle : singular_second_angles(set)) {
      // Move into the documented range of the second angle.
      const double inward = (singular_angle > 0.0) ? -1.0 : 1.0;
      for (const double d : distances) {
        for (int n = 0; n < 20; ++n) {
          const Vec3 g(rng.uniform(-3.0, 3.0), singular_angle + inward * d, rng.uniform(-3.0, 3.0));
          const std::string where = set.name() + " θ = " + std::to_string(singular_angle) + " + " +
                                    std::to_string(inward * d);
          const Tensor Q = product_of_elementary(set, g);
          const EulerAngles a = euler_angles(set, Q);
          EXPECT_LT(max_abs_diff(rotation_tensor(set, a.angles), Q), 1e-12) << where;
          EXPECT_TRUE(in_documented_range(set, a.angles)) << where << " " << a.angles.transpose();
          EXPECT_NEAR(a.angles[1], g[1], 1e-12) << where;
          // |[g1,g2,g3]| = sin d, far above round-off (1e-16) except at d ≤ 1e-13.
          EXPECT_NEAR(std::abs(a.volume), std::sin(d), 1e-15) << where;
          EXPECT_NEAR(std::abs(euler_basis_volume(set, g)), std::sin(d), 1e-15) << where;
          const bool locked = d < kGimbalLockTolerance;
          EXPECT_EQ(a.singular, locked) << where;
          if (a.singular) {
            EXPECT_EQ(a.angles[0], 0.0) << where;
          } else {
            // γ1 is found to ≈ ε / sin d.
            EXPECT_NEAR(angle_diff(a.angles[0], g[0]), 0.0, 1e-15 / std::sin(d) + 1e-15) << where;
          }
          if (locked) {
            // g1 = ±g3 at gimbal lock.
            const Tensor b = euler_basis(set, g);
            EXPECT_LT(std::min(max_abs_diff(b.col(0), b.col(2)), max_abs_diff(b.col(0), -b.col(2))),
                      1e-12)
                << where;
            EXPECT_THROW(dual_euler_basis(set, g), SingularConfiguration) << where;
            EXPECT_THROW(euler_angle_rates(set, g, Vec3(0.1, 0.2, 0.3)), SingularConfiguration)
                << where;
          } else {
            EXPECT_NO_THROW(dual_euler_basis(set, g)) << where;
            EXPECT_NO_THROW(euler_angle_rates(set, g, Vec3(0.1, 0.2, 0.3))) << where;
          }
        }
      }
    }
  }
}

// Exercise 6.11: the 3-2-1 angles of Qᵀ reproduce Qᵀ; its 1-2-3 angles are (−α3, −α2, −α1).
TEST(EulerBookExercise, E611AnglesOfTranspose) {
  Random rng(501);
  const EulerSet s321 = set_of("3-2-1");
  const EulerSet s123 = set_of("1-2-3");
  for (int n = 0; n < 1000; ++n) {
    const Vec3 alpha = random_angles(rng, s321, 0.01);
    const Tensor Qt = (Rz(alpha[0]) * Ry(alpha[1]) * Rx(alpha[2])).transpose();
    const EulerAngles a = euler_angles(s321, Qt);
    EXPECT_LT(max_abs_diff(rotation_tensor(s321, a.angles), Qt), 1e-12);
    EXPECT_LT(max_abs_diff(Rz(a.angles[0]) * Ry(a.angles[1]) * Rx(a.angles[2]), Qt), 1e-12);
    const EulerAngles b = euler_angles(s123, Qt);
    EXPECT_NEAR(angle_diff(b.angles[0], -alpha[2]), 0.0, 1e-12);
    EXPECT_NEAR(b.angles[1], -alpha[1], 1e-12);
    EXPECT_NEAR(angle_diff(b.angles[2], -alpha[0]), 0.0, 1e-12);
  }
}

// Exercise 6.12: space-fixed 3-2-1 (β1, β2, β3), [R] = Rx(β3) Ry(β2) Rz(β1), is body 1-2-3 with
// (β3, β2, β1).
TEST(EulerBookExercise, E612SpaceFixed321IsBody123) {
  Random rng(502);
  const EulerSet s123 = set_of("1-2-3");
  for (int n = 0; n < 1000; ++n) {
    const Vec3 beta = random_angles(rng, s123, 0.01);  // β2 ∈ (−π/2, π/2)
    const Tensor R = Rx(beta[2]) * Ry(beta[1]) * Rz(beta[0]);
    EXPECT_LT(max_abs_diff(rotation_tensor(s123, Vec3(beta[2], beta[1], beta[0])), R), 1e-14);
    const EulerAngles a = euler_angles(s123, R);
    EXPECT_NEAR(angle_diff(a.angles[0], beta[2]), 0.0, 1e-12);
    EXPECT_NEAR(a.angles[1], beta[1], 1e-12);
    EXPECT_NEAR(angle_diff(a.angles[2], beta[0]), 0.0, 1e-12);
  }
}

// Body angular velocity components ω_body(t), as gyros measure them.
using BodySignals = std::function<Vec3(double)>;

// The attitude from gyro signals two ways, each by RK4 with `steps` steps to T: the Euler angles of
// `set` by the library's (6.45)-type rates γ̇ = ω · g^i (the smallest and largest second angle met
// in `second`), and Q by Q̇ = Q skew(ω_body) on its nine components; the angles' rotation tensor is
// returned with Q.
struct TwoAttitudes {
  Vec3 angles;
  Tensor Q;
  double second_min, second_max;
};
TwoAttitudes integrate_attitude(const EulerSet& set, const BodySignals& body_omega, Vec3 g,
                                double T, int steps) {
  const double h = T / steps;
  const auto angle_rates = [&](double t, const Vec3& a) {
    return euler_angle_rates(set, a, rotation_tensor(set, a) * body_omega(t));
  };
  TwoAttitudes out{g, rotation_tensor(set, g), g[1], g[1]};
  for (int n = 0; n < steps; ++n) {
    const double t = n * h;
    const Vec3 k1 = angle_rates(t, g);
    const Vec3 k2 = angle_rates(t + h / 2, g + h / 2 * k1);
    const Vec3 k3 = angle_rates(t + h / 2, g + h / 2 * k2);
    const Vec3 k4 = angle_rates(t + h, g + h * k3);
    g += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    out.second_min = std::min(out.second_min, g[1]);
    out.second_max = std::max(out.second_max, g[1]);
  }
  out.angles = g;
  const auto Q_rate = [&](double t, const Tensor& Q) { return Tensor(Q * skew_of(body_omega(t))); };
  Tensor Q = out.Q;
  for (int n = 0; n < steps; ++n) {
    const double t = n * h;
    const Tensor k1 = Q_rate(t, Q);
    const Tensor k2 = Q_rate(t + h / 2, Q + h / 2 * k1);
    const Tensor k3 = Q_rate(t + h / 2, Q + h / 2 * k2);
    const Tensor k4 = Q_rate(t + h, Q + h * k3);
    Q += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  out.Q = orthonormalise(Q);
  return out;
}

// Exercise 6.2(j): integrate (6.45) and compare with Q̇ = Q skew(ω_body) integrated directly.
TEST(EulerBookExercise, E62jIntegrationOf323KinematicEquation) {
  const EulerSet set = set_of("3-2-3");
  const auto body_omega = [](double t) {
    const double w1 = 0.2 * std::sin(0.5 * t);
    return Vec3(w1, 0.2 * std::sin(0.05 * t), 10.0 * w1);
  };
  // h = 4e-3. RK4's global error is O(h⁴): already at h = 1e-2 the final angles agree with
  // h = 1e-3 to 3e-11 (checked offline), so at h = 4e-3 the error is ≲ 1e-12, far below 1e-8.
  // Independent: Q from Rz(0.3) Ry(1.0) Rz(0.2), its nine components integrated.
  const TwoAttitudes a = integrate_attitude(set, body_omega, Vec3(0.3, 1.0, 0.2), 20.0, 5000);
  // The trajectory keeps well clear of θ = 0, π, where (6.45) is singular.
  EXPECT_GT(a.second_min, 0.5);
  EXPECT_LT(a.second_max, kPi - 0.5);
  EXPECT_LT(max_abs_diff(rotation_tensor(set, a.angles), a.Q), 1e-8);
  EXPECT_LT(max_abs_diff(Rz(a.angles[0]) * Ry(a.angles[1]) * Rz(a.angles[2]), a.Q), 1e-8);
  // The same final angles from the tensor integration.
  const EulerAngles found = euler_angles(set, a.Q);
  EXPECT_NEAR(angle_diff(found.angles[0], a.angles[0]), 0.0, 1e-8);
  EXPECT_NEAR(found.angles[1], a.angles[1], 1e-8);
  EXPECT_NEAR(angle_diff(found.angles[2], a.angles[2]), 0.0, 1e-8);
}

// Exercise 7.9(f): an aircraft starting level (3-1-2 angles 0) with gyro signals ω1 = 0.02 sin
// 0.5t, ω2 = 0.02 sin 0.05t, ω3 = 2.0 sin 0.5t: the attitude from (7.28) is the one Q̇ = Q
// skew(ω_body) gives (the book prints no numbers), clear of the set's singular roll ±π/2; and
// (iii), the rotation axis against the instantaneous axis.
TEST(EulerBookExercise, E79fAircraftAttitudeFromGyros) {
  const EulerSet set = set_of("3-1-2");
  const auto body_omega = [](double t) {
    return Vec3(0.02 * std::sin(0.5 * t), 0.02 * std::sin(0.05 * t), 2.0 * std::sin(0.5 * t));
  };
  const TwoAttitudes a = integrate_attitude(set, body_omega, Vec3(0, 0, 0), 40.0, 10000);
  EXPECT_GT(a.second_min, -kPi / 2 + 0.5);
  EXPECT_LT(a.second_max, kPi / 2 - 0.5);
  EXPECT_GT(a.second_max - a.second_min, 1e-3);  // it does roll
  EXPECT_LT(max_abs_diff(rotation_tensor(set, a.angles), a.Q), 1e-8);
  // (iii): the rotation axis q of Q(40) = Q(40)Q(0)ᵀ (L(angle, q) gives Q back, (6.8) typed) is
  // not the instantaneous axis i = ω/‖ω‖ (§7.5; printed "ω̇/‖ω̇‖", a ⚠): 0.12 rad apart at t = 40,
  // where the attitude is known to 1e-8
  const AxisAngle rotation = axis_angle(a.Q);
  EXPECT_LT(max_abs_diff(test::book_L(rotation.angle, rotation.axis), a.Q), 1e-12);
  const Vec3 omega = a.Q * body_omega(40.0);
  const double apart = std::acos(std::abs(rotation.axis.dot(omega.normalized())));
  EXPECT_GT(apart, 1e-3) << "q = " << rotation.axis.transpose() << ", i = " << omega.transpose();
  std::printf("t = 40: rotation angle %.4f about q, %.3f rad from the instantaneous axis\n",
              rotation.angle, apart);
}

}  // namespace
}  // namespace unidyn

namespace unidyn {
namespace {

// Exercise 7.2(d): the robot arm's load turns by the 3-2-3 set (ψ about E3, θ about g2, φ about
// g3); r = H E3 + L g3 does not depend on φ, so when r returns (ψ, θ as before) the load has
// turned by Q(t1) Q(t0)ᵀ = L(φ(t1) − φ(t0), g3(t0)).
TEST(EulerBookExercise, E72dRobotArmTurnsAboutG3WhenItsTipReturns) {
  const EulerSet set = *EulerSet::parse("3-2-3");
  test::Random random;
  for (int trial = 0; trial < 50; ++trial) {
    const double psi = random.uniform(-3, 3), theta = random.uniform(0.1, 3);
    const double phi0 = random.uniform(-3, 3), phi1 = random.uniform(-3, 3);
    const Tensor Q0 = rotation_tensor(set, Vec3(psi, theta, phi0));
    const Tensor Q1 = rotation_tensor(set, Vec3(psi, theta, phi1));
    const Vec3 g3_0 = euler_basis(set, Vec3(psi, theta, phi0)).col(2);
    const Vec3 g3_1 = euler_basis(set, Vec3(psi, theta, phi1)).col(2);
    EXPECT_LT((g3_1 - g3_0).norm(), 1e-15) << "r = H E3 + L g3 returns";
    EXPECT_LT(max_abs_diff(Q1 * Q0.transpose(), test::book_L(phi1 - phi0, g3_0)), 1e-14);
  }
}

// Exercise 8.3(c): body 1 turned by Q1 (3-2-1 angles γ), body 2 by Q2 = Q1 P with P the 1-3-1
// set of angles ν relative to body 1: ω2 − ω1 = ν̇¹ ₁e1 + ν̇² ₂e3′ + ν̇³ ₂e1 (₂e3′ = Q1 L(ν¹, E1) E3,
// ₂e1 = Q2 E1) — against ω = axial(Q̇ Qᵀ) of both bodies by finite differences.
TEST(EulerBookExercise, E83RelativeAngularVelocity) {
  const EulerSet body1 = *EulerSet::parse("3-2-1"), relative = *EulerSet::parse("1-3-1");
  const auto gamma = [](double t) {
    return Vec3(0.3 + 0.7 * t, -0.2 + 0.4 * t * t, 1.1 - 0.5 * t);
  };
  const auto nu = [](double t) { return Vec3(0.5 - 0.9 * t, 1.2 + 0.3 * t, -0.4 + 1.3 * t * t); };
  const auto Q1 = [&](double t) { return rotation_tensor(body1, gamma(t)); };
  const auto Q2 = [&](double t) { return Tensor(Q1(t) * rotation_tensor(relative, nu(t))); };
  // ω of Q(t): the axial vector of Q̇ Qᵀ
  const auto omega = [](const std::function<Tensor(double)>& Q, double t) {
    const Tensor W = test::derivative(Q, t) * Q(t).transpose();
    return Vec3(W(2, 1), W(0, 2), W(1, 0));
  };
  for (const double t : {0.0, 0.4, 1.1}) {
    const Vec3 rates = (nu(t + 1e-6) - nu(t - 1e-6)) / 2e-6;
    const Vec3 e1_body1 = Q1(t) * Vec3::UnitX();
    const Vec3 e3_prime = Q1(t) * test::book_L(nu(t)[0], Vec3::UnitX()) * Vec3::UnitZ();
    const Vec3 e1_body2 = Q2(t) * Vec3::UnitX();
    const Vec3 book = rates[0] * e1_body1 + rates[1] * e3_prime + rates[2] * e1_body2;
    EXPECT_LT((omega(Q2, t) - omega(Q1, t) - book).norm(), 1e-8) << t;
  }
}

}  // namespace
}  // namespace unidyn
