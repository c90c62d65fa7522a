// The representative point in E^{3N} (book §4.7): Ex. 4.4's bases for two particles in Cartesian
// coordinates, and Ex. 5.3's coordinate bases a_K, a^K of two free particles — m1 in cylindrical
// coordinates, r2 − r1 in spherical ones — against the book's printed components; the metric
// against the kinetic energy T = (m/2) a_JK q̇^J q̇^K.
#include "unidyn/kinematics/representative_point.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

// The value of e with the parameters and the state `values` (coordinates, then their rates).
double value(const Expr& e, const System& system, const std::vector<double>& values) {
  GiNaC::exmap at;
  for (const auto& p : system.parameters) at[p.symbol] = p.value;
  const auto& q = system.coordinates();
  for (std::size_t i = 0; i < q.size(); ++i) {
    at[q[i].value] = values[i];
    if (values.size() > q.size()) at[q[i].rate] = values[q.size() + i];
  }
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(at))).to_double();
}

// a^K · a_J = δ^K_J at the state
void expect_reciprocal(const RepresentativePoint& point, const System& system,
                       const std::vector<double>& at) {
  for (std::size_t K = 0; K < point.contravariant.size(); ++K) {
    for (std::size_t J = 0; J < point.covariant.size(); ++J) {
      EXPECT_NEAR(value(dot(point.contravariant[K], point.covariant[J]), system, at),
                  K == J ? 1.0 : 0.0, 1e-14)
          << K << ", " << J;
    }
  }
}

const std::string two_particles = R"(unidyn: 1
parameters: {m1: 1.5, m2: 0.5}
coordinates: [r1, th1, z1, R2, ph2, th2]
particles:
  A: {mass: m1, position: "[r1*cos(th1), r1*sin(th1), z1]"}
  B: {mass: m2, position: "[r1*cos(th1) + R2*sin(ph2)*cos(th2), r1*sin(th1) + R2*sin(ph2)*sin(th2), z1 + R2*cos(ph2)]"}
)";

// Ex. 4.4: in Cartesian coordinates a_K = e_K = √(m_i/m) ē_K and a^K = e^K = √(m/m_i) ē_K, so
// e_K · e^J = δ_K^J while |e_K|² = m_i/m.
TEST(RepresentativePoint, CartesianBasesOfExercise44) {
  const System system = parse_model(R"(unidyn: 1
parameters: {m1: 1.5, m2: 0.5}
coordinates: [x1, y1, z1, x2, y2, z2]
particles:
  A: {mass: m1, position: [x1, y1, z1]}
  B: {mass: m2, position: [x2, y2, z2]}
)",
                                    "two.yaml");
  const RepresentativePoint point = representative_point(system);
  ASSERT_EQ(point.contravariant.size(), 6u);
  const std::vector<double> at{0.1, 0.2, 0.3, 0.4, 0.5, 0.6};
  for (std::size_t K = 0; K < 6; ++K) {
    const double m_i = K < 3 ? 1.5 : 0.5;
    EXPECT_NEAR(value(dot(point.covariant[K], point.covariant[K]), system, at), m_i / 2.0, 1e-15);
    EXPECT_NEAR(value(dot(point.contravariant[K], point.contravariant[K]), system, at), 2.0 / m_i,
                1e-14);
  }
  expect_reciprocal(point, system, at);
}

// Ex. 5.3(b)–(c): the book's a_K on e_K and a^K on e^K, component by component, and
// a^I · a_J = δ^I_J, at a few states.
TEST(RepresentativePoint, CoordinateBasesOfExercise53) {
  const System system = parse_model(two_particles, "ex53.yaml");
  const RepresentativePoint point = representative_point(system);
  ASSERT_EQ(point.contravariant.size(), 6u);
  const std::vector<std::vector<double>> states{{0.8, 0.3, -0.2, 1.1, 0.7, 2.0},
                                                {1.7, -2.1, 0.5, 0.4, 2.5, -0.6}};
  for (const auto& at : states) {
    const double r1 = at[0], t1 = at[1], R2 = at[3], p2 = at[4], t2 = at[5];
    const double c1 = std::cos(t1), s1 = std::sin(t1), cp = std::cos(p2), sp = std::sin(p2),
                 c2 = std::cos(t2), s2 = std::sin(t2);
    // (b), on e_1 .. e_6
    const std::vector<std::vector<double>> a{{c1, s1, 0, c1, s1, 0},
                                             {-r1 * s1, r1 * c1, 0, -r1 * s1, r1 * c1, 0},
                                             {0, 0, 1, 0, 0, 1},
                                             {0, 0, 0, sp * c2, sp * s2, cp},
                                             {0, 0, 0, R2 * cp * c2, R2 * cp * s2, -R2 * sp},
                                             {0, 0, 0, -R2 * sp * s2, R2 * sp * c2, 0}};
    // (c), on e^1 .. e^6
    const std::vector<std::vector<double>> upper{
        {c1, s1, 0, 0, 0, 0},
        {-s1 / r1, c1 / r1, 0, 0, 0, 0},
        {0, 0, 1, 0, 0, 0},
        {-sp * c2, -sp * s2, -cp, sp * c2, sp * s2, cp},
        {-cp * c2 / R2, -cp * s2 / R2, sp / R2, cp * c2 / R2, cp * s2 / R2, -sp / R2},
        {s2 / (R2 * sp), -c2 / (R2 * sp), 0, -s2 / (R2 * sp), c2 / (R2 * sp), 0}};
    for (std::size_t K = 0; K < 6; ++K) {
      for (std::size_t c = 0; c < 6; ++c) {
        const double scale = value(point.scale[c], system, at);
        EXPECT_NEAR(value(point.covariant[K][c], system, at), a[K][c] * scale, 1e-14) << K << c;
        EXPECT_NEAR(value(point.contravariant[K][c], system, at), upper[K][c] / scale, 1e-13)
            << K << c;
      }
    }
    expect_reciprocal(point, system, at);
  }
}

// The metric is the kinetic energy's: (m/2) a_JK q̇^J q̇^K = ½ Σ m_i v_i · v_i.
TEST(RepresentativePoint, MetricGivesTheKineticEnergy) {
  const System system = parse_model(two_particles, "ex53.yaml");
  const RepresentativePoint point = representative_point(system);
  const auto& q = system.coordinates();
  Expr T = 0;
  for (std::size_t J = 0; J < q.size(); ++J) {
    for (std::size_t K = 0; K < q.size(); ++K) {
      T += point.mass / 2 * point.metric(unsigned(J), unsigned(K)) * q[J].rate * q[K].rate;
    }
  }
  const std::vector<double> at{0.8, 0.3, -0.2, 1.1, 0.7, 2.0, 0.5, -1.2, 0.3, 0.9, -0.4, 1.5};
  EXPECT_NEAR(value(T, system, at), value(system.kinetic_energy(), system, at), 1e-13);
}

}  // namespace
}  // namespace unidyn
