#include "unidyn/kinematics/kinetic_energy.hpp"

#include "support/oracles.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

bool vanishes(const Expr& e) {
  return simplify(e).is_zero();
}

// T = ½ q̇ᵀ M q̇ + b · q̇ + T0 reproduces ½ Σ m v · v, for a rheonomic system (the bead on a hoop
// spinning at Ω: T1 = 0, T0 = ½ m R0² Ω² sin²φ, Ex. 3.7) and a scleronomic one
TEST(KineticEnergy, QuadraticFormReproducesT) {
  for (const char* text : {
           R"(unidyn: 1
parameters: {m: 0.5, R0: 2, Omega: 3}
coordinates: [phi]
particles:
  P: {mass: m, position: "R0*[sin(phi)*cos(Omega*t), sin(phi)*sin(Omega*t), cos(phi)]"}
)",
           R"(unidyn: 1
parameters: {m1: 1, m2: 2, l: 0.7}
coordinates: [x, theta]
particles:
  A: {mass: m1, position: [x, 0, 0]}
  B: {mass: m2, position: "[x + l*sin(theta), -l*cos(theta), 0]"}
)"}) {
    const System system = parse_model(text, "test.yaml");
    const KineticEnergyForm form = kinetic_energy_form(system);
    const auto& q = system.coordinates();
    Expr T = form.constant;
    for (std::size_t i = 0; i < q.size(); ++i) {
      T += form.linear[i] * q[i].rate;
      for (std::size_t k = 0; k < q.size(); ++k) {
        T += form.mass_matrix(i, k) * q[i].rate * q[k].rate / 2;
      }
    }
    EXPECT_TRUE(vanishes(T - system.kinetic_energy()));
  }
}

// Ex. 3.7: the hoop's T0 = ½ m R0² Ω² sin²φ and T1 = 0; M = m R0²
TEST(KineticEnergy, RotatingHoopParts) {
  const System system = parse_model(R"(unidyn: 1
parameters: {m: 0.5, R0: 2, Omega: 3}
coordinates: [phi]
particles:
  P: {mass: m, position: "R0*[sin(phi)*cos(Omega*t), sin(phi)*sin(Omega*t), cos(phi)]"}
)",
                                    "hoop.yaml");
  const KineticEnergyForm form = kinetic_energy_form(system);
  const Expr m = system.parameters[0].symbol, R0 = system.parameters[1].symbol,
             Omega = system.parameters[2].symbol;
  const Expr phi = system.coordinates()[0].value;
  EXPECT_TRUE(vanishes(form.mass_matrix(0, 0) - m * R0 * R0));
  EXPECT_TRUE(vanishes(form.linear[0]));
  EXPECT_TRUE(
      vanishes(form.constant - m * R0 * R0 * Omega * Omega * GiNaC::pow(GiNaC::sin(phi), 2) / 2));
}

// Bodies (Koenig, (10.12)): the rate gyroscope of §11.4, rheonomic through the platform's turn Ωt.
// By hand from ω_g = α̇ e1 + Ω (sin α e2 + cos α e3) and ω_r = ω_g + β̇ e2 (rotor axisymmetric about
// e2): M = diag(ρ1 + λ1, λ2), b = (0, λ2 Ω sin α),
// T0 = ½ Ω² ((ρ2 + λ2) sin²α + (ρ3 + λ1) cos²α).
TEST(KineticEnergy, RateGyroscopeParts) {
  const System system = parse_model(R"(unidyn: 1
parameters: {l1: 1, l2: 2, r1: 3, r2: 5, r3: 7, W: 0.5}
coordinates: [alpha, beta]
bodies:
  gimbal:
    mass: 1
    inertia: [r1, r2, r3]
    rotation: [{axis: [0, 0, 1], angle: W*t}, {axis: [1, 0, 0], angle: alpha}]
    center: [0, 0, 0]
  rotor:
    mass: 1
    inertia: [l1, l2, l1]
    rotation: [{axis: [0, 0, 1], angle: W*t}, {axis: [1, 0, 0], angle: alpha}, {axis: [0, 1, 0], angle: beta}]
    center: [0, 0, 0]
)",
                                    "gyro.yaml");
  const KineticEnergyForm form = kinetic_energy_form(system);
  const auto p = [&](const char* name) {
    return Expr(system.parameters[*system.find_parameter(name)].symbol);
  };
  const Expr alpha = system.coordinates()[0].value, W = p("W");
  const Expr s = GiNaC::sin(alpha), c = GiNaC::cos(alpha);
  EXPECT_TRUE(vanishes(form.mass_matrix(0, 0) - p("r1") - p("l1")));
  EXPECT_TRUE(vanishes(form.mass_matrix(1, 1) - p("l2")));
  EXPECT_TRUE(vanishes(form.mass_matrix(0, 1)));
  EXPECT_TRUE(vanishes(form.linear[0]));
  EXPECT_TRUE(vanishes(form.linear[1] - p("l2") * W * s));
  EXPECT_TRUE(vanishes(form.constant -
                       W * W * ((p("r2") + p("l2")) * s * s + (p("r3") + p("l1")) * c * c) / 2));
}

}  // namespace
}  // namespace unidyn
