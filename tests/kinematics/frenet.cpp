#include "unidyn/kinematics/frenet.hpp"

#include "support/oracles.hpp"

namespace unidyn {
namespace {

using GiNaC::cos;
using GiNaC::sin;

double value_at(const Expr& e, const GiNaC::exmap& at) {
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

// §3.8: the helix r = R e_r + αRθ E3 has κ = 1/(R(1 + α²)), τ = α/(R(1 + α²)),
// ds/dθ = R √(1 + α²)
TEST(Frenet, HelixCurvatureAndTorsion) {
  const GiNaC::realsymbol theta("theta"), R("R"), alpha("alpha");
  const FrenetTriad f = frenet_triad({R * cos(theta), R * sin(theta), alpha * R * theta}, theta);
  for (double a : {0.3, 1.0, 2.5}) {
    for (double radius : {0.5, 2.0}) {
      for (double t : {-1.0, 0.2, 3.0}) {
        const GiNaC::exmap at{{theta, t}, {R, radius}, {alpha, a}};
        EXPECT_NEAR(value_at(f.curvature, at), 1 / (radius * (1 + a * a)), 1e-14);
        EXPECT_NEAR(value_at(f.torsion, at), a / (radius * (1 + a * a)), 1e-14);
        EXPECT_NEAR(value_at(f.speed, at), radius * std::sqrt(1 + a * a), 1e-14);
        // e_n points at the axis: −e_r
        EXPECT_NEAR(value_at(f.normal[0], at), -std::cos(t), 1e-14);
        EXPECT_NEAR(value_at(f.normal[1], at), -std::sin(t), 1e-14);
        EXPECT_NEAR(value_at(f.normal[2], at), 0.0, 1e-14);
      }
    }
  }
}

// A circle of radius ρ has κ = 1/ρ and τ = 0; the triad is right-handed and orthonormal
TEST(Frenet, CircleAndOrthonormality) {
  const GiNaC::realsymbol u("u");
  const double rho = 1.7;
  const FrenetTriad f = frenet_triad({rho * cos(2 * u), rho * sin(2 * u), 0}, u);
  const GiNaC::exmap at{{u, 0.4}};
  EXPECT_NEAR(value_at(f.curvature, at), 1 / rho, 1e-14);
  EXPECT_NEAR(value_at(f.torsion, at), 0.0, 1e-14);
  EXPECT_NEAR(value_at(f.speed, at), 2 * rho, 1e-14);
  const VectorExpr* triad[3] = {&f.tangent, &f.normal, &f.binormal};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(value_at(dot(*triad[i], *triad[k]), at), i == k ? 1.0 : 0.0, 1e-14);
    }
  }
  EXPECT_NEAR(value_at(dot(cross(f.tangent, f.normal), f.binormal), at), 1.0, 1e-14);
}

// A twisted cubic r = (u, u², u³): κ and τ against the general formulas evaluated by hand
TEST(Frenet, TwistedCubic) {
  const GiNaC::realsymbol u("u");
  const FrenetTriad f = frenet_triad({u, u * u, u * u * u}, u);
  for (double x : {-0.7, 0.0, 0.5, 1.3}) {
    const Vec3 r1(1, 2 * x, 3 * x * x), r2(0, 2, 6 * x), r3(0, 0, 6);
    const Vec3 c = r1.cross(r2);
    const GiNaC::exmap at{{u, x}};
    EXPECT_NEAR(value_at(f.curvature, at), c.norm() / std::pow(r1.norm(), 3), 1e-13);
    EXPECT_NEAR(value_at(f.torsion, at), c.dot(r3) / c.squaredNorm(), 1e-13);
  }
}

}  // namespace
}  // namespace unidyn
