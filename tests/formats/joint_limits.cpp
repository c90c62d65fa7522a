// Joint limits on request (--limits, formats::ImportOptions): a URDF <limit lower upper> and an
// MJCF limited joint's range become two unilateral contacts Q_lower: Q − lower ≥ 0 and Q_upper:
// upper − Q ≥ 0 without rebound. Checked against a pendulum released horizontally onto its stop,
// in closed form and by a quadrature written here:
//
//   energy: ½ I_O θ̇² = m g l sin θ, so it reaches the stop θ* at t* = ∫₀^θ* dθ / √(k sin θ),
//   k = 2 m g l / I_O (θ = u²: t* = ∫₀^√θ* 2u du / √(k sin u²), a smooth integrand);
//   the stop takes all of ½ I_O θ̇*² (restitution 0) and then holds it: λ = m g l cos θ*.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "support/model_run.hpp"
#include "unidyn/commands/model_source.hpp"
#include "unidyn/formats/mjcf.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/io/model_file.hpp"

namespace unidyn {
namespace {

constexpr double m = 2, l = 0.5, I_c = 0.1, g = 9.81;
const formats::ImportOptions kLimits{true};

// A rod hinged at one end about E2 (its centre at l on the link's x axis, horizontal at θ = 0),
// stopped at `lower` and `upper`.
std::string stopped_pendulum(const std::string& lower, const std::string& upper) {
  return "<robot name=\"stopped\">\n  <link name=\"base\"/>\n"
         "  <link name=\"rod\"><inertial><origin xyz=\"0.5 0 0\"/><mass value=\"2\"/>"
         "<inertia ixx=\"0.001\" iyy=\"0.1\" izz=\"0.1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/>"
         "</inertial></link>\n"
         "  <joint name=\"swing\" type=\"revolute\"><parent link=\"base\"/><child link=\"rod\"/>"
         "<axis xyz=\"0 1 0\"/><limit lower=\"" +
         lower + "\" upper=\"" + upper + "\" effort=\"10\" velocity=\"3\"/></joint>\n</robot>\n";
}

// The time to fall from θ = 0 (at rest) to θ*, by Simpson's rule in u = √θ.
double time_to(double theta_stop) {
  const double k = 2 * m * g * l / (I_c + m * l * l);
  const auto integrand = [&](double u) {
    return u == 0 ? 2 / std::sqrt(k) : 2 * u / std::sqrt(k * std::sin(u * u));
  };
  const int n = 20000;
  const double b = std::sqrt(theta_stop), h = b / n;
  double sum = integrand(0) + integrand(b);
  for (int i = 1; i < n; ++i) sum += (i % 2 ? 4 : 2) * integrand(i * h);
  return sum * h / 3;
}

// Released at rest, horizontal: it stops at θ* at t*, loses ½ I_O θ̇*², and is held there.
void expect_stopped_at(const test::ModelRun& run, double theta_stop) {
  ASSERT_TRUE(run.summary.ok) << run.summary.message;
  const auto& phases = run.summary.phases;
  ASSERT_EQ(phases.size(), 3u);
  EXPECT_EQ(phases[0].what, "'swing_lower' free");
  EXPECT_EQ(phases[2].what.substr(0, 30), "contact 'swing_upper' made (ap");
  const double t_stop = time_to(theta_stop);
  EXPECT_NEAR(phases[2].t, t_stop, 1e-9);
  // all the kinetic energy taken at the stop: E = V(θ*) = −m g l sin θ* after it
  EXPECT_NEAR(run.summary.energy_final, -m * g * l * std::sin(theta_stop), 1e-9);
  for (std::size_t i = 0; i < run.rows.size(); ++i) {
    if (run.at(i, "t") <= t_stop) continue;
    EXPECT_NEAR(run.at(i, "swing"), theta_stop, 1e-12);
    EXPECT_NEAR(run.at(i, "der(swing)"), 0, 1e-12);
    EXPECT_NEAR(run.at(i, "lambda(swing_upper)"), m * g * l * std::cos(theta_stop), 1e-9);
    EXPECT_EQ(run.at(i, "lambda(swing_lower)"), 0);
  }
}

test::ModelRun run_imported(const formats::ImportedModel& model) {
  return test::run_system(parse_model(model.yaml, "t (imported)"), {},
                          [](SimulationOptions& o) { o.t_end = 1.5; });
}

TEST(JointLimits, UrdfLimitsAreTwoContacts) {
  const auto model = formats::import_urdf(stopped_pendulum("-0.5", "1"), "t.urdf", kLimits);
  EXPECT_NE(model.yaml.find("  - name: swing_lower\n    position: swing - (-0.5)\n"
                            "    unilateral: true\n"
                            "  - name: swing_upper\n    position: (1) - swing\n"
                            "    unilateral: true\n"),
            std::string::npos)
      << model.yaml;
  ASSERT_EQ(model.notes.size(), 1u);
  EXPECT_EQ(model.notes[0],
            "t.urdf:4:98: <limit> lower and upper made two unilateral contacts, Q_lower and "
            "Q_upper of the joint's coordinate Q (--limits, no rebound); effort and velocity "
            "not applied");
  expect_stopped_at(run_imported(model), 1.0);
  // without --limits: noted, not applied
  const auto free = formats::import_urdf(stopped_pendulum("-0.5", "1"), "t.urdf");
  EXPECT_EQ(free.yaml.find("constraints:"), std::string::npos);
  EXPECT_EQ(free.notes[0],
            "t.urdf:4:98: <limit> not applied (--limits makes lower and upper two unilateral "
            "contacts)");
}

// MJCF: a limited hinge's range in degrees (<compiler angle> default), and autolimits.
TEST(JointLimits, MjcfRangeIsTwoContactsInItsUnit) {
  const auto mjcf = [](const std::string& compiler, const std::string& limited) {
    return "<mujoco>" + compiler +
           "<worldbody><body name=\"rod\"><joint name=\"swing\" axis=\"0 1 0\" range=\"-30 30\"" +
           limited +
           "/><inertial pos=\"0.5 0 0\" mass=\"2\" diaginertia=\"0.001 0.1 0.1\"/></body>"
           "</worldbody></mujoco>\n";
  };
  const auto model = formats::import_mjcf(mjcf("", " limited=\"true\""), "t.xml", kLimits);
  EXPECT_NE(model.yaml.find("    position: swing - (-30*deg)\n    unilateral: true\n"),
            std::string::npos)
      << model.yaml;
  expect_stopped_at(run_imported(model), std::numbers::pi / 6);
  const auto automatic =
      formats::import_mjcf(mjcf("<compiler autolimits=\"true\"/>", ""), "t.xml", kLimits);
  EXPECT_NE(automatic.yaml.find("swing - (-30*deg)"), std::string::npos) << automatic.yaml;
  // not limited: noted, not applied
  for (const auto& text :
       {mjcf("", ""), mjcf("<compiler autolimits=\"true\"/>", " limited=\"false\"")}) {
    const auto unlimited = formats::import_mjcf(text, "t.xml", kLimits);
    EXPECT_EQ(unlimited.yaml.find("constraints:"), std::string::npos) << unlimited.yaml;
  }
}

TEST(JointLimits, RefusedWhereTheyCannotBeContacts) {
  const auto refused = [](const auto& import, const std::string& expected) {
    try {
      import();
      ADD_FAILURE() << "not refused; expected " << expected;
    } catch (const ModelError& e) {
      EXPECT_EQ(std::string(e.what()), expected);
    }
  };
  refused([] { formats::import_urdf(stopped_pendulum("1", "1"), "t.urdf", kLimits); },
          "t.urdf:4:98: --limits: lower 1 is not below upper 1 (a joint held at one value is a "
          "fixed joint)");
  refused(
      [] {
        formats::import_mjcf(
            "<mujoco><worldbody><body><joint type=\"ball\" limited=\"true\" "
            "range=\"0 40\"/></body></worldbody></mujoco>",
            "t.xml", kLimits);
      },
      "t.xml:1:67: --limits: a ball joint's range is not supported yet");
  // a model of the model language writes its limits itself
  EXPECT_THROW(commands::load_named_model("double-pendulum", kLimits), std::invalid_argument);
}

}  // namespace
}  // namespace unidyn
