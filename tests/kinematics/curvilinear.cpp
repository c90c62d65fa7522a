#include "unidyn/kinematics/curvilinear.hpp"

#include "support/oracles.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

using GiNaC::cos;
using GiNaC::pow;
using GiNaC::sin;

bool vanishes(const Expr& e) {
  return simplify(e).is_zero();
}

// Spherical coordinates {R, φ, θ}, φ from E3 (§3.3, Ex. 3.3)
struct Spherical {
  GiNaC::realsymbol R{"R"}, phi{"phi"}, theta{"theta"};
  std::vector<Expr> q{R, phi, theta};
  VectorExpr r{R * sin(phi) * cos(theta), R* sin(phi) * sin(theta), R* cos(phi)};
};

// (4.33) metric diag(1, R², R² sin²φ), and a^i · a_k = δ^i_k (Ex. 3.3)
TEST(Curvilinear, SphericalMetricAndDualBasis) {
  const Spherical s;
  const CurvilinearCoordinates c = curvilinear_coordinates(s.r, s.q);
  const Expr expected[3] = {1, pow(s.R, 2), pow(s.R * sin(s.phi), 2)};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_TRUE(vanishes(c.metric(i, k) - (i == k ? expected[i] : Expr(0)))) << i << k;
      EXPECT_TRUE(vanishes(dot(c.contravariant_basis[i], c.covariant_basis[k]) - (i == k ? 1 : 0)));
    }
  }
  // a^3 = e_θ / (R sin φ): its length is 1/(R sin φ)
  EXPECT_TRUE(vanishes(dot(c.contravariant_basis[2], c.contravariant_basis[2]) -
                       1 / pow(s.R * sin(s.phi), 2)));
}

// §4.10: [22,1] = −R, [33,1] = −R sin²φ, [12,2] = R, [13,3] = R sin²φ; the others vanish
TEST(Curvilinear, SphericalChristoffelFirstKind) {
  const Spherical s;
  const auto first = christoffel_first_kind(curvilinear_coordinates(s.r, s.q).metric, s.q);
  Expr expected[3][3][3];
  for (auto& a : expected)
    for (auto& b : a)
      for (auto& e : b) e = 0;
  expected[1][1][0] = -s.R;
  expected[2][2][0] = -s.R * pow(sin(s.phi), 2);
  expected[0][1][1] = expected[1][0][1] = s.R;
  expected[0][2][2] = expected[2][0][2] = s.R * pow(sin(s.phi), 2);
  expected[1][2][2] = expected[2][1][2] = pow(s.R, 2) * sin(s.phi) * cos(s.phi);
  expected[2][2][1] = -pow(s.R, 2) * sin(s.phi) * cos(s.phi);
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j)
      for (std::size_t k = 0; k < 3; ++k) {
        EXPECT_TRUE(vanishes(first[i][j][k] - expected[i][j][k]))
            << "[" << i + 1 << j + 1 << "," << k + 1 << "] = " << first[i][j][k];
      }
}

// §4.10: Γ^1_22 = −R, Γ^2_33 = −sin φ cos φ, Γ^3_23 = cot φ, Γ^2_12 = Γ^3_13 = 1/R
TEST(Curvilinear, SphericalChristoffelSecondKind) {
  const Spherical s;
  const auto gamma = christoffel_second_kind(curvilinear_coordinates(s.r, s.q), s.q);
  EXPECT_TRUE(vanishes(gamma[0][1][1] + s.R));
  EXPECT_TRUE(vanishes(gamma[0][2][2] + s.R * pow(sin(s.phi), 2)));
  EXPECT_TRUE(vanishes(gamma[1][2][2] + sin(s.phi) * cos(s.phi)));
  EXPECT_TRUE(vanishes(gamma[2][1][2] - cos(s.phi) / sin(s.phi)));
  EXPECT_TRUE(vanishes(gamma[1][0][1] - 1 / s.R));
  EXPECT_TRUE(vanishes(gamma[2][0][2] - 1 / s.R));
  EXPECT_TRUE(vanishes(gamma[0][0][0]));
  EXPECT_TRUE(vanishes(gamma[1][1][1]));
}

// Ex. 3.2(d): in Cartesian coordinates the metric is constant and every symbol vanishes
TEST(Curvilinear, CartesianChristoffelSymbolsVanish) {
  const GiNaC::realsymbol x("x"), y("y"), z("z");
  const std::vector<Expr> q{x, y, z};
  const CurvilinearCoordinates c = curvilinear_coordinates({x, y, z}, q);
  const auto gamma = christoffel_second_kind(c, q);
  for (const auto& a : gamma)
    for (const auto& b : a)
      for (const auto& e : b) EXPECT_TRUE(e.is_zero());
}

// Ex. 3.1 parabolic coordinates: a_1 = v e_r + u E3, a_2 = u e_r − v E3, a_3 = uv e_θ and
// a^i = a_i/(u² + v²) (i = 1, 2), a^3 = e_θ/(uv)
TEST(Curvilinear, ParabolicBases) {
  const GiNaC::realsymbol u("u"), v("v"), th("theta");
  const std::vector<Expr> q{u, v, th};
  const CurvilinearCoordinates c =
      curvilinear_coordinates({u * v * cos(th), u * v * sin(th), (pow(u, 2) - pow(v, 2)) / 2}, q);
  const VectorExpr e_r{cos(th), sin(th), 0}, e_theta{-sin(th), cos(th), 0}, E3{0, 0, 1};
  const VectorExpr a1 = v * e_r + u * E3, a2 = u * e_r - v * E3, a3 = u * v * e_theta;
  const VectorExpr duals[3] = {a1 / (u * u + v * v), a2 / (u * u + v * v), e_theta / (u * v)};
  const VectorExpr covariants[3] = {a1, a2, a3};
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_TRUE(vanishes(c.covariant_basis[i][k] - covariants[i][k]));
      EXPECT_TRUE(vanishes(c.contravariant_basis[i][k] - duals[i][k]));
    }
  }
}

// Dependent coordinates have no dual basis
TEST(Curvilinear, SingularMetricIsRefused) {
  const GiNaC::realsymbol x("x"), y("y");
  EXPECT_THROW(curvilinear_coordinates({x + y, x + y, 0}, {x, y}), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
