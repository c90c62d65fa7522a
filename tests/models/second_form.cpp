// Lagrange's equations in the second form (10.16): partial angular velocities are the Euler basis
// (10.6), and the generalised forces from the load vectors are those from the potentials (8.27),
// (10.7) plus the non-conservative ones, for every bundled model.
#include <filesystem>

#include "support/model_run.hpp"
#include "unidyn/equations/second_form.hpp"
#include "unidyn/rotation/euler_angles.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

double number(const Expr& e, const GiNaC::exmap& state) {
  return GiNaC::ex_to<GiNaC::numeric>(GiNaC::evalf(e.subs(state))).to_double();
}

SecondForm second_form(const System& system) {
  return lagrange_second_form(system, newton_equations(system), lagrange_equations(system));
}

// (10.6): ∂ω/∂ψ̇, ∂ω/∂θ̇, ∂ω/∂φ̇ of the 3-1-3 top are g_1, g_2, g_3 of the rotation layer.
TEST(SecondForm, PartialAngularVelocitiesAreTheEulerBasis) {
  const System system = load_model(test::model_path("heavy-top"));
  const SecondForm form = second_form(system);
  GiNaC::exmap state = system.parameter_values();
  const Vec3 angles(0.4, 1.1, -2.0);
  for (std::size_t i = 0; i < 3; ++i) state[system.coordinates()[i].value] = angles[int(i)];
  const Tensor g = euler_basis(*EulerSet::parse("3-1-3"), angles);
  for (std::size_t A = 0; A < 3; ++A) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_NEAR(number(form.angular_velocity[A][0][k], state), g(k, int(A)), 1e-15);
    }
  }
}

// The gyroscope's spring and damper act on α alone: Φ_α = −(K α + c α̇) A, Φ_β = 0.
TEST(SecondForm, RateGyroscopeGeneralisedForces) {
  const System system = load_model(test::model_path("rate-gyroscope"));
  const SecondForm form = second_form(system);
  const auto p = [&](const char* name) {
    return Expr(system.parameters[*system.find_parameter(name)].symbol);
  };
  const auto& alpha = system.coordinates()[0];
  EXPECT_TRUE(
      simplify(form.generalized_force[0] + (p("K") * alpha.value + p("c") * alpha.rate) * p("A"))
          .is_zero());
  EXPECT_TRUE(simplify(form.generalized_force[1]).is_zero());
}

// Every bundled model: Φ_A from the vectors = −∂U/∂u^A + Φ_A of the non-conservative loads, at
// random states.
TEST(SecondForm, LoadVectorsMatchPotentialsInEveryModel) {
  int models = 0;
  for (const auto& entry : std::filesystem::directory_iterator(UNIDYN_MODELS_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    const System system = load_model(entry.path().string());
    const EquationsOfMotion eq = lagrange_equations(system);
    const SecondForm form = lagrange_second_form(system, newton_equations(system), eq);
    const auto& q = system.coordinates();
    GiNaC::exmap state = system.parameter_values();
    double value = 0.2;
    state[system.time()] = 0.3;
    for (const auto& c : q) {
      state[c.value] = value += 0.13;
      state[c.rate] = value - 0.9;
    }
    for (std::size_t A = 0; A < q.size(); ++A) {
      const double from_vectors = number(form.generalized_force[A], state);
      const double from_potential =
          number(eq.generalized_force[A] - eq.potential_energy.diff(q[A].value), state);
      EXPECT_NEAR(from_vectors, from_potential, 1e-9 * (1 + std::abs(from_potential)))
          << entry.path().stem() << " " << q[A].name;
    }
    ++models;
  }
  EXPECT_GT(models, 20);
}

}  // namespace
}  // namespace unidyn
