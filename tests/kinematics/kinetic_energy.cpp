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

}  // namespace
}  // namespace unidyn
