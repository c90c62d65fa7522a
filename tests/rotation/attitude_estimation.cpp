// Attitude from vector observations: Wahba's problem (d = 0) and Horn's (d free), book eq. (6.37).
#include "unidyn/rotation/attitude_estimation.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "support/eigen_solvers.hpp"
#include "support/oracles.hpp"

namespace unidyn {
namespace {

using test::book_L;

using Observations = std::vector<VectorObservation>;

// (6.36) in components: (e0² − e·e) I + 2 e⊗e + 2 e0 [e]×, [e]× a = e × a (i.e. −2 e0 εe).
Tensor quaternion_rotation(double e0, const Vec3& e) {
  const double e1 = e(0), e2 = e(1), e3 = e(2);
  const double d = e0 * e0 - e1 * e1 - e2 * e2 - e3 * e3;
  Tensor R;
  R << d + 2 * e1 * e1, 2 * e1 * e2 - 2 * e0 * e3, 2 * e1 * e3 + 2 * e0 * e2,  //
      2 * e2 * e1 + 2 * e0 * e3, d + 2 * e2 * e2, 2 * e2 * e3 - 2 * e0 * e1,   //
      2 * e3 * e1 - 2 * e0 * e2, 2 * e3 * e2 + 2 * e0 * e1, d + 2 * e3 * e3;
  return R;
}

// (6.37) W = ½ Σ α_K ‖b_K − Q a_K − d‖², typed here.
double loss(const Observations& obs, const Tensor& Q, const Vec3& d) {
  double w = 0.0;
  for (const auto& o : obs) w += 0.5 * o.weight * (o.observed - Q * o.reference - d).squaredNorm();
  return w;
}

// Davenport's q-method, written independently of the SVD solution. With B = Σ α b⊗a and the
// rotation (6.36) of p = (e0, e), tr(Qᵀ B) = pᵀ K p with
//   K = [[σ, zᵀ], [z, B + Bᵀ − σ I]],  σ = tr B,  z = (B32 − B23, B13 − B31, B21 − B12),
// and W = const − tr(Qᵀ B) is least at the unit eigenvector of K's largest eigenvalue.
// With d free (Horn), the vectors are centred at their weighted means first and d = b̄ − Q ā.
struct Solution {
  Tensor rotation;
  Vec3 translation;
};
Solution davenport(const Observations& obs, bool with_translation) {
  Vec3 a_mean = Vec3::Zero(), b_mean = Vec3::Zero();
  double total = 0.0;
  for (const auto& o : obs) {
    a_mean += o.weight * o.reference;
    b_mean += o.weight * o.observed;
    total += o.weight;
  }
  a_mean /= total;
  b_mean /= total;
  if (!with_translation) a_mean = b_mean = Vec3::Zero();
  Tensor B = Tensor::Zero();
  for (const auto& o : obs)
    B += o.weight * (o.observed - b_mean) * (o.reference - a_mean).transpose();
  const double sigma = B.trace();
  const Vec3 z(B(2, 1) - B(1, 2), B(0, 2) - B(2, 0), B(1, 0) - B(0, 1));
  Eigen::Matrix4d K;
  K(0, 0) = sigma;
  K.block<3, 1>(1, 0) = z;
  K.block<1, 3>(0, 1) = z.transpose();
  K.block<3, 3>(1, 1) = B + B.transpose() - sigma * Tensor::Identity();
  const test::SymmetricEigen solver = test::symmetric_eigen(K);
  const Eigen::Vector4d p = solver.eigenvectors().col(3);  // eigenvalues ascend
  const Tensor Q = quaternion_rotation(p(0), p.tail<3>());
  return {Q, b_mean - Q * a_mean};
}

// N observations b = Q a + d + noise with random positive weights.
Observations simulate(test::Random& rng, int count, const Tensor& Q, const Vec3& d, double noise) {
  Observations obs;
  for (int k = 0; k < count; ++k) {
    const Vec3 a = rng.vector(2.0);
    obs.push_back({a, Q * a + d + rng.vector(noise), rng.uniform(0.1, 5.0)});
  }
  return obs;
}

void expect_rotation(const Tensor& Q) {
  EXPECT_LT(test::max_abs_diff(Tensor(Q.transpose() * Q), Tensor::Identity()), 1e-14);
  EXPECT_NEAR(Q.determinant(), 1.0, 1e-14);
}

// (6.37) noise-free: the generating rotation and translation are recovered, W ≈ 0.
TEST(AttitudeEstimation, NoiseFreeRecovery637) {
  test::Random rng(401);
  for (int n = 0; n < 500; ++n) {
    const bool with_translation = n % 2 == 1;
    const Tensor Q = rng.rotation();
    const Vec3 d = with_translation ? rng.vector(5.0) : Vec3::Zero();
    // With d free, two observations leave the rotation about a_2 − a_1 undetermined: use three.
    const int count = static_cast<int>(rng.uniform(with_translation ? 3.0 : 2.0, 12.0));
    const Observations obs = simulate(rng, count, Q, d, 0.0);
    const AttitudeEstimate est = estimate_attitude(obs, with_translation);
    SCOPED_TRACE(testing::Message() << "n = " << n << ", N = " << count);
    expect_rotation(est.rotation);
    EXPECT_LT(test::max_abs_diff(est.rotation, Q), 1e-12);
    EXPECT_LT(test::max_abs_diff(est.translation, d), 1e-12);
    EXPECT_LT(est.loss, 1e-24);
    EXPECT_NEAR(est.loss, loss(obs, est.rotation, est.translation), 1e-24);
  }
}

// (6.37) with noise: the estimate equals Davenport's q-method (Horn's centring for d).
TEST(AttitudeEstimation, NoisyAgreesWithDavenport637) {
  test::Random rng(402);
  for (int n = 0; n < 500; ++n) {
    const bool with_translation = n % 2 == 1;
    const Tensor Q = rng.rotation();
    const Vec3 d = with_translation ? rng.vector(5.0) : Vec3::Zero();
    const int count = static_cast<int>(rng.uniform(with_translation ? 3.0 : 2.0, 12.0));
    const double noise = rng.uniform(0.001, 0.2);
    const Observations obs = simulate(rng, count, Q, d, noise);
    const AttitudeEstimate est = estimate_attitude(obs, with_translation);
    const Solution ref = davenport(obs, with_translation);
    SCOPED_TRACE(testing::Message() << "n = " << n << ", N = " << count << ", noise " << noise);
    expect_rotation(est.rotation);
    EXPECT_LT(test::max_abs_diff(est.rotation, ref.rotation), 1e-10);
    EXPECT_LT(test::max_abs_diff(est.translation, ref.translation), 1e-10);
    if (!with_translation) {
      EXPECT_EQ(est.translation, Vec3::Zero());
    }
    const double W = loss(obs, est.rotation, est.translation);
    EXPECT_NEAR(est.loss, W, 1e-13 * (1.0 + W));
    EXPECT_GT(W, 0.0);
  }
}

// (6.37) local optimality: small turns L(δ, r) of Q (and shifts of d) never lower W.
TEST(AttitudeEstimation, LossDoesNotDecreaseUnderPerturbation637) {
  // The increase is O(δ²) ≥ ~1e-8 W for δ ≥ 1e-4, far above round-off ~1e-16 W.
  test::Random rng(403);
  for (int n = 0; n < 100; ++n) {
    const bool with_translation = n % 2 == 1;
    const Tensor Q = rng.rotation();
    const Vec3 d = with_translation ? rng.vector(5.0) : Vec3::Zero();
    const int count = static_cast<int>(rng.uniform(with_translation ? 3.0 : 2.0, 12.0));
    const Observations obs = simulate(rng, count, Q, d, rng.uniform(0.01, 0.3));
    const AttitudeEstimate est = estimate_attitude(obs, with_translation);
    const double W = loss(obs, est.rotation, est.translation);
    for (int k = 0; k < 50; ++k) {
      const double delta = rng.uniform(1e-4, 1e-2);
      const Tensor turned = book_L(delta, rng.unit_vector()) * est.rotation;
      const Vec3 shifted =
          with_translation ? Vec3(est.translation + rng.vector(1e-3)) : Vec3::Zero();
      EXPECT_GE(loss(obs, turned, shifted), W - 1e-14 * (1.0 + W)) << "n = " << n << ", k = " << k;
      EXPECT_GE(loss(obs, turned, est.translation), W - 1e-14 * (1.0 + W));
    }
  }
}

// (6.37): Wahba's problem needs only N = 2 non-parallel observations.
TEST(AttitudeEstimation, TwoObservationsSuffice) {
  test::Random rng(404);
  for (int n = 0; n < 500; ++n) {
    const Tensor Q = rng.rotation();
    const Observations exact = simulate(rng, 2, Q, Vec3::Zero(), 0.0);
    const AttitudeEstimate est = estimate_attitude(exact, false);
    expect_rotation(est.rotation);
    EXPECT_LT(test::max_abs_diff(est.rotation, Q), 1e-12) << "n = " << n;
    const Observations noisy = simulate(rng, 2, Q, Vec3::Zero(), 0.05);
    EXPECT_LT(test::max_abs_diff(estimate_attitude(noisy, false).rotation,
                                 davenport(noisy, false).rotation),
              1e-10)
        << "n = " << n;
  }
}

// (6.37) is over rotations: coplanar or mirrored data still give det = +1.
TEST(AttitudeEstimation, PlanarAndMirroredDataGiveProperRotation) {
  // Coplanar references make B singular; mirrored data make the best orthogonal tensor improper.
  // Davenport's solution is a rotation by construction.
  test::Random rng(405);
  for (int n = 0; n < 500; ++n) {
    const bool with_translation = n % 2 == 1;
    const Tensor Q = rng.rotation();
    const Vec3 d = with_translation ? rng.vector(5.0) : Vec3::Zero();
    // References in a random plane through the origin (through a random point when d is free).
    const Vec3 normal = rng.unit_vector();
    const Vec3 u = normal.unitOrthogonal(), v = normal.cross(u);
    const Vec3 origin = with_translation ? rng.vector(2.0) : Vec3::Zero();
    Observations exact, noisy;
    const int count = static_cast<int>(rng.uniform(3.0, 10.0));
    for (int k = 0; k < count; ++k) {
      const Vec3 a = origin + rng.uniform(-2, 2) * u + rng.uniform(-2, 2) * v;
      const double weight = rng.uniform(0.1, 5.0);
      exact.push_back({a, Q * a + d, weight});
      noisy.push_back({a, Q * a + d + rng.vector(0.05), weight});
    }
    SCOPED_TRACE(testing::Message() << "n = " << n);
    const AttitudeEstimate est = estimate_attitude(exact, with_translation);
    expect_rotation(est.rotation);
    EXPECT_LT(test::max_abs_diff(est.rotation, Q), 1e-11);
    EXPECT_LT(test::max_abs_diff(est.translation, d), 1e-10);
    const AttitudeEstimate est_noisy = estimate_attitude(noisy, with_translation);
    expect_rotation(est_noisy.rotation);
    EXPECT_LT(test::max_abs_diff(est_noisy.rotation, davenport(noisy, with_translation).rotation),
              1e-10);

    // Mirrored data b = M a, M = Q (I − 2 m⊗m) improper.
    const Vec3 m = rng.unit_vector();
    const Tensor M = Q * (Tensor::Identity() - 2.0 * m * m.transpose());
    Observations mirrored;
    for (int k = 0; k < 6; ++k) {
      const Vec3 a = rng.vector(2.0);
      mirrored.push_back({a, M * a + rng.vector(0.01), rng.uniform(0.1, 5.0)});
    }
    const AttitudeEstimate est_mirrored = estimate_attitude(mirrored, with_translation);
    expect_rotation(est_mirrored.rotation);
    const Solution ref = davenport(mirrored, with_translation);
    EXPECT_LT(test::max_abs_diff(est_mirrored.rotation, ref.rotation), 1e-10);
    EXPECT_NEAR(est_mirrored.loss, loss(mirrored, ref.rotation, ref.translation),
                1e-12 * (1.0 + est_mirrored.loss));
  }
}

// (6.37) with d free (Horn): d is recovered, and d = b̄ − Q ā for the weighted means.
TEST(AttitudeEstimation, WithTranslationRecoversOffset) {
  test::Random rng(406);
  for (int n = 0; n < 300; ++n) {
    const Tensor Q = rng.rotation();
    const Vec3 d = rng.vector(100.0);
    const Observations obs = simulate(rng, 5, Q, d, 0.0);
    const AttitudeEstimate est = estimate_attitude(obs, true);
    EXPECT_LT(test::max_abs_diff(est.translation, d), 1e-11 * (1.0 + d.norm()));
    EXPECT_LT(test::max_abs_diff(est.rotation, Q), 1e-12);
    // Without the translation the same data cannot be fitted.
    EXPECT_GT(estimate_attitude(obs, false).loss, 1e-3);

    // Two exact observations with d free: only the rotation about a2 − a1 is undetermined, but W
    // still vanishes and a2 − a1 is carried onto b2 − b1.
    const Observations pair = simulate(rng, 2, Q, d, 0.0);
    const AttitudeEstimate two = estimate_attitude(pair, true);
    expect_rotation(two.rotation);
    EXPECT_LT(two.loss, 1e-20);
    EXPECT_LT(test::max_abs_diff(Vec3(two.rotation * (pair[1].reference - pair[0].reference)),
                                 Vec3(pair[1].observed - pair[0].observed)),
              1e-12 * (1.0 + d.norm()));

    // With noise, ∂W/∂d = 0 at the optimum: d = b̄ − Q ā with α-weighted means.
    const Observations noisy = simulate(rng, 7, Q, d, 0.1);
    const AttitudeEstimate fit = estimate_attitude(noisy, true);
    Vec3 a_mean = Vec3::Zero(), b_mean = Vec3::Zero();
    double total = 0.0;
    for (const auto& o : noisy) {
      a_mean += o.weight * o.reference;
      b_mean += o.weight * o.observed;
      total += o.weight;
    }
    const Vec3 optimal_d = (b_mean - fit.rotation * a_mean) / total;
    EXPECT_LT(test::max_abs_diff(fit.translation, optimal_d), 1e-12 * (1.0 + d.norm()));
  }
}

// (6.37) preconditions: N ≥ 2 and α_K > 0, else std::invalid_argument.
TEST(AttitudeEstimation, RejectsBadInput) {
  const Vec3 a(1, 0, 0), b(0, 1, 0);
  EXPECT_THROW(estimate_attitude(Observations{}, false), std::invalid_argument);
  EXPECT_THROW(estimate_attitude(Observations{{a, b, 1.0}}, false), std::invalid_argument);
  EXPECT_THROW(estimate_attitude(Observations{{a, b, 1.0}}, true), std::invalid_argument);
  EXPECT_THROW(estimate_attitude(Observations{{a, b, 1.0}, {b, a, 0.0}}, false),
               std::invalid_argument);
  EXPECT_THROW(estimate_attitude(Observations{{a, b, -1.0}, {b, a, 1.0}}, true),
               std::invalid_argument);
  EXPECT_THROW(
      estimate_attitude(Observations{{a, b, std::numeric_limits<double>::quiet_NaN()}, {b, a, 1.0}},
                        false),
      std::invalid_argument);
  EXPECT_NO_THROW(estimate_attitude(Observations{{a, b, 1.0}, {b, a, 1e-6}}, false));
}

}  // namespace
}  // namespace unidyn
