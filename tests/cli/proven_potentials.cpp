// "Conservative" means one thing in every command: a `moment:` (or `force:`) given without a
// potential whose potential `derive` proves (its curl is 0, U integrated in closed form) is in
// the energy column of `simulate`, keeps it constant, and is accepted by the symplectic methods.
// Oracle: a wheel on a fixed axis under a constant moment M0, J θ'' = M0, so
//   θ(t) = θ0 + ω0 t + ½ (M0/J) t²,   E = ½ J θ'² − M0 θ constant,
// both written here from the closed form, not taken from unidyn.
#include <cmath>
#include <string>

#include "cli_support.hpp"

namespace unidyn {
namespace {

using namespace cli_test;

constexpr double kJ = 2.0, kM0 = 0.5, kOmega0 = 0.3;

std::string wheel_model() {
  const std::string path = temp_path("wheel.yaml");
  write_file(path,
             "unidyn: 1\nname: Wheel under a constant moment\nparameters: {J: 2.0, M0: 0.5}\n"
             "coordinates: [theta]\nbodies:\n"
             "  wheel: {mass: 1, inertia: [1, 1, J], rotation: {axis: [0, 0, 1], angle: theta}, "
             "center: [0, 0, 0]}\n"
             "forces:\n  - moment: {on: wheel, value: M0*E3}\n"
             "initial: {der(theta): 0.3}\nsimulate: {t_end: 2, output_step: 0.1, rtol: 1e-12}\n");
  return path;
}

double theta_at(double t) {
  return kOmega0 * t + 0.5 * (kM0 / kJ) * t * t;
}

TEST(ProvenPotentials, DeriveSaysTheMomentIsConservative) {
  const Outcome r = run("derive '" + wheel_model() + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "moment (line 8) is conservative: U = ")) << r.out;
  EXPECT_TRUE(contains(r.out, "(in the energy and in -dU/dq)")) << r.out;
}

// The energy column holds ½ J θ'² − M0 θ, constant, and the summary says where U came from.
TEST(ProvenPotentials, SimulateCountsItsPotentialInTheEnergy) {
  const std::string csv = temp_path("wheel.csv");
  const Outcome r = run("simulate '" + wheel_model() + "' -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_TRUE(contains(r.out, "U of moment (line 8) found by unidyn")) << r.out;
  EXPECT_TRUE(contains(r.out, "energy: initial")) << r.out;
  const Csv rows = parse_csv(read_file(csv));
  ASSERT_EQ(rows.rows.size(), 21u);
  const double e0 = 0.5 * kJ * kOmega0 * kOmega0;
  for (std::size_t k = 0; k < rows.rows.size(); ++k) {
    const double t = rows.at(k, "t"), theta = rows.at(k, "theta"), rate = rows.at(k, "der(theta)");
    EXPECT_NEAR(theta, theta_at(t), 1e-10) << t;
    EXPECT_NEAR(rows.at(k, "energy"), 0.5 * kJ * rate * rate - kM0 * theta, 1e-12) << t;
    EXPECT_NEAR(rows.at(k, "energy"), e0, 1e-10) << t;
  }
}

// RATTLE takes the model (a natural system: T quadratic, U(θ)); with θ'' constant, Störmer–Verlet
// is exact, so θ(2) is the closed form's to rounding.
TEST(ProvenPotentials, SymplecticMethodsAcceptIt) {
  const std::string csv = temp_path("wheel-rattle.csv");
  const Outcome r = run("simulate '" + wheel_model() + "' --method rattle -o '" + csv + "'");
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const Csv rows = parse_csv(read_file(csv));
  ASSERT_FALSE(rows.rows.empty());
  const std::size_t last = rows.rows.size() - 1;
  EXPECT_NEAR(rows.at(last, "t"), 2.0, 1e-12);
  EXPECT_NEAR(rows.at(last, "theta"), theta_at(2.0), 1e-11);
}

}  // namespace
}  // namespace unidyn
