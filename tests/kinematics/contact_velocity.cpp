// The velocity of a body's point of contact, v_P = v̄ + ω × π_P (book §8.3): the Griffin grinding
// mill of Ex. 8.10, a millstone in 3-1-3 angles {ψ, π − γ, φ} with x̄ = H e3 from the Cardan
// joint and π_P = −r (cos φ e2 + sin φ e1). Rolling (v_P = 0) needs γ̇ = 0 — v_P · e3 = r γ̇ —
// and φ̇ = (cos γ0 − (H/r) sin γ0) ψ̇ (d).
#include <gtest/gtest.h>

#include <cmath>

#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

TEST(ContactVelocity, GriffinMillRollsWhenItsSpinMatchesExercise810) {
  const System s = parse_model(R"yaml(unidyn: 1
parameters: {H: 0.5, r: 0.2}
coordinates: [psi, gamma, phi]
bodies:
  stone:
    mass: 1
    inertia: [1, 1, 1.5]
    rotation: {euler: 3-1-3, angles: [psi, pi - gamma, phi]}
    center: H*stone.e3
definitions:
  contact_velocity: "stone.velocity + cross(stone.omega, -r*(cos(phi)*stone.e2 + sin(phi)*stone.e1))"
outputs:
  v1: dot(contact_velocity, stone.e1)
  v2: dot(contact_velocity, stone.e2)
  v3: dot(contact_velocity, stone.e3)
)yaml",
                               "griffin-mill.yaml");
  ASSERT_EQ(s.outputs.size(), 3u);
  const double H = 0.5, r = 0.2;
  const auto& q = s.coordinates();
  for (const double gamma0 : {0.3, 0.9, 1.4}) {
    for (const double dpsi : {2.0, -7.5}) {
      for (const double dgamma : {0.0, 0.8}) {
        GiNaC::exmap at;
        for (const auto& p : s.parameters) at[p.symbol] = p.value;
        at[q[0].value] = 0.4;
        at[q[1].value] = gamma0;
        at[q[2].value] = -1.3;
        at[q[0].rate] = dpsi;
        at[q[1].rate] = dgamma;
        at[q[2].rate] = (std::cos(gamma0) - H / r * std::sin(gamma0)) * dpsi;
        const auto value = [&](std::size_t k) {
          return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(s.outputs[k].expression.subs(at)))
              .to_double();
        };
        EXPECT_NEAR(value(2), r * dgamma, 1e-13) << "v_P · e3 = r γ̇";
        if (dgamma == 0.0) {
          EXPECT_NEAR(value(0), 0, 1e-13);
          EXPECT_NEAR(value(1), 0, 1e-13);
        }
        // any other spin slips
        at[q[2].rate] = at[q[2].rate] + 0.5;
        EXPECT_GT(std::hypot(value(0), value(1)), 0.05);
      }
    }
  }
}

}  // namespace
}  // namespace unidyn
