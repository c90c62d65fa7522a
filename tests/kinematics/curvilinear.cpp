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

// Ex. 1.4, the vectors themselves: a₁ = e_R, a₂ = R e_φ, a₃ = R sin φ e_θ and a^3 = e_θ/(R sin φ),
// with e_R, e_φ, e_θ typed from the book (φ from E3, θ about E3).
TEST(Curvilinear, SphericalBasesAreTheBooksOfExercise14) {
  const Spherical s;
  const CurvilinearCoordinates c = curvilinear_coordinates(s.r, s.q);
  const VectorExpr e_R{sin(s.phi) * cos(s.theta), sin(s.phi) * sin(s.theta), cos(s.phi)};
  const VectorExpr e_phi{cos(s.phi) * cos(s.theta), cos(s.phi) * sin(s.theta), -sin(s.phi)};
  const VectorExpr e_theta{-sin(s.theta), cos(s.theta), 0};
  for (int k = 0; k < 3; ++k) {
    EXPECT_TRUE(vanishes(c.covariant_basis[0][k] - e_R[k])) << "a_1, component " << k;
    EXPECT_TRUE(vanishes(c.covariant_basis[1][k] - s.R * e_phi[k])) << "a_2, component " << k;
    EXPECT_TRUE(vanishes(c.covariant_basis[2][k] - s.R * sin(s.phi) * e_theta[k]))
        << "a_3, component " << k;
    EXPECT_TRUE(vanishes(c.contravariant_basis[2][k] - e_theta[k] / (s.R * sin(s.phi))))
        << "a^3, component " << k;
  }
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

// Ex. 1.5, where the coordinates fail: det a_ik = (u² + v²)² u² v², zero exactly on uv = 0 (the
// E3 axis), where the map is refused.
TEST(Curvilinear, ParabolicCoordinatesAreSingularOnUvZero) {
  const GiNaC::realsymbol u("u"), v("v"), th("theta");
  const std::vector<Expr> q{u, v, th};
  const VectorExpr r{u * v * cos(th), u * v * sin(th), (pow(u, 2) - pow(v, 2)) / 2};
  const CurvilinearCoordinates c = curvilinear_coordinates(r, q);
  const ExprMatrix& a = c.metric;
  const Expr det = a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) -
                   a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
                   a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  EXPECT_TRUE(vanishes(det - pow(u * u + v * v, 2) * pow(u * v, 2))) << det;
  // with u = 0 (or v = 0) put in, r no longer depends on θ: no basis
  for (const Expr& zero : {Expr(u), Expr(v)}) {
    const VectorExpr on_axis{r[0].subs(zero == 0), r[1].subs(zero == 0), r[2].subs(zero == 0)};
    EXPECT_THROW(curvilinear_coordinates(on_axis, q), std::invalid_argument) << zero;
  }
}

// Each component of two vectors equal, after simplification.
void expect_equal(const VectorExpr& a, const VectorExpr& b, const char* what) {
  for (int k = 0; k < 3; ++k) EXPECT_TRUE(vanishes(a[k] - b[k])) << what << " component " << k;
}

// §1.5 (1.6): q¹ = y, q² = x − y², q³ = z, so r = (q² + (q¹)², q¹, q³): a₁ = 2q¹ E1 + E2,
// a^1 = grad q¹ = E2, a^2 = grad q² = E1 − 2q¹ E2, and a^1 · a^2 = −2q¹ (not orthogonal).
TEST(Curvilinear, NonOrthogonalCoordinatesOfSection15) {
  const GiNaC::realsymbol q1("q1"), q2("q2"), q3("q3");
  const CurvilinearCoordinates c = curvilinear_coordinates({q2 + pow(q1, 2), q1, q3}, {q1, q2, q3});
  expect_equal(c.covariant_basis[0], {2 * q1, 1, 0}, "a_1");
  expect_equal(c.contravariant_basis[0], {0, 1, 0}, "a^1");
  expect_equal(c.contravariant_basis[1], {1, -2 * q1, 0}, "a^2");
  EXPECT_TRUE(vanishes(dot(c.contravariant_basis[0], c.contravariant_basis[1]) + 2 * q1));
}

// Ex. 1.3, cylindrical coordinates {r, θ, z}: a₂ = r e_θ, a^2 = e_θ/r, and the metric diag(1, r²,
// 1) of T = (m/2)(ṙ² + r² θ̇² + ż²).
TEST(Curvilinear, CylindricalCoordinatesOfExercise13) {
  const GiNaC::realsymbol r("r"), th("theta"), z("z");
  const CurvilinearCoordinates c =
      curvilinear_coordinates({r * cos(th), r * sin(th), z}, {r, th, z});
  const VectorExpr e_theta{-sin(th), cos(th), 0};
  expect_equal(c.covariant_basis[1], r * e_theta, "a_2");
  expect_equal(c.contravariant_basis[1], e_theta / r, "a^2");
  const Expr metric[3] = {1, pow(r, 2), 1};
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_TRUE(vanishes(c.metric(i, k) - (i == k ? metric[i] : Expr(0)))) << i << k;
    }
  }
}

// Ex. 1.6, helicoidal coordinates {θ, r, ν = z − α r θ}: T = (m/2)[(1 + α²θ²) ṙ² + (1 + α²) r² θ̇²
// + ν̇² + …], i.e. a_rr = 1 + α²θ², a_θθ = (1 + α²) r², a_νν = 1.
TEST(Curvilinear, HelicoidalCoordinatesOfExercise16) {
  const GiNaC::realsymbol th("theta"), r("r"), nu("nu"), alpha("alpha");
  const CurvilinearCoordinates c =
      curvilinear_coordinates({r * cos(th), r * sin(th), nu + alpha * r * th}, {th, r, nu});
  EXPECT_TRUE(vanishes(c.metric(1, 1) - (1 + pow(alpha * th, 2))));
  EXPECT_TRUE(vanishes(c.metric(0, 0) - (1 + pow(alpha, 2)) * pow(r, 2)));
  EXPECT_TRUE(vanishes(c.metric(2, 2) - 1));
  EXPECT_TRUE(vanishes(c.metric(0, 1) - pow(alpha, 2) * r * th));
}

// Ex. 1.7–1.9, oblique coordinates q¹ = x₁ sec α, q² = x₂ − x₁ tan α (x₁ = q¹ cos α, x₂ = q² +
// q¹ sin α): a₁ = cos α E1 + sin α E2, a₂ = E2, a^1 = sec α E1, a^2 = −tan α E1 + E2 (1.24)–(1.25);
// b = 10 E1 + 5 E2 + 6 E3 has b₁ = 10 cos α + 5 sin α, b^1 = 10 sec α, b^2 = 5 − 10 tan α
// (Ex. 1.8); a_ik a^kj = δ_i^j and b_i = a_ik b^k (Ex. 1.9). At α = π/2 there is no basis.
TEST(Curvilinear, ObliqueCoordinatesOfExercises17To19) {
  const GiNaC::realsymbol q1("q1"), q2("q2"), q3("q3"), alpha("alpha");
  const std::vector<Expr> q{q1, q2, q3};
  const CurvilinearCoordinates c =
      curvilinear_coordinates({q1 * cos(alpha), q2 + q1 * sin(alpha), q3}, q);
  expect_equal(c.covariant_basis[0], {cos(alpha), sin(alpha), 0}, "a_1");
  expect_equal(c.covariant_basis[1], {0, 1, 0}, "a_2");
  expect_equal(c.contravariant_basis[0], {1 / cos(alpha), 0, 0}, "a^1");
  expect_equal(c.contravariant_basis[1], {-sin(alpha) / cos(alpha), 1, 0}, "a^2");
  const VectorExpr b{10, 5, 6};
  EXPECT_TRUE(vanishes(dot(b, c.covariant_basis[0]) - (10 * cos(alpha) + 5 * sin(alpha))));
  EXPECT_TRUE(vanishes(dot(b, c.contravariant_basis[0]) - 10 / cos(alpha)));
  EXPECT_TRUE(vanishes(dot(b, c.contravariant_basis[1]) - (5 - 10 * sin(alpha) / cos(alpha))));
  for (std::size_t i = 0; i < 3; ++i) {
    Expr b_lower = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      Expr delta = 0;
      for (std::size_t l = 0; l < 3; ++l) delta += c.metric(i, l) * c.inverse_metric(l, k);
      EXPECT_TRUE(vanishes(delta - (i == k ? 1 : 0))) << i << k;
      b_lower += c.metric(i, k) * dot(b, c.contravariant_basis[k]);
    }
    EXPECT_TRUE(vanishes(b_lower - dot(b, c.covariant_basis[i]))) << i;
  }
  EXPECT_THROW(curvilinear_coordinates({q1 * 0, q2 + q1, q3}, q),  // cos α = 0: a₁ = a₂ = E2
               std::invalid_argument);
}

// Dependent coordinates have no dual basis
TEST(Curvilinear, SingularMetricIsRefused) {
  const GiNaC::realsymbol x("x"), y("y");
  EXPECT_THROW(curvilinear_coordinates({x + y, x + y, 0}, {x, y}), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
