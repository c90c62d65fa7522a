// Chasles' screw of a rigid displacement (book §7.2, (7.5)–(7.7)): the screw found must move every
// material point as the displacement does, solve (7.6) with ρ ⟂ s, and give back a screw built by
// hand.
#include "unidyn/kinematics/screw_motion.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/oracles.hpp"
#include "unidyn/rotation/errors.hpp"

namespace unidyn {
namespace {

// x ↦ ρ + L(φ, s)(x − ρ) + σ s: the rotation about the axis through ρ, then the slide, with
// L(φ, s) typed from (6.8) in the test's own oracle.
Vec3 screw_of(const ScrewMotion& screw, const Vec3& x) {
  return screw.point + test::book_L(screw.angle, screw.axis) * (x - screw.point) +
         screw.slide * screw.axis;
}

// Random placements (Q0, d0) and (Q, d): (7.6)'s residual vanishes, ρ · s = 0, and each material
// point X, at Q0 X + d0 then Q X + d (7.4), moves along the screw.
TEST(ScrewMotion, MovesEveryPointAsTheDisplacementDoes) {
  test::Random random;
  for (int trial = 0; trial < 200; ++trial) {
    const Tensor Q0 = random.rotation(), Q = random.rotation();
    const Vec3 d0 = random.vector(3), d = random.vector(3);
    const ScrewMotion screw = screw_motion(Q0, d0, Q, d);
    const Tensor R = Q * Q0.transpose();
    const Vec3 z = d - R * d0;
    EXPECT_NEAR(screw.axis.norm(), 1, 1e-14);
    EXPECT_NEAR(screw.axis.dot(screw.point), 0, 1e-12);
    EXPECT_LT(((Tensor::Identity() - R) * screw.point + screw.slide * screw.axis - z).norm(),
              1e-12 * (1 + z.norm()));
    for (int k = 0; k < 5; ++k) {
      const Vec3 X = random.vector(2);
      EXPECT_LT((screw_of(screw, Q0 * X + d0) - (Q * X + d)).norm(), 1e-11 * (1 + z.norm()))
          << trial;
    }
  }
}

// A screw by hand: 0.7 rad about E3 through (1, 2, 0), sliding 0.4 along E3 — and about a tilted
// axis, with the turn through π (cot(π/2) = 0).
TEST(ScrewMotion, GivesBackAScrewBuiltByHand) {
  for (const double angle : {0.7, test::kPi}) {
    const Vec3 s = Vec3(1, 2, 2) / 3, rho = Vec3(2, -1, 0);  // ρ · s = 0
    const ScrewMotion built{s, angle, rho, 0.4};
    const Tensor R = test::book_L(angle, s);
    const Vec3 z = screw_of(built, Vec3::Zero());
    const ScrewMotion found = screw_motion(R, z);
    EXPECT_NEAR(found.angle, angle, 1e-14);
    EXPECT_LT((found.axis - s).norm(), 1e-14) << angle;
    EXPECT_LT((found.point - rho).norm(), 1e-7) << angle;
    EXPECT_NEAR(found.slide, 0.4, 1e-7) << angle;
  }
  const ScrewMotion e3 = screw_motion(test::book_L(0.7, Vec3::UnitZ()), Vec3(0, 0, 0.4));
  EXPECT_LT((e3.point - Vec3::Zero()).norm(), 1e-15);
  EXPECT_NEAR(e3.slide, 0.4, 1e-15);
}

// A pure translation has no axis.
TEST(ScrewMotion, PureTranslationHasNoAxis) {
  EXPECT_THROW(screw_motion(Tensor::Identity(), Vec3(1, 0, 0)), SingularConfiguration);
}

}  // namespace
}  // namespace unidyn
