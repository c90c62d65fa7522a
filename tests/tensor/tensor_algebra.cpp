// Tensor algebra of Appendix A: alternator, tensor products, skew tensors and axial vectors,
// invariants, adjugate, spectral decomposition, positive definiteness and rotations.
//
// Oracles are closed forms and exercise answers from the book notes, identities checked on seeded
// random inputs, and independent computations written here (explicit Σ ε_ijk loops from a table
// of the alternator, cofactors from 2×2 minors). Entries of the random inputs are O(1), so a
// result assembled from a handful of products is accurate to a few units of 2⁻⁵² ≈ 2.2e-16 times
// its size; kTol = 1e-13 leaves two orders of magnitude of margin for that round-off.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "support/oracles.hpp"
#include "unidyn/tensor/tensor.hpp"

namespace unidyn {
namespace {

using test::max_abs_diff;
using test::Random;

constexpr double kTol = 1e-13;
constexpr int kSamples = 1000;

// ε_ijk (indices 1..3) from an explicit table of the six permutations of §A.2, independent of the
// formula used by the library.
int epsilon(int i, int j, int k) {
  constexpr std::array<std::array<int, 3>, 3> even{{{1, 2, 3}, {2, 3, 1}, {3, 1, 2}}};
  constexpr std::array<std::array<int, 3>, 3> odd{{{2, 1, 3}, {1, 3, 2}, {3, 2, 1}}};
  for (const auto& p : even)
    if (p[0] == i && p[1] == j && p[2] == k) return 1;
  for (const auto& p : odd)
    if (p[0] == i && p[1] == j && p[2] == k) return -1;
  return 0;
}

// E_i built here, with indices 1..3.
Vec3 E(int i) {
  Vec3 v = Vec3::Zero();
  v(i - 1) = 1.0;
  return v;
}

// a ⊗ b written out componentwise: (a ⊗ b)_ij = a_i b_j.
Tensor outer(const Vec3& a, const Vec3& b) {
  Tensor T;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T(i, j) = a(i) * b(j);
  return T;
}

// [a, b, c] as the determinant of the matrix with columns a, b, c (A.7)/(A.8).
double det_columns(const Vec3& a, const Vec3& b, const Vec3& c) {
  Tensor M;
  M.col(0) = a;
  M.col(1) = b;
  M.col(2) = c;
  return M.determinant();
}

double triple(const Vec3& a, const Vec3& b, const Vec3& c) {
  return a.dot(b.cross(c));
}

Tensor random_tensor(Random& rng, double scale = 1.0) {
  Tensor A;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i, j) = rng.uniform(-scale, scale);
  return A;
}

Tensor random_symmetric(Random& rng) {
  const Tensor B = random_tensor(rng);
  return B + B.transpose();
}

Tensor random_skew(Random& rng) {
  const Tensor B = random_tensor(rng);
  return B - B.transpose();
}

// Q diag(d) Qᵀ: a symmetric tensor with known eigenvalues d and eigenvectors the columns of Q.
Tensor with_spectrum(const Tensor& Q, const Vec3& d) {
  return Q * d.asDiagonal() * Q.transpose();
}

// Cofactor matrix from signed 2×2 minors: cof_ij = (−1)^(i+j) M_ij.
Tensor cofactor(const Tensor& A) {
  Tensor C;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const int r0 = i == 0 ? 1 : 0, r1 = i == 2 ? 1 : 2;
      const int c0 = j == 0 ? 1 : 0, c1 = j == 2 ? 1 : 2;
      const double minor = A(r0, c0) * A(r1, c1) - A(r0, c1) * A(r1, c0);
      C(i, j) = (i + j) % 2 == 0 ? minor : -minor;
    }
  }
  return C;
}

// A small rotation about a random axis, from Rodrigues' formula written out here.
Tensor small_rotation(Random& rng, double angle) {
  const Vec3 r = rng.unit_vector();
  Tensor K;
  K << 0.0, -r.z(), r.y(),  //
      r.z(), 0.0, -r.x(),   //
      -r.y(), r.x(), 0.0;
  return Tensor::Identity() + std::sin(angle) * K + (1.0 - std::cos(angle)) * K * K;
}

// ---------------------------------------------------------------------------------------------
// Basis vectors and the alternator symbol

// (§A.2) E_i are the columns of the identity; indices outside 1..3 are rejected.
TEST(TensorAlgebra, BasisVectors) {
  for (int i = 1; i <= 3; ++i) EXPECT_EQ(basis_vector(i), E(i)) << "i = " << i;
  EXPECT_THROW(basis_vector(0), std::out_of_range);
  EXPECT_THROW(basis_vector(4), std::out_of_range);
  EXPECT_THROW(basis_vector(-1), std::out_of_range);
}

// (§A.2) ε123 = ε231 = ε312 = 1, ε213 = ε132 = ε321 = −1, zero when an index repeats.
TEST(TensorAlgebra, AlternatorSymbolValues) {
  EXPECT_EQ(alternator(1, 2, 3), 1);
  EXPECT_EQ(alternator(2, 3, 1), 1);
  EXPECT_EQ(alternator(3, 1, 2), 1);
  EXPECT_EQ(alternator(2, 1, 3), -1);
  EXPECT_EQ(alternator(1, 3, 2), -1);
  EXPECT_EQ(alternator(3, 2, 1), -1);
  int zeros = 0;
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j)
      for (int k = 1; k <= 3; ++k) {
        EXPECT_EQ(alternator(i, j, k), epsilon(i, j, k)) << i << j << k;
        if (i == j || j == k || k == i) {
          EXPECT_EQ(alternator(i, j, k), 0) << i << j << k;
          ++zeros;
        }
      }
  EXPECT_EQ(zeros, 21);
}

// (§A.2) [E_i, E_j, E_k] = ε_ijk, both from triple_product and from a determinant.
TEST(TensorAlgebra, AlternatorFromTripleProductsOfBasis) {
  for (int i = 1; i <= 3; ++i)
    for (int j = 1; j <= 3; ++j)
      for (int k = 1; k <= 3; ++k) {
        const double expected = epsilon(i, j, k);
        EXPECT_EQ(triple_product(basis_vector(i), basis_vector(j), basis_vector(k)), expected)
            << i << j << k;
        EXPECT_EQ(det_columns(E(i), E(j), E(k)), static_cast<double>(alternator(i, j, k)))
            << i << j << k;
      }
}

// (§A.2) [a, b, c] = a · (b × c) equals the determinant of the columns a, b, c, and is cyclic.
TEST(TensorAlgebra, TripleProductIsDeterminant) {
  Random rng(11);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 a = rng.vector(), b = rng.vector(), c = rng.vector();
    const double t = triple_product(a, b, c);
    EXPECT_NEAR(t, det_columns(a, b, c), kTol);
    EXPECT_NEAR(t, triple_product(b, c, a), kTol);
    EXPECT_NEAR(t, -triple_product(b, a, c), kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Tensor product (A.1)

// (A.1) (a⊗b)_ij = a_i b_j, (a⊗b)c = (b·c)a and c(a⊗b) = (a·c)b on random vectors.
TEST(TensorAlgebra, TensorProductActions) {
  Random rng(21);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 a = rng.vector(), b = rng.vector(), c = rng.vector();
    const Tensor ab = tensor_product(a, b);
    EXPECT_LE(max_abs_diff(ab, outer(a, b)), 0.0);
    EXPECT_LE(max_abs_diff(ab * c, b.dot(c) * a), kTol);
    const Vec3 left = (c.transpose() * ab).transpose();
    EXPECT_LE(max_abs_diff(left, a.dot(c) * b), kTol);
  }
}

// (§A.3) (E1⊗E2)E2 = E1 and E2(E1⊗E2) = 0.
TEST(TensorAlgebra, TensorProductBookExample) {
  const Tensor T = tensor_product(basis_vector(1), basis_vector(2));
  EXPECT_EQ(Vec3(T * E(2)), E(1));
  EXPECT_EQ(Vec3((E(2).transpose() * T).transpose()), Vec3::Zero());
}

// (§A.5) (a⊗b)(c⊗d) = (b·c) a⊗d; (§A.6) tr(a⊗b) = a·b and (A.3) (a⊗b)ᵀ = b⊗a.
TEST(TensorAlgebra, TensorProductIdentities) {
  Random rng(22);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 a = rng.vector(), b = rng.vector(), c = rng.vector(), d = rng.vector();
    EXPECT_LE(max_abs_diff(tensor_product(a, b) * tensor_product(c, d), b.dot(c) * outer(a, d)),
              kTol);
    EXPECT_NEAR(tensor_product(a, b).trace(), a.dot(b), kTol);
    EXPECT_LE(max_abs_diff(Tensor(tensor_product(a, b).transpose()), tensor_product(b, a)), 0.0);
  }
}

// (§A.3) bilinearity: (αa + βb)⊗c = α a⊗c + β b⊗c, and likewise in the second slot.
TEST(TensorAlgebra, TensorProductBilinear) {
  Random rng(23);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 a = rng.vector(), b = rng.vector(), c = rng.vector();
    const double alpha = rng.uniform(-2, 2), beta = rng.uniform(-2, 2);
    EXPECT_LE(max_abs_diff(tensor_product(alpha * a + beta * b, c),
                           alpha * tensor_product(a, c) + beta * tensor_product(b, c)),
              kTol);
    EXPECT_LE(max_abs_diff(tensor_product(c, alpha * a + beta * b),
                           alpha * tensor_product(c, a) + beta * tensor_product(c, b)),
              kTol);
  }
}

// (A.1) Exercise: a = E1, b = E2 gives (a⊗b)c = c2 E1 and c(a⊗b) = c1 E2.
TEST(TensorAlgebra, ExerciseA1) {
  const Vec3 c(1.5, -2.25, 3.75);
  const Tensor T = tensor_product(E(1), E(2));
  EXPECT_EQ(Vec3(T * c), Vec3(-2.25, 0.0, 0.0));
  EXPECT_EQ(Vec3((c.transpose() * T).transpose()), Vec3(0.0, 1.5, 0.0));
}

// (A.2) Exercise: (a⊗b − b⊗a)c = c2 E1 − c1 E2 for a = E1, b = E2.
TEST(TensorAlgebra, ExerciseA2) {
  Random rng(24);
  for (int n = 0; n < 100; ++n) {
    const Vec3 c = rng.vector();
    const Tensor T = tensor_product(E(1), E(2)) - tensor_product(E(2), E(1));
    EXPECT_LE(max_abs_diff(T * c, c(1) * E(1) - c(0) * E(2)), 0.0);
  }
}

// Exercise A.5: a = e_r, b = e_θ (cylindrical, at angle θ): (a⊗b)u = e_r (e_θ · u).
TEST(TensorAlgebra, ExerciseA5) {
  Random rng(25);
  for (int n = 0; n < 100; ++n) {
    const double theta = rng.uniform(-3.0, 3.0);
    const Vec3 e_r(std::cos(theta), std::sin(theta), 0),
        e_theta(-std::sin(theta), std::cos(theta), 0);
    const Vec3 u = rng.vector();
    EXPECT_LE(max_abs_diff(tensor_product(e_r, e_theta) * u, e_r * e_theta.dot(u)), 1e-15);
  }
}

// (A.4) Exercise: a = 10E1, b = 5E2 gives (a⊗b)u = 50 E1 (E2·u) and (b⊗a)u = 50 E2 (E1·u).
TEST(TensorAlgebra, ExerciseA4) {
  const Vec3 a = 10.0 * E(1), b = 5.0 * E(2);
  Tensor ab_expected = Tensor::Zero(), ba_expected = Tensor::Zero();
  ab_expected(0, 1) = 50.0;
  ba_expected(1, 0) = 50.0;
  EXPECT_EQ(tensor_product(a, b), ab_expected);
  EXPECT_EQ(tensor_product(b, a), ba_expected);
  const Vec3 u(0.3, -0.7, 1.9);
  EXPECT_LE(max_abs_diff(tensor_product(a, b) * u, 50.0 * E(1) * E(2).dot(u)), kTol);
  EXPECT_LE(max_abs_diff(tensor_product(b, a) * u, 50.0 * E(2) * E(1).dot(u)), kTol);
}

// ---------------------------------------------------------------------------------------------
// The alternator acting on vectors and tensors (A.10), (A.11)

// (A.11) (εc)_ij = ε_ijk c_k by an explicit Σ_k loop; (εc)a = a × c; εc is skew.
TEST(TensorAlgebra, AlternatorTimesVector) {
  Random rng(31);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 c = rng.vector(), a = rng.vector();
    const Tensor ec = alternator_times(c);
    Tensor expected = Tensor::Zero();
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j)
        for (int k = 1; k <= 3; ++k) expected(i - 1, j - 1) += epsilon(i, j, k) * c(k - 1);
    EXPECT_LE(max_abs_diff(ec, expected), 0.0);
    EXPECT_LE(max_abs_diff(ec * a, a.cross(c)), kTol);
    EXPECT_LE(max_abs_diff(Tensor(ec + ec.transpose()), Tensor::Zero()), 0.0);
  }
}

// (A.11) εc = c3(E1⊗E2 − E2⊗E1) + c2(E3⊗E1 − E1⊗E3) + c1(E2⊗E3 − E3⊗E2); εE3 = E1⊗E2 − E2⊗E1.
TEST(TensorAlgebra, AlternatorTimesBasisExpansion) {
  Random rng(32);
  for (int n = 0; n < 100; ++n) {
    const Vec3 c = rng.vector();
    const Tensor expected = c(2) * (outer(E(1), E(2)) - outer(E(2), E(1))) +
                            c(1) * (outer(E(3), E(1)) - outer(E(1), E(3))) +
                            c(0) * (outer(E(2), E(3)) - outer(E(3), E(2)));
    EXPECT_LE(max_abs_diff(alternator_times(c), expected), 0.0);
  }
  EXPECT_EQ(alternator_times(E(3)), Tensor(outer(E(1), E(2)) - outer(E(2), E(1))));
}

// (§A.7) ε(γE1) = γE2⊗E3 − γE3⊗E2 and γE1 × b = (γE3⊗E2 − γE2⊗E3) b.
TEST(TensorAlgebra, AlternatorTimesBookExample) {
  const double gamma = 2.5;
  EXPECT_EQ(alternator_times(gamma * E(1)),
            Tensor(gamma * outer(E(2), E(3)) - gamma * outer(E(3), E(2))));
  const Vec3 b(0.4, -1.3, 0.9);
  EXPECT_LE(max_abs_diff((gamma * E(1)).cross(b),
                         (gamma * outer(E(3), E(2)) - gamma * outer(E(2), E(3))) * b),
            kTol);
  EXPECT_LE(max_abs_diff(skew(gamma * E(1)) * b, (gamma * E(1)).cross(b)), kTol);
}

// (A.10) ε[A]_i = ε_ijk A_jk by an explicit Σ_jk loop on random tensors.
TEST(TensorAlgebra, AlternatorContractTensor) {
  Random rng(33);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    Vec3 expected = Vec3::Zero();
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j)
        for (int k = 1; k <= 3; ++k) expected(i - 1) += epsilon(i, j, k) * A(j - 1, k - 1);
    EXPECT_LE(max_abs_diff(alternator_contract(A), expected), 0.0);
  }
}

// (§A.7) ε[A] = 0 for a symmetric A.
TEST(TensorAlgebra, AlternatorContractSymmetricIsZero) {
  Random rng(34);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor S = random_symmetric(rng);
    EXPECT_EQ(alternator_contract(S), Vec3::Zero());
  }
  EXPECT_EQ(alternator_contract(Tensor::Identity()), Vec3::Zero());
}

// (§A.7, oracle 11) ε[QBQᵀ] = det(Q) Q ε[B] for orthogonal Q: rotations and reflections.
TEST(TensorAlgebra, AlternatorContractUnderOrthogonalChange) {
  Random rng(35);
  Tensor reflection = Tensor::Identity();
  reflection(2, 2) = -1.0;  // E1⊗E1 + E2⊗E2 − E3⊗E3
  for (int n = 0; n < kSamples; ++n) {
    const Tensor B = random_tensor(rng);
    const Tensor R = rng.rotation();
    const Tensor L = R * reflection;  // det L = −1
    EXPECT_LE(max_abs_diff(alternator_contract(R * B * R.transpose()), R * alternator_contract(B)),
              kTol);
    EXPECT_LE(
        max_abs_diff(alternator_contract(L * B * L.transpose()), -(L * alternator_contract(B))),
        kTol);
    const Tensor minus_I = -Tensor::Identity();
    EXPECT_LE(max_abs_diff(alternator_contract(minus_I * B * minus_I.transpose()),
                           -(minus_I * alternator_contract(B))),
              kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Skew tensors and axial vectors (§A.7)

// (§A.7) C = −εc gives Ca = c × a and −½ ε[C] = c.
TEST(TensorAlgebra, SkewAndAxialVector) {
  Random rng(41);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 c = rng.vector(), a = rng.vector();
    const Tensor C = skew(c);
    EXPECT_LE(max_abs_diff(C * a, c.cross(a)), kTol);
    EXPECT_LE(max_abs_diff(C, Tensor(-alternator_times(c))), 0.0);
    EXPECT_LE(max_abs_diff(axial(C), c), kTol);
    EXPECT_LE(max_abs_diff(axial(C), Vec3(-0.5 * alternator_contract(C))), 0.0);
  }
}

// (§A.7) the axial vector of a random skew C satisfies Ca = axial(C) × a, and skew(axial(C)) = C.
TEST(TensorAlgebra, AxialOfRandomSkewTensor) {
  Random rng(42);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor C = random_skew(rng);
    const Vec3 a = rng.vector();
    EXPECT_LE(max_abs_diff(C * a, axial(C).cross(a)), kTol);
    EXPECT_LE(max_abs_diff(skew(axial(C)), C), kTol);
  }
}

// (§A.7) C = c21(E2⊗E1 − E1⊗E2) + c32(E3⊗E2 − E2⊗E3) + c13(E1⊗E3 − E3⊗E1) has
// c = c21 E3 + c13 E2 + c32 E1.
TEST(TensorAlgebra, AxialVectorFromComponents) {
  const double c21 = 0.7, c32 = -1.2, c13 = 2.1;
  const Tensor C = c21 * (outer(E(2), E(1)) - outer(E(1), E(2))) +
                   c32 * (outer(E(3), E(2)) - outer(E(2), E(3))) +
                   c13 * (outer(E(1), E(3)) - outer(E(3), E(1)));
  EXPECT_LE(max_abs_diff(axial(C), Vec3(c32 * E(1) + c13 * E(2) + c21 * E(3))), 0.0);
}

// (A.6) Exercise: −εE3 = E2⊗E1 − E1⊗E2 and E3 × a = (E2⊗E1 − E1⊗E2)a.
TEST(TensorAlgebra, ExerciseA6) {
  Tensor expected;
  expected << 0.0, -1.0, 0.0,  //
      1.0, 0.0, 0.0,           //
      0.0, 0.0, 0.0;
  EXPECT_EQ(Tensor(-alternator_times(basis_vector(3))), expected);
  EXPECT_EQ(skew(basis_vector(3)), expected);
  Random rng(43);
  for (int n = 0; n < 100; ++n) {
    const Vec3 a = rng.vector();
    EXPECT_LE(max_abs_diff(E(3).cross(a), expected * a), 0.0);
    EXPECT_LE(max_abs_diff(skew(E(3)) * a, E(3).cross(a)), 0.0);
  }
}

// (§A.7 example, W2) Ω = Ω(E2⊗E1 − E1⊗E2) gives ε[Ω] = −2ΩE3, axial vector ΩE3.
TEST(TensorAlgebra, AxialVectorBookExample) {
  const double omega = 1.75;
  const Tensor W = omega * (outer(E(2), E(1)) - outer(E(1), E(2)));
  EXPECT_EQ(alternator_contract(W), Vec3(-2.0 * omega * E(3)));
  EXPECT_EQ(axial(W), Vec3(omega * E(3)));
  const Vec3 a(0.2, -0.6, 1.1);
  EXPECT_LE(max_abs_diff(W * a, (omega * E(3)).cross(a)), kTol);
  // Oracle 10: ε[E2⊗E1 − E1⊗E2] = −2E3.
  EXPECT_EQ(alternator_contract(Tensor(outer(E(2), E(1)) - outer(E(1), E(2)))), Vec3(-2.0 * E(3)));
}

// (§A.6) B = ½(B + Bᵀ) + ½(B − Bᵀ): a symmetric plus a skew part.
TEST(TensorAlgebra, SymmetricSkewDecomposition) {
  Random rng(44);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor B = random_tensor(rng);
    const Tensor S = symmetric_part(B), W = skew_part(B);
    EXPECT_LE(max_abs_diff(Tensor(S + W), B), kTol);
    EXPECT_LE(max_abs_diff(S, Tensor(S.transpose())), 0.0);
    EXPECT_LE(max_abs_diff(W, Tensor(-W.transpose())), 0.0);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) EXPECT_NEAR(S(i, j), 0.5 * (B(i, j) + B(j, i)), kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Exercises A.11–A.15

// (A.11) ε[B] = ½ ε[B − Bᵀ].
TEST(TensorAlgebra, ExerciseA11) {
  Random rng(51);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor B = random_tensor(rng);
    EXPECT_LE(max_abs_diff(alternator_contract(B),
                           Vec3(0.5 * alternator_contract(Tensor(B - B.transpose())))),
              kTol);
    EXPECT_LE(max_abs_diff(alternator_contract(B), alternator_contract(skew_part(B))), kTol);
  }
}

// (A.12) −ε[c⊗d] = −½ ε[c⊗d − d⊗c] = d × c.
TEST(TensorAlgebra, ExerciseA12) {
  Random rng(52);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 c = rng.vector(), d = rng.vector();
    const Vec3 lhs = -alternator_contract(tensor_product(c, d));
    const Vec3 mid =
        -0.5 * alternator_contract(Tensor(tensor_product(c, d) - tensor_product(d, c)));
    EXPECT_LE(max_abs_diff(lhs, d.cross(c)), kTol);
    EXPECT_LE(max_abs_diff(mid, d.cross(c)), kTol);
  }
}

// (A.13) For skew A, B with axial vectors a, b: a·b = ½ tr(ABᵀ).
TEST(TensorAlgebra, ExerciseA13) {
  Random rng(53);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_skew(rng), B = random_skew(rng);
    EXPECT_NEAR(axial(A).dot(axial(B)), 0.5 * (A * B.transpose()).trace(), kTol);
    const Vec3 a = rng.vector(), b = rng.vector();
    EXPECT_NEAR(a.dot(b), 0.5 * (skew(a) * skew(b).transpose()).trace(), kTol);
  }
}

// (A.14) For skew A with axial vector a and symmetric C: −½ ε[AC + CA] = (tr(C) I − C) a.
TEST(TensorAlgebra, ExerciseA14) {
  Random rng(54);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 a = rng.vector();
    const Tensor A = skew(a);
    const Tensor C = random_symmetric(rng);
    const Vec3 lhs = -0.5 * alternator_contract(Tensor(A * C + C * A));
    const Vec3 rhs = (C.trace() * Tensor::Identity() - C) * a;
    EXPECT_LE(max_abs_diff(lhs, rhs), kTol);
  }
}

// (A.15) (tr(A) I − Aᵀ)(b × c) = Ab × c + b × Ac.
TEST(TensorAlgebra, ExerciseA15) {
  Random rng(55);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    const Vec3 b = rng.vector(), c = rng.vector();
    const Vec3 lhs = (invariants(A).first * Tensor::Identity() - A.transpose()) * b.cross(c);
    const Vec3 rhs = (A * b).cross(c) + b.cross(A * c);
    EXPECT_LE(max_abs_diff(lhs, rhs), kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Principal invariants and the adjugate (§A.6)

// (§A.6) Triple-product definitions: [Aa,b,c]+[a,Ab,c]+[a,b,Ac] = I_A[a,b,c], etc.
TEST(TensorAlgebra, InvariantsFromTripleProducts) {
  Random rng(61);
  double worst = 0.0;
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    const Vec3 a = rng.vector(), b = rng.vector(), c = rng.vector();
    const Vec3 Aa = A * a, Ab = A * b, Ac = A * c;
    const double abc = triple(a, b, c);
    const Invariants inv = invariants(A);
    const double first = triple(Aa, b, c) + triple(a, Ab, c) + triple(a, b, Ac);
    const double second = triple(a, Ab, Ac) + triple(Aa, b, Ac) + triple(Aa, Ab, c);
    const double third = triple(Aa, Ab, Ac);
    // Every term is a sum of products of at most six O(1) factors bounded by 3⁶ in size; 1e-12
    // still leaves a wide margin over the ~1e-14 round-off seen for such sums.
    EXPECT_NEAR(inv.first * abc, first, 1e-12);
    EXPECT_NEAR(inv.second * abc, second, 1e-12);
    EXPECT_NEAR(inv.third * abc, third, 1e-12);
    worst = std::max(worst, std::abs(inv.second * abc - second));
  }
  RecordProperty("worst_second_invariant_residual", std::to_string(worst));
}

// (A.6) I_A = A11 + A22 + A33, II_A = ½((tr A)² − tr A²) and (A.7) III_A = Σ ε_ijk A_i1 A_j2 A_k3.
TEST(TensorAlgebra, InvariantsComponentFormulas) {
  Random rng(62);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    const Invariants inv = invariants(A);
    double det = 0.0;
    for (int i = 1; i <= 3; ++i)
      for (int j = 1; j <= 3; ++j)
        for (int k = 1; k <= 3; ++k)
          det += epsilon(i, j, k) * A(i - 1, 0) * A(j - 1, 1) * A(k - 1, 2);
    // II as the sum of the principal 2×2 minors.
    const double minors = A(0, 0) * A(1, 1) - A(0, 1) * A(1, 0) + A(1, 1) * A(2, 2) -
                          A(1, 2) * A(2, 1) + A(0, 0) * A(2, 2) - A(0, 2) * A(2, 0);
    EXPECT_NEAR(inv.first, A(0, 0) + A(1, 1) + A(2, 2), kTol);
    EXPECT_NEAR(inv.second, minors, kTol);
    EXPECT_NEAR(inv.third, det, kTol);
  }
}

// (§A.6) For symmetric A with eigenvalues λ_i: I = Σλ_i, II = λ1λ2 + λ2λ3 + λ3λ1, III = λ1λ2λ3,
// and λ³ − Iλ² + IIλ − III vanishes at each λ_i.
TEST(TensorAlgebra, InvariantsFromEigenvalues) {
  Random rng(63);
  for (int n = 0; n < kSamples; ++n) {
    const Vec3 l = rng.vector(2.0);
    const Tensor A = with_spectrum(rng.rotation(), l);
    const Invariants inv = invariants(A);
    // Entries and eigenvalues are at most 2 in size, so the cubic terms are at most 8 and their
    // round-off well below 1e-13 · 8.
    const double tol = 8.0 * kTol;
    EXPECT_NEAR(inv.first, l.sum(), tol);
    EXPECT_NEAR(inv.second, l(0) * l(1) + l(1) * l(2) + l(2) * l(0), tol);
    EXPECT_NEAR(inv.third, l.prod(), tol);
    for (int i = 0; i < 3; ++i) {
      const double x = l(i);
      EXPECT_NEAR(x * x * x - inv.first * x * x + inv.second * x - inv.third, 0.0, 8.0 * tol);
    }
  }
}

// (§A.6) Invariants are unchanged by a change of basis: A ↦ QAQᵀ.
TEST(TensorAlgebra, InvariantsAreBasisIndependent) {
  Random rng(64);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng), Q = rng.rotation();
    const Invariants a = invariants(A), b = invariants(Q * A * Q.transpose());
    EXPECT_NEAR(a.first, b.first, kTol);
    EXPECT_NEAR(a.second, b.second, kTol);
    EXPECT_NEAR(a.third, b.third, kTol);
  }
}

// (§A.6) A*(a × b) = Aa × Ab for random A, and A* is the cofactor matrix.
TEST(TensorAlgebra, AdjugateCrossProductRule) {
  Random rng(71);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    const Vec3 a = rng.vector(), b = rng.vector();
    const Tensor adj = adjugate(A);
    EXPECT_LE(max_abs_diff(adj * a.cross(b), (A * a).cross(A * b)), kTol);
    EXPECT_LE(max_abs_diff(adj, cofactor(A)), kTol);
  }
}

// (§A.6) The adjugate exists for a singular (rank-2) A: A*(a × b) = Aa × Ab and A*ᵀA = 0.
TEST(TensorAlgebra, AdjugateOfSingularTensor) {
  Random rng(72);
  for (int n = 0; n < kSamples; ++n) {
    // Rank 2: A = u⊗v + w⊗x.
    const Vec3 u = rng.vector(), v = rng.vector(), w = rng.vector(), x = rng.vector();
    const Tensor A = outer(u, v) + outer(w, x);
    const Vec3 a = rng.vector(), b = rng.vector();
    const Tensor adj = adjugate(A);
    EXPECT_LE(max_abs_diff(adj * a.cross(b), (A * a).cross(A * b)), kTol);
    EXPECT_LE(max_abs_diff(adj, cofactor(A)), kTol);
    // A*ᵀ A = det(A) I = 0, while A* itself is rank one and nonzero: A* = (u × w) ⊗ (v × x).
    EXPECT_LE(max_abs_diff(Tensor(adj.transpose() * A), Tensor::Zero()), kTol);
    EXPECT_LE(max_abs_diff(adj, outer(u.cross(w), v.cross(x))), kTol);
  }
}

// (§A.6) A* = det(A) A⁻ᵀ for invertible A, checked as A*ᵀA = AA*ᵀ = det(A) I.
TEST(TensorAlgebra, AdjugateOfInvertibleTensor) {
  Random rng(73);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    const double det = A.determinant();
    const Tensor adj = adjugate(A);
    EXPECT_LE(max_abs_diff(Tensor(adj.transpose() * A), Tensor(det * Tensor::Identity())), kTol);
    EXPECT_LE(max_abs_diff(Tensor(A * adj.transpose()), Tensor(det * Tensor::Identity())), kTol);
    if (std::abs(det) > 0.1) {
      // Error of the inverse grows like the condition number; |det| > 0.1 keeps it modest.
      const Tensor expected = det * A.inverse().transpose();
      EXPECT_LE(max_abs_diff(adj, expected), 1e-12);
    }
  }
  // Closed form: adjugate of diag(a, b, c) is diag(bc, ca, ab).
  const Tensor D = Vec3(2.0, 3.0, 5.0).asDiagonal();
  EXPECT_EQ(adjugate(D), Tensor(Vec3(15.0, 10.0, 6.0).asDiagonal()));
  // A rotation is its own adjugate: Q* = det(Q) Q⁻ᵀ = Q.
  const Tensor Q = Random(74).rotation();
  EXPECT_LE(max_abs_diff(adjugate(Q), Q), kTol);
}

// ---------------------------------------------------------------------------------------------
// Spectral decomposition (§A.8)

// (§A.8) A = Σ λ_i u_i⊗u_i with orthonormal right-handed u_i and ascending λ_i.
TEST(TensorAlgebra, SpectralDecompositionOfRandomSymmetric) {
  Random rng(81);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_symmetric(rng);  // entries at most 2 in size
    const SpectralDecomposition s = spectral_decomposition(A);
    const Tensor& U = s.vectors;
    EXPECT_LE(s.values(0), s.values(1));
    EXPECT_LE(s.values(1), s.values(2));
    EXPECT_LE(max_abs_diff(Tensor(U.transpose() * U), Tensor::Identity()), kTol);
    EXPECT_GT(det_columns(U.col(0), U.col(1), U.col(2)), 0.0);
    EXPECT_NEAR(det_columns(U.col(0), U.col(1), U.col(2)), 1.0, kTol);
    Tensor sum = Tensor::Zero();
    for (int i = 0; i < 3; ++i) {
      const Vec3 u = U.col(i);
      sum += s.values(i) * outer(u, u);
      EXPECT_LE(max_abs_diff(Vec3(A * u), Vec3(s.values(i) * u)), 1e-12);
    }
    // Eigen-solver backward error is a few ulps of ‖A‖ ≤ 6.
    EXPECT_LE(max_abs_diff(sum, A), 1e-12);
  }
}

// (§A.8) Eigenvalues of Q diag(λ) Qᵀ are the λ sorted ascending, and u_i = ±Q e_i.
TEST(TensorAlgebra, SpectralDecompositionKnownSpectrum) {
  Random rng(82);
  const Vec3 lambda(-1.5, 0.25, 3.0);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q = rng.rotation();
    // Pass the eigenvalues in a scrambled order; the result must still be ascending.
    const Tensor A = with_spectrum(Q, Vec3(lambda(2), lambda(0), lambda(1)));
    const SpectralDecomposition s = spectral_decomposition(A);
    EXPECT_LE(max_abs_diff(s.values, lambda), 1e-13 * 3.0);
    const std::array<int, 3> column_of{1, 2, 0};  // λ_i sits in column column_of[i] of Q
    for (int i = 0; i < 3; ++i) {
      const Vec3 q = Q.col(column_of[static_cast<std::size_t>(i)]);
      // Eigenvalue gaps are ≥ 1.75, so the eigenvectors are determined to ~1e-15.
      EXPECT_NEAR(std::abs(s.vectors.col(i).dot(q)), 1.0, 1e-13);
    }
  }
}

// (§A.6 example, W7) J0 = diag(ma²/12, mb²/12, mc²/12) has those eigenvalues with E1, E2, E3.
TEST(TensorAlgebra, SpectralDecompositionInertiaExample) {
  const double m = 2.0, a = 3.0, b = 1.0, c = 2.0;
  const Tensor J0 = (m * a * a / 12) * outer(E(1), E(1)) + (m * b * b / 12) * outer(E(2), E(2)) +
                    (m * c * c / 12) * outer(E(3), E(3));
  const SpectralDecomposition s = spectral_decomposition(J0);
  // Ascending: mb²/12 = 1/6, mc²/12 = 2/3, ma²/12 = 3/2, along E2, E3, E1.
  EXPECT_NEAR(s.values(0), m * b * b / 12, kTol);
  EXPECT_NEAR(s.values(1), m * c * c / 12, kTol);
  EXPECT_NEAR(s.values(2), m * a * a / 12, kTol);
  EXPECT_NEAR(std::abs(s.vectors.col(0).dot(E(2))), 1.0, kTol);
  EXPECT_NEAR(std::abs(s.vectors.col(1).dot(E(3))), 1.0, kTol);
  EXPECT_NEAR(std::abs(s.vectors.col(2).dot(E(1))), 1.0, kTol);
  EXPECT_NEAR(s.vectors.determinant(), 1.0, kTol);
  EXPECT_TRUE(is_positive_definite(J0));
}

// (§A.8) Repeated eigenvalues: the eigenvectors still form a right-handed orthonormal basis that
// reproduces A; the simple eigenvalue keeps its direction.
TEST(TensorAlgebra, SpectralDecompositionRepeatedEigenvalues) {
  Random rng(83);
  for (int n = 0; n < 200; ++n) {
    const Tensor Q = rng.rotation();
    for (const Vec3& lambda : {Vec3(2.0, 2.0, 5.0), Vec3(-1.0, 4.0, 4.0), Vec3(3.0, 3.0, 3.0)}) {
      const Tensor A = with_spectrum(Q, lambda);
      const SpectralDecomposition s = spectral_decomposition(A);
      const Tensor& U = s.vectors;
      EXPECT_LE(max_abs_diff(s.values, lambda), 5.0 * kTol);
      EXPECT_LE(max_abs_diff(Tensor(U.transpose() * U), Tensor::Identity()), kTol);
      EXPECT_NEAR(U.determinant(), 1.0, kTol);
      EXPECT_LE(max_abs_diff(Tensor(U * s.values.asDiagonal() * U.transpose()), A), 5.0 * kTol);
    }
    // The simple eigenvalue 5 of diag(2, 2, 5) has eigenvector ±Q E3.
    const SpectralDecomposition s = spectral_decomposition(with_spectrum(Q, Vec3(2.0, 2.0, 5.0)));
    EXPECT_NEAR(std::abs(s.vectors.col(2).dot(Q.col(2))), 1.0, kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Positive definiteness (§A.6, §A.8)

// (§A.8) Aa·a > 0 for a ≠ 0: positive, semidefinite and indefinite tensors.
TEST(TensorAlgebra, PositiveDefiniteness) {
  Random rng(91);
  for (int n = 0; n < 200; ++n) {
    const Tensor Q = rng.rotation();
    EXPECT_TRUE(is_positive_definite(with_spectrum(Q, Vec3(0.5, 1.0, 7.0))));
    EXPECT_TRUE(is_positive_definite(with_spectrum(Q, Vec3(1e-3, 1.0, 2.0)), 1e-12));
    EXPECT_FALSE(is_positive_definite(with_spectrum(Q, Vec3(-0.5, 1.0, 7.0))));
    EXPECT_FALSE(is_positive_definite(with_spectrum(Q, Vec3(-3.0, -2.0, -1.0))));
    // Semidefinite: a zero eigenvalue computed as round-off of ‖A‖ ≈ 1e-16 must fall below the
    // relative tolerance.
    EXPECT_FALSE(is_positive_definite(with_spectrum(Q, Vec3(0.0, 1.0, 2.0)), 1e-12));
    // A nonsymmetric tensor is judged by its symmetric part: S + W with W skew.
    const Tensor S = with_spectrum(Q, Vec3(0.5, 1.0, 7.0));
    const Tensor W = 10.0 * skew(rng.unit_vector());
    EXPECT_TRUE(is_positive_definite(Tensor(S + W)));
    const Vec3 a = rng.vector();
    EXPECT_GT(a.dot((S + W) * a), 0.0);
  }
  // Exact semidefinite and zero tensors.
  EXPECT_FALSE(is_positive_definite(Tensor(Vec3(0.0, 1.0, 2.0).asDiagonal())));
  EXPECT_FALSE(is_positive_definite(Tensor::Zero()));
  EXPECT_TRUE(is_positive_definite(Tensor::Identity()));
  // A tensor whose smallest eigenvalue is below the relative tolerance is rejected.
  EXPECT_FALSE(is_positive_definite(Tensor(Vec3(1e-9, 1.0, 2.0).asDiagonal()), 1e-6));
  EXPECT_TRUE(is_positive_definite(Tensor(Vec3(1e-9, 1.0, 2.0).asDiagonal())));
}

// (§A.8) Positive definiteness does not depend on the scale of A: the tolerance is relative to
// the largest eigenvalue.
TEST(TensorAlgebra, PositiveDefinitenessIsScaleInvariant) {
  Random rng(93);
  for (int n = 0; n < 200; ++n) {
    const Tensor Q = rng.rotation();
    const Tensor A = with_spectrum(Q, Vec3(1e-3, 1.0, 2.0));  // λ_min/λ_max = 5e-4
    const Tensor B = with_spectrum(Q, Vec3(1e-8, 1.0, 2.0));  // λ_min/λ_max = 5e-9
    for (const double scale : {1e-8, 1.0, 1e8}) {
      EXPECT_TRUE(is_positive_definite(Tensor(scale * A), 1e-6)) << "scale " << scale;
      EXPECT_FALSE(is_positive_definite(Tensor(scale * B), 1e-6)) << "scale " << scale;
    }
  }
}

// (§A.8) A skew tensor cannot be positive definite: Wa·a = 0.
TEST(TensorAlgebra, SkewTensorIsNotPositiveDefinite) {
  Random rng(92);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor W = random_skew(rng);
    EXPECT_FALSE(is_positive_definite(W));
    EXPECT_FALSE(is_positive_definite(W, 1e-12));
    const Vec3 a = rng.vector();
    EXPECT_NEAR(a.dot(W * a), 0.0, kTol);
  }
}

// ---------------------------------------------------------------------------------------------
// Rotations and orthogonal tensors (§A.8)

// (§A.8) Random rotations pass; I passes; the reflection E1⊗E1 + E2⊗E2 − E3⊗E3 and −I fail.
TEST(TensorAlgebra, IsRotation) {
  Random rng(101);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q = rng.rotation();
    EXPECT_TRUE(is_rotation(Q));
    EXPECT_LE(rotation_defect(Q), 1e-14);
    // Q times the reflection is orthogonal but improper.
    Tensor reflected = Q;
    reflected.col(2) = -reflected.col(2);
    EXPECT_FALSE(is_rotation(reflected));
    EXPECT_NEAR(rotation_defect(reflected), 2.0, 1e-14);
  }
  EXPECT_TRUE(is_rotation(Tensor::Identity()));
  EXPECT_EQ(rotation_defect(Tensor::Identity()), 0.0);
  const Tensor reflection = outer(E(1), E(1)) + outer(E(2), E(2)) - outer(E(3), E(3));
  EXPECT_FALSE(is_rotation(reflection));
  EXPECT_EQ(rotation_defect(reflection), 2.0);  // orthogonal, det − 1 = −2
  EXPECT_FALSE(is_rotation(Tensor(-Tensor::Identity())));
  EXPECT_EQ(rotation_defect(Tensor(-Tensor::Identity())), 2.0);
  Tensor nan = Tensor::Identity();
  nan(0, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(is_rotation(nan));
}

// (§A.8) A slightly perturbed rotation is rejected, with the defect of the perturbation.
TEST(TensorAlgebra, RotationDefectOfPerturbedMatrix) {
  // diag(1, 1, 1 + δ): QᵀQ − I = diag(0, 0, 2δ + δ²) and det − 1 = δ, so the defect is 2δ + δ².
  for (const double delta : {1e-3, 1e-6, 1e-9}) {
    Tensor P = Tensor::Identity();
    P(2, 2) += delta;
    EXPECT_NEAR(rotation_defect(P), 2 * delta + delta * delta, 1e-15);
    EXPECT_FALSE(is_rotation(P));
    EXPECT_TRUE(is_rotation(P, 3 * delta));
  }
  Random rng(102);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q = rng.rotation();
    EXPECT_FALSE(is_rotation(Tensor(Q + 1e-6 * outer(rng.unit_vector(), rng.unit_vector()))));
    EXPECT_FALSE(is_rotation(Tensor(1.001 * Q)));
    // (1 + s)Q: QᵀQ − I = (2s + s²) I and det − 1 = (1 + s)³ − 1 = 3s + 3s² + s³.
    const double s = 1e-4;
    EXPECT_NEAR(rotation_defect(Tensor((1 + s) * Q)), 3 * s + 3 * s * s + s * s * s, 1e-14);
  }
}

// (§A.8) The nearest rotation to a rotation is itself.
TEST(TensorAlgebra, NearestRotationOfRotationIsIdentityMap) {
  Random rng(111);
  double worst = 0.0;
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q = rng.rotation();
    const double diff = max_abs_diff(nearest_rotation(Q), Q);
    EXPECT_LE(diff, 1e-14);
    worst = std::max(worst, diff);
  }
  RecordProperty("worst_rotation_change", std::to_string(worst));
  EXPECT_LE(max_abs_diff(nearest_rotation(Tensor::Identity()), Tensor::Identity()), 1e-15);
}

// (§A.8) A = Q1 diag(s) Q2ᵀ with s1 > s2 > |s3| has nearest rotation Q1 Q2ᵀ whatever the sign of
// s3, so a matrix with negative determinant still gives det +1.
TEST(TensorAlgebra, NearestRotationClosedForm) {
  Random rng(112);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q1 = rng.rotation(), Q2 = rng.rotation();
    const Tensor expected = Q1 * Q2.transpose();
    for (const Vec3& s : {Vec3(3.0, 2.0, 0.5), Vec3(3.0, 2.0, -0.5), Vec3(1.0, 0.8, -0.2)}) {
      const Tensor A = Q1 * s.asDiagonal() * Q2.transpose();
      const Tensor R = nearest_rotation(A);
      // Sensitivity of the rotation factor is 1/(s2 ± s3) ≤ 1/0.6; round-off in A is ~1e-15.
      EXPECT_LE(max_abs_diff(R, expected), kTol) << "s = " << s.transpose();
      EXPECT_TRUE(is_rotation(R));
      EXPECT_NEAR(R.determinant(), 1.0, kTol);
    }
  }
}

// (§A.8) A perturbed rotation Q + ΔA is fixed to within the size of the perturbation, and the
// result beats nearby rotations in the Frobenius distance.
TEST(TensorAlgebra, NearestRotationOfPerturbedRotation) {
  Random rng(113);
  for (int n = 0; n < kSamples; ++n) {
    const Tensor Q = rng.rotation();
    const Tensor dA = random_tensor(rng, 1e-4);
    const Tensor A = Q + dA;
    const Tensor R = nearest_rotation(A);
    EXPECT_TRUE(is_rotation(R));
    // The polar factor of A = Q + ΔA moves by at most ‖ΔA‖_F (all singular values of Q are 1).
    EXPECT_LE((R - Q).norm(), dA.norm() + kTol);
    // Polar decomposition: RᵀA is symmetric positive definite.
    const Tensor S = R.transpose() * A;
    EXPECT_LE(max_abs_diff(S, Tensor(S.transpose())), kTol);
    EXPECT_TRUE(is_positive_definite(S));
    // Minimality: no nearby rotation is closer to A.
    const double best = (A - R).norm();
    for (int m = 0; m < 5; ++m) {
      const Tensor other = small_rotation(rng, 1e-3) * R;
      EXPECT_LT(best, (A - other).norm());
    }
  }
}

// (§A.8) For a general matrix (any determinant sign), the result is a rotation, RᵀA is symmetric,
// and no random rotation is closer.
TEST(TensorAlgebra, NearestRotationOfGeneralMatrix) {
  Random rng(114);
  int negative = 0;
  for (int n = 0; n < kSamples; ++n) {
    const Tensor A = random_tensor(rng);
    if (A.determinant() < 0.0) ++negative;
    const Tensor R = nearest_rotation(A);
    EXPECT_TRUE(is_rotation(R));
    EXPECT_NEAR(R.determinant(), 1.0, kTol);
    const Tensor S = R.transpose() * A;
    EXPECT_LE(max_abs_diff(S, Tensor(S.transpose())), 1e-12);
    const double best = (A - R).norm();
    for (int m = 0; m < 5; ++m) EXPECT_LE(best, (A - rng.rotation()).norm() + kTol);
    for (int m = 0; m < 5; ++m) EXPECT_LE(best, (A - small_rotation(rng, 1e-3) * R).norm() + kTol);
  }
  EXPECT_GT(negative, kSamples / 4);  // both signs of the determinant were exercised
}

// ---------------------------------------------------------------------------------------------
// Basis changes of Exercises A.7–A.9 (oracle 22)

// (A.7) Cylindrical basis: P = cθ(E1⊗E1 + E2⊗E2) + sθ(E2⊗E1 − E1⊗E2) + E3⊗E3
// = cθ(I − E3⊗E3) − sθ εE3 + E3⊗E3 = e_r⊗E1 + e_θ⊗E2 + e_z⊗E3 is proper orthogonal.
TEST(TensorAlgebra, ExerciseA7CylindricalBasisIsRotation) {
  Random rng(121);
  for (int n = 0; n < 200; ++n) {
    const double theta = rng.uniform(-test::kPi, test::kPi);
    const double c = std::cos(theta), s = std::sin(theta);
    const Vec3 er(c, s, 0.0), et(-s, c, 0.0), ez(0.0, 0.0, 1.0);
    const Tensor P1 = c * (outer(E(1), E(1)) + outer(E(2), E(2))) +
                      s * (outer(E(2), E(1)) - outer(E(1), E(2))) + outer(E(3), E(3));
    const Tensor P2 = c * (Tensor::Identity() - tensor_product(E(3), E(3))) -
                      s * alternator_times(E(3)) + tensor_product(E(3), E(3));
    const Tensor P3 = outer(er, E(1)) + outer(et, E(2)) + outer(ez, E(3));
    EXPECT_LE(max_abs_diff(P1, P2), kTol);
    EXPECT_LE(max_abs_diff(P1, P3), kTol);
    EXPECT_LE(max_abs_diff(Vec3(P1 * E(1)), er), kTol);
    EXPECT_LE(max_abs_diff(Vec3(P1 * E(2)), et), kTol);
    EXPECT_LE(max_abs_diff(Vec3(P1 * E(3)), ez), kTol);
    EXPECT_LE(max_abs_diff(Tensor(P1.transpose() * P1), Tensor::Identity()), kTol);
    EXPECT_NEAR(det_columns(er, et, ez), 1.0, kTol);
    EXPECT_TRUE(is_rotation(P1));
    EXPECT_TRUE(is_rotation(P2));
    EXPECT_LE(max_abs_diff(nearest_rotation(P1), P1), 1e-14);
  }
}

// (A.8, A.9) Spherical basis: R = e_R⊗E3 + e_φ⊗E1 + e_θ⊗E2 is proper orthogonal.
TEST(TensorAlgebra, ExerciseA8SphericalBasisIsRotation) {
  Random rng(122);
  for (int n = 0; n < 200; ++n) {
    const double theta = rng.uniform(-test::kPi, test::kPi), phi = rng.uniform(0.0, test::kPi);
    const double ct = std::cos(theta), st = std::sin(theta), cp = std::cos(phi), sp = std::sin(phi);
    const Vec3 eR(ct * sp, st * sp, cp), ephi(ct * cp, st * cp, -sp), etheta(-st, ct, 0.0);
    const Tensor R =
        tensor_product(eR, E(3)) + tensor_product(ephi, E(1)) + tensor_product(etheta, E(2));
    EXPECT_LE(max_abs_diff(Vec3(R * E(3)), eR), kTol);
    EXPECT_LE(max_abs_diff(Vec3(R * E(1)), ephi), kTol);
    EXPECT_LE(max_abs_diff(Vec3(R * E(2)), etheta), kTol);
    EXPECT_LE(max_abs_diff(Tensor(R.transpose() * R), Tensor::Identity()), kTol);
    // [e_φ, e_θ, e_R] = +1: the images of E1, E2, E3 form a right-handed basis.
    EXPECT_NEAR(det_columns(ephi, etheta, eR), 1.0, kTol);
    EXPECT_TRUE(is_rotation(R));
    EXPECT_NEAR(invariants(R).third, 1.0, kTol);
  }
}

}  // namespace
}  // namespace unidyn
