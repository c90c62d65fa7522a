// Floquet analysis of periodic motions (analysis/floquet.hpp, floquet_sweep.hpp) against results
// that are not unidyn's: the Mathieu equation's characteristic values (Abramowitz & Stegun ch. 20:
// Table 20.1 and the series 20.2.25, and Hill's tridiagonal eigenproblems written here), the
// inverted pendulum's Kapitza boundary and the hanging one's parametric resonance (both Mathieu
// equations after τ = Ωt/2), and damping, which turns the damped equation into an undamped one
// exactly (x = e^{−κt/2} y), against a monodromy matrix integrated here by RK4.
#include "unidyn/analysis/floquet.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/eigen_solvers.hpp"
#include "support/model_run.hpp"
#include "unidyn/analysis/floquet_sweep.hpp"
#include "unidyn/analysis/time_dependence.hpp"

namespace unidyn {
namespace {

using test::model_path;
using Parameters = std::vector<std::pair<std::string, double>>;

// ---- oracles written here ----

// The characteristic values of y'' + (a − 2q cos 2z) y = 0 as the lowest eigenvalue of Hill's
// tridiagonal matrices (A&S 20.2.5–20.2.11, the recurrences of the Fourier coefficients of
// ce_r and se_r, symmetrised), truncated at 60 terms: kind 'a0' (ce_0: [0, √2 q; √2 q, 4, q; q,
// 16, …]), 'b1' (se_1: [1 − q, q; q, 9, q; …]), 'a1' (ce_1: [1 + q, q; …]), 'b2' (se_2: [4, q;
// q, 16, q; …]), 'a2' (ce_2: the second eigenvalue of a0's matrix).
double characteristic_value(const std::string& kind, double q) {
  const int size = 60;
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(size, size);
  const bool odd = kind == "a1" || kind == "b1";
  for (int k = 0; k < size; ++k) {
    const double order = odd ? 2 * k + 1 : (kind == "b2" ? 2 * k + 2 : 2 * k);
    H(k, k) = order * order;
    if (k + 1 < size) H(k, k + 1) = H(k + 1, k) = q;
  }
  if (kind == "a0" || kind == "a2") H(0, 1) = H(1, 0) = std::sqrt(2.0) * q;
  if (kind == "a1") H(0, 0) += q;
  if (kind == "b1") H(0, 0) -= q;
  const Eigen::VectorXd values = test::symmetric_eigen(H).eigenvalues();
  return kind == "a2" ? values[1] : values[0];
}

// The monodromy matrix of x'' + κx' + (a − 2q cos 2t) x = 0 over [0, π] for the state (x, x'),
// by classical RK4 with 4000 steps (error ~1e-13 here).
Eigen::Matrix2d mathieu_monodromy(double a, double q, double kappa) {
  const auto f = [&](double t, const Eigen::Matrix2d& Y) {
    Eigen::Matrix2d A;
    A << 0, 1, -(a - 2 * q * std::cos(2 * t)), -kappa;
    return Eigen::Matrix2d(A * Y);
  };
  const int steps = 4000;
  const double h = std::numbers::pi / steps;
  Eigen::Matrix2d Y = Eigen::Matrix2d::Identity();
  for (int k = 0; k < steps; ++k) {
    const double t = k * h;
    const Eigen::Matrix2d k1 = f(t, Y), k2 = f(t + h / 2, Y + h / 2 * k1),
                          k3 = f(t + h / 2, Y + h / 2 * k2), k4 = f(t + h, Y + h * k3);
    Y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return Y;
}

double largest_modulus(const Eigen::Matrix2d& Y) {
  return test::eigenvalues(Y).cwiseAbs().maxCoeff();
}

// ---- unidyn ----

// A model with its equations' time dependence, ready for Floquet analysis.
struct Driven {
  System system;
  EquationsOfMotion equations;
  CompiledSystem compiled;
  TimeDependence dependence;

  explicit Driven(System s)
      : system(std::move(s)),
        equations(lagrange_equations(system)),
        compiled(system, equations),
        dependence(time_dependence(system, equations)) {}
  static Driven bundled(const std::string& name) { return Driven(load_model(model_path(name))); }
  static Driven text(const std::string& yaml) { return Driven(parse_model(yaml, "test.yaml")); }

  std::vector<double> parameters(const Parameters& sets) const {
    return initial_state(system, sets).parameters;
  }
  PeriodicLinearization at(const std::vector<std::string>& given, const Parameters& sets = {},
                           std::optional<double> period = std::nullopt) const {
    const std::vector<double> p = parameters(sets);
    const OperatingPoint point =
        operating_point(system, compiled, parse_given_values(system, given), p);
    return linearize_periodic(system, compiled, point,
                              *drive_period(system, compiled, dependence, p, period));
  }
  std::vector<double> boundaries(const std::vector<std::string>& given, const Parameters& sets,
                                 const std::string& name, double from, double to,
                                 std::size_t count) const {
    const FloquetSweep sweep =
        sweep_floquet(system, compiled, dependence, parse_given_values(system, given), sets, name,
                      from, to, count);
    std::vector<double> out;
    for (const StabilityBoundary& b : sweep.boundaries) out.push_back(b.value);
    for (const FloquetSweepPoint& p : sweep.points) EXPECT_EQ(p.failure, "") << p.value;
    return out;
  }
};

// The oracle itself, before it judges anything: Hill's matrices give A&S Table 20.1's values at
// q = 1 (printed to 8 decimals) and the series 20.2.25 at q = 0.1.
TEST(Floquet, HillsMatricesGiveTheTabulatedCharacteristicValues) {
  EXPECT_NEAR(characteristic_value("a0", 1), -0.45513861, 1e-8);
  EXPECT_NEAR(characteristic_value("b1", 1), -0.11024882, 1e-8);
  EXPECT_NEAR(characteristic_value("a1", 1), 1.85910807, 1e-8);
  EXPECT_NEAR(characteristic_value("b2", 1), 3.91702477, 1e-8);
  EXPECT_NEAR(characteristic_value("a2", 1), 4.37130098, 1e-8);
  const double q = 0.1, q2 = q * q;
  EXPECT_NEAR(characteristic_value("a0", q), -q2 / 2 + 7 * q2 * q2 / 128 - 29 * q2 * q2 * q2 / 2304,
              1e-10);
  EXPECT_NEAR(characteristic_value("b1", q),
              1 - q - q2 / 8 + q2 * q / 64 - q2 * q2 / 1536 - 11 * q2 * q2 * q / 36864, 1e-9);
  EXPECT_NEAR(characteristic_value("a1", q),
              1 + q - q2 / 8 - q2 * q / 64 - q2 * q2 / 1536 + 11 * q2 * q2 * q / 36864, 1e-9);
}

// The period is found from cos(2t): π; the equations depend on t, and periodically.
TEST(Floquet, MathieuPeriodIsPi) {
  const Driven m = Driven::bundled("mathieu");
  ASSERT_TRUE(m.dependence.depends);
  EXPECT_EQ(m.dependence.not_periodic, "");
  const auto period = drive_period(m.system, m.compiled, m.dependence, m.parameters({}));
  ASSERT_TRUE(period.has_value());
  EXPECT_NEAR(period->period, std::numbers::pi, 1e-15);
}

// The monodromy matrix itself against RK4 here, damped and undamped, inside and outside a tongue.
TEST(Floquet, MathieuMonodromyMatchesAnIntegrationWrittenHere) {
  const Driven m = Driven::bundled("mathieu");
  for (const double kappa : {0.0, 0.3}) {
    for (const double a : {-0.3, 0.5, 1.0, 2.5}) {
      const PeriodicLinearization P = m.at({"x=0"}, {{"a", a}, {"q", 0.4}, {"kappa", kappa}});
      ASSERT_EQ(P.at_start.state, (std::vector<std::string>{"x", "der(x)"}));
      const Eigen::Matrix2d expected = mathieu_monodromy(a, 0.4, kappa);
      EXPECT_LT((P.monodromy - expected).cwiseAbs().maxCoeff(), 1e-9)
          << "a = " << a << ", kappa = " << kappa << "\n"
          << P.monodromy << "\nvs\n"
          << expected;
    }
  }
}

// The transition curves a0, b1, a1, b2, a2 where stability changes along a, at q = 0.1, 1 and 5
// (at q = 5 the stable band between a0 and b1 is 0.01 wide: swept on its own).
TEST(Floquet, MathieuTransitionCurves) {
  const Driven m = Driven::bundled("mathieu");
  const auto curves = [](double q, std::vector<std::string> kinds) {
    std::vector<double> out;
    for (const auto& kind : kinds) out.push_back(characteristic_value(kind, q));
    return out;
  };
  struct Case {
    double q, from, to;
    std::size_t count;
    std::vector<std::string> kinds;
  };
  for (const Case& c :
       {Case{0.1, -0.5, 3, 36, {"a0", "b1", "a1"}},
        Case{1, -1, 5, 61, {"a0", "b1", "a1", "b2", "a2"}}, Case{5, -5.85, -5.75, 21, {"a0", "b1"}},
        Case{5, 0, 8, 81, {"a1", "b2", "a2"}}}) {
    const std::vector<double> found =
        m.boundaries({"x=0"}, {{"q", c.q}}, "a", c.from, c.to, c.count);
    const std::vector<double> expected = curves(c.q, c.kinds);
    ASSERT_EQ(found.size(), expected.size()) << "q = " << c.q;
    for (std::size_t k = 0; k < found.size(); ++k) {
      EXPECT_NEAR(found[k], expected[k], 1e-10 * (1 + std::abs(expected[k])))
          << "q = " << c.q << ": " << c.kinds[k];
    }
  }
}

// Kapitza's pendulum (the bundled driven-pendulum, phi = 0 inverted): about it δφ'' = (g/l −
// (aΩ²/l) cos Ωt) δφ, with τ = Ωt/2 a Mathieu equation of a_M = −4g/(lΩ²), q = 2a/l; it is
// stable above a0(q): Ω* = √(4g/(l |a0(q)|)) = 198.199 for l = 0.2, a = 0.01 (the first-order
// √(2gl)/a = 198.09). At Ω = 158 it falls; at 250 it stands.
TEST(Floquet, KapitzaPendulumStandsAboveTheA0Curve) {
  const Driven p = Driven::bundled("driven-pendulum");
  const double g = 9.81, l = 0.2, a = 0.01;
  const double expected = std::sqrt(4 * g / (l * -characteristic_value("a0", 2 * a / l)));
  const std::vector<double> found = p.boundaries({"phi=0"}, {}, "Omega", 150, 260, 12);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0], expected, 1e-10 * expected);
  EXPECT_EQ(analyse_floquet(p.at({"phi=0"}, {{"Omega", 158}})).verdict, Stability::unstable);
  const FloquetAnalysis standing = analyse_floquet(p.at({"phi=0"}, {{"Omega", 250}}));
  EXPECT_EQ(standing.verdict, Stability::linearly_stable) << standing.reason;
  // the hanging position is stable there too (no resonance near 250)
  EXPECT_EQ(analyse_floquet(p.at({"phi=pi"}, {{"Omega", 250}})).verdict,
            Stability::linearly_stable);
}

// Parametric resonance: the hanging pendulum (phi = pi) driven near twice its natural frequency
// 2√(g/l) is unstable between Ω = √(4g/(l a1(q))) and √(4g/(l b1(q))), q = 2a/l; the tongue's width
// grows with the amplitude a, to first order in proportion.
TEST(Floquet, ParametricResonanceTongueWidensWithTheAmplitude) {
  const Driven p = Driven::bundled("driven-pendulum");
  const double g = 9.81, l = 0.2;
  std::vector<double> widths;
  for (const double a : {0.002, 0.004}) {
    const double q = 2 * a / l;
    const std::vector<double> found = p.boundaries({"phi=pi"}, {{"a", a}}, "Omega", 12.5, 15.5, 13);
    ASSERT_EQ(found.size(), 2u) << "a = " << a;
    EXPECT_NEAR(found[0], std::sqrt(4 * g / (l * characteristic_value("a1", q))), 1e-9);
    EXPECT_NEAR(found[1], std::sqrt(4 * g / (l * characteristic_value("b1", q))), 1e-9);
    widths.push_back(found[1] - found[0]);
  }
  EXPECT_NEAR(widths[1] / widths[0], 2.0, 0.02);
  // in the middle of the tongue it grows
  EXPECT_EQ(
      analyse_floquet(p.at({"phi=pi"}, {{"a", 0.004}, {"Omega", 2 * std::sqrt(g / l)}})).verdict,
      Stability::unstable);
}

// Damping: x = e^{−κt/2} y turns x'' + κx' + (a − 2q cos 2t) x = 0 into y'' + (a − κ²/4 − 2q cos
// 2t) y = 0, so the damped multipliers are e^{−κπ/2} times the undamped ones at a − κ²/4: inside
// the first tongue the boundaries move in to where the undamped |μ| reaches e^{κπ/2}, and a damping
// beyond the tongue's largest growth closes it. Outside the tongues the motion now decays.
TEST(Floquet, DampingNarrowsAndClosesTheTongues) {
  const Driven m = Driven::bundled("mathieu");
  const double q = 0.1;
  const double narrow = 0.02, wide = 0.2;
  const std::vector<double> found =
      m.boundaries({"x=0"}, {{"q", q}, {"kappa", narrow}}, "a", 0.8, 1.2, 9);
  ASSERT_EQ(found.size(), 2u);
  for (const double a : found) {
    EXPECT_NEAR(largest_modulus(mathieu_monodromy(a - narrow * narrow / 4, q, 0.0)),
                std::exp(narrow * std::numbers::pi / 2), 1e-9)
        << a;
  }
  EXPECT_GT(found[0], characteristic_value("b1", q));
  EXPECT_LT(found[1], characteristic_value("a1", q));
  // closed: the undamped tongue's largest |μ| is below e^{κπ/2} everywhere (checked here on a fine
  // grid), and no boundary is found
  double most = 0.0;
  for (double a = 0.8; a <= 1.2; a += 0.001) {
    most = std::max(most, largest_modulus(mathieu_monodromy(a - wide * wide / 4, q, 0.0)));
  }
  ASSERT_LT(most, std::exp(wide * std::numbers::pi / 2));
  EXPECT_TRUE(m.boundaries({"x=0"}, {{"q", q}, {"kappa", wide}}, "a", 0.8, 1.2, 9).empty());
  const FloquetAnalysis decaying = analyse_floquet(m.at({"x=0"}, {{"q", q}, {"kappa", wide}}));
  EXPECT_EQ(decaying.verdict, Stability::asymptotically_stable) << decaying.reason;
  for (const FloquetMultiplier& mu : decaying.multipliers) {
    EXPECT_NEAR(std::abs(mu.multiplier), std::exp(-wide * std::numbers::pi / 2), 1e-9);
    EXPECT_NEAR(mu.exponent.real(), -wide / 2, 1e-9);
  }
}

// The same pendulum in Cartesian coordinates held by a rheonomic constraint x² + (y − a cos Ωt)² =
// l²: a dependent coordinate (y) that moves with the drive, and the same multipliers as the angle's
// (they do not depend on the coordinates). A free coordinate z on the side is ignorable: dropped.
TEST(Floquet, ConstraintsAndIgnorableCoordinatesAsInTheAutonomousCase) {
  const Driven cartesian = Driven::text(R"(unidyn: 1
name: Driven pendulum, Cartesian
parameters: {m: 0.1, g: 9.81, l: 0.2, a: 0.01, Omega: 250}
coordinates: [x, y, z]
particles:
  P: {mass: m, position: [x, y, 0]}
  Q: {mass: m, position: [0, 0, z]}
forces:
  - gravity: -g*E2
constraints:
  - {name: rod, position: "x^2 + (y - a*cos(Omega*t))^2 - l^2"}
)");
  const Driven angle = Driven::bundled("driven-pendulum");
  for (const double Omega : {158.0, 250.0}) {
    const PeriodicLinearization C = cartesian.at({"x=0", "y=a+l"}, {{"Omega", Omega}});
    // z's rate stays a state: z'' = 0, a multiplier 1
    EXPECT_EQ(C.at_start.state, (std::vector<std::string>{"x", "der(x)", "der(z)"}));
    EXPECT_EQ(C.at_start.dependent_coordinates, (std::vector<std::string>{"y"}));
    EXPECT_EQ(C.at_start.ignorable, (std::vector<std::string>{"z"}));
    EXPECT_LT((C.monodromy.row(2) - Eigen::RowVector3d(0, 0, 1)).norm(), 1e-12);
    const FloquetAnalysis c = analyse_floquet(C);
    const FloquetAnalysis p = analyse_floquet(angle.at({"phi=0"}, {{"Omega", Omega}}));
    ASSERT_EQ(p.multipliers.size(), 2u);
    // the pendulum's two among the three
    const Eigen::MatrixXd pendulum = C.monodromy.topLeftCorner(2, 2);
    const Eigen::VectorXcd mu = test::eigenvalues(pendulum);
    for (const FloquetMultiplier& expected : p.multipliers) {
      EXPECT_LT(
          std::min(std::abs(mu[0] - expected.multiplier), std::abs(mu[1] - expected.multiplier)),
          1e-9);
    }
    EXPECT_EQ(c.verdict, p.verdict);
  }
}

// What is not a periodic motion, or not periodic, is refused with the reason.
TEST(Floquet, RefusesWhatIsNotPeriodic) {
  const auto model = [](const std::string& potential) {
    return Driven::text(
        "unidyn: 1\nname: test\nparameters: {k: 1}\ncoordinates: [x]\n"
        "particles:\n  P: {mass: 1, position: [x, 0, 0]}\nforces:\n"
        "  - potential: \"" +
        potential + "\"\n");
  };
  // t outside a trigonometric function
  const Driven growing = model("(k + t)*x^2/2");
  EXPECT_TRUE(growing.dependence.depends);
  EXPECT_NE(growing.dependence.not_periodic, "");
  EXPECT_THROW(
      drive_period(growing.system, growing.compiled, growing.dependence, growing.parameters({})),
      NotPeriodic);
  // incommensurate frequencies: quasi-periodic
  const Driven quasi = model("(k + cos(t) + cos(sqrt(2)*t))*x^2/2");
  EXPECT_EQ(quasi.dependence.not_periodic, "");
  EXPECT_THROW(drive_period(quasi.system, quasi.compiled, quasi.dependence, quasi.parameters({})),
               NotPeriodic);
  // commensurate ones: the fundamental, 2π/gcd
  const Driven both = model("(k + cos(4*t) + sin(6*t))*x^2/2");
  EXPECT_NEAR(
      drive_period(both.system, both.compiled, both.dependence, both.parameters({}))->period,
      std::numbers::pi, 1e-14);
  // a period given that the equations do not have, and one they have
  EXPECT_THROW(drive_period(both.system, both.compiled, both.dependence, both.parameters({}), 1.0),
               NotPeriodic);
  EXPECT_NO_THROW(drive_period(both.system, both.compiled, both.dependence, both.parameters({}),
                               2 * std::numbers::pi));
  // t that cancels (a hoop turning at a constant rate) is no dependence at all
  EXPECT_FALSE(Driven::bundled("rotating-hoop").dependence.depends);
  // a point the drive does not keep at rest: a pendulum whose pivot moves sideways
  const Driven sideways = Driven::text(R"(unidyn: 1
name: Sideways pivot
parameters: {g: 9.81, l: 0.2, a: 0.01, Omega: 30}
coordinates: [phi]
particles:
  P: {mass: 1, position: "[a*cos(Omega*t) + l*sin(phi), -l*cos(phi), 0]"}
forces:
  - gravity: -g*E2
)");
  try {
    sideways.at({"phi=0"});
    ADD_FAILURE() << "a point off every periodic motion was analysed";
  } catch (const NotAnOperatingPoint& e) {
    EXPECT_NE(std::string(e.what()).find("does not come back"), std::string::npos) << e.what();
  }
}

// linearize() itself never freezes t: at phi = 0 the driven pendulum's acceleration is 0 and
// ∂/∂t of it too at t = 0 (cos Ωt), but the equations differ at other instants.
TEST(Floquet, LinearizationRefusesEquationsThatChangeWithT) {
  const Driven p = Driven::bundled("driven-pendulum");
  const OperatingPoint point =
      operating_point(p.system, p.compiled, parse_given_values(p.system, {"phi=0"}),
                      p.parameters({{"Omega", 158}}));
  try {
    linearize(p.system, p.compiled, point);
    ADD_FAILURE() << "the driven pendulum was linearised at one instant";
  } catch (const NotAnOperatingPoint& e) {
    EXPECT_NE(std::string(e.what()).find("depend on t"), std::string::npos) << e.what();
  }
}

// A pivot moved by a crank turned at a constant rate, ψ − Ωt = 0: the equations have no t (e =
// −Ω), but ψ, on which they depend, moves with the point. The linearisation sees the point move
// and refuses; over the period 2π/Ω given (--period), the motion is periodic and its multipliers
// are those of the same pivot motion written with t (driven-pendulum, hanging: phase does not
// change multipliers).
TEST(Floquet, ACrankTurnedAtAConstantRateIsAnalysedOverItsPeriod) {
  const Driven crank = Driven::text(R"(unidyn: 1
name: Pendulum on a crank
parameters: {g: 9.81, l: 0.2, a: 0.01, Omega: 14}
coordinates: [psi, phi]
particles:
  P: {mass: 1, position: "[l*sin(phi), a*sin(psi) - l*cos(phi), 0]"}
forces:
  - gravity: -g*E2
constraints:
  - {name: crank, position: psi - Omega*t}
)");
  EXPECT_FALSE(crank.dependence.depends);
  const OperatingPoint point =
      operating_point(crank.system, crank.compiled, parse_given_values(crank.system, {"phi=0"}),
                      crank.parameters({}));
  try {
    linearize(crank.system, crank.compiled, point);
    ADD_FAILURE() << "the crank was frozen at psi = 0";
  } catch (const NotAnOperatingPoint& e) {
    EXPECT_NE(std::string(e.what()).find("the point moves"), std::string::npos) << e.what();
  }
  const FloquetAnalysis turning =
      analyse_floquet(crank.at({"phi=0"}, {}, 2 * std::numbers::pi / 14));
  const FloquetAnalysis driven =
      analyse_floquet(Driven::bundled("driven-pendulum").at({"phi=pi"}, {{"Omega", 14}}));
  ASSERT_EQ(turning.multipliers.size(), 2u);
  ASSERT_EQ(driven.multipliers.size(), 2u);
  EXPECT_EQ(turning.verdict, Stability::unstable);  // inside the first tongue
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_LT(std::abs(turning.multipliers[k].multiplier - driven.multipliers[k].multiplier), 1e-9);
  }
}

}  // namespace
}  // namespace unidyn
