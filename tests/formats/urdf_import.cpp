// URDF files imported as the model language (src/formats): what maps to what, line by line; every
// refusal at the file, line and column of its cause; the same bytes every time; and a pendulum
// whose mass matrix and gravity moment are computed here by hand, from the URDF's numbers alone.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/formats/urdf.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/symbolic/expression.hpp"

namespace unidyn {
namespace {

using formats::import_urdf;

// A robot of the given elements: <robot> is line 1, the elements start on line 2.
std::string robot(const std::string& elements) {
  return "<robot name=\"r\">\n" + elements + "</robot>\n";
}

bool has_line(const std::string& yaml, const std::string& line) {
  return ("\n" + yaml).find("\n" + line + "\n") != std::string::npos;
}

// The import refused with exactly this "file:line:column: message" beginning.
void expect_refused(const std::string& text, const std::string& expected) {
  try {
    import_urdf(text, "t.urdf");
    ADD_FAILURE() << "not refused; expected " << expected;
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, expected.size()), expected) << e.what();
  }
}

const std::string kLinkA = "  <link name=\"a\"/>\n";
std::string joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& inside = "") {
  return "  <joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/>" + inside + "</joint>\n";
}

TEST(UrdfImport, MapsLinksJointsInertiasAndVisuals) {
  const std::string text =
      robot("  <link name=\"base\"/>\n" +
            joint("j1", "revolute", "base", "arm",
                  "<origin xyz=\"0 0 0.5\" rpy=\"0 1e-1 0\"/><axis xyz=\"0 1 0\"/>"
                  "<dynamics damping=\"0.3\"/>") +
            "  <link name=\"arm\"><inertial><origin xyz=\"0 0 +0.25\"/><mass value=\"2\"/>"
            "<inertia ixx=\"0.02\" ixy=\"0\" ixz=\"0\" iyy=\"0.02\" iyz=\"0\" izz=\"0.001\"/>"
            "</inertial><visual><origin xyz=\"0 0 0.25\"/><geometry><box size=\"0.05 0.05 "
            "0.5\"/></geometry><material name=\"red\"><color rgba=\"1 0 0 1\"/></material></visual>"
            "</link>\n" +
            joint("slide", "prismatic", "arm", "tip", "<axis xyz=\"0 0 1\"/>") +
            "  <link name=\"tip\"><inertial><mass value=\"0.5\"/><inertia ixx=\"1e-4\" ixy=\"0\" "
            "ixz=\"0\" iyy=\"1e-4\" iyz=\"0\" izz=\"1e-4\"/></inertial></link>\n");
  const std::string yaml = import_urdf(text, "t.urdf").yaml;
  for (const char* line : {
           "unidyn: 1",
           "name: \"r\"",
           "description: \"Imported by unidyn from t.urdf (URDF)\"",
           "parameters: {g: 9.81}",
           "coordinates: [j1, slide]",
           "  base:",
           "    joint: {}  # the root link, fixed to the ground",
           "    mass: 0  # a frame: the link has no mass",
           "  arm:",
           "    joint: {parent: base, origin: [0, 0, 0.5], rpy: [0, 1e-1, 0], revolute: j1, "
           "axis: [0, 1, 0]}",
           "    mass: 2",
           "    inertia: {tensor: [[0.02, 0, 0], [0, 0.02, 0], [0, 0, 0.001]]}",
           "    center: arm.frame_point([0, 0, 0.25])",
           "    visual: {box: {a: 0.05, b: 0.05, c: 0.5}, color: \"#ff0000\"}",
           "  tip:",
           "    joint: {parent: arm, prismatic: slide, axis: [0, 0, 1]}",
           "    mass: 0.5",
           "  - gravity: -g*E3",
           "  - torsion_damper: {angle: j1, coefficient: 0.3}",
           "initial: {}",
           "simulate: {t_end: 5, output_step: 0.01}",
       }) {
    EXPECT_TRUE(has_line(yaml, line)) << "missing: " << line << "\nin:\n" << yaml;
  }
  // the model language reads it
  EXPECT_EQ(parse_model(yaml, "t.urdf (imported)").coordinates().size(), 2u);
}

TEST(UrdfImport, FloatingAndPlanarJointsTakeSuffixedCoordinates) {
  const std::string yaml =
      import_urdf(robot(kLinkA + joint("free", "floating", "a", "b") + "  <link name=\"b\"/>\n" +
                        joint("flat", "planar", "b", "c", "<axis xyz=\"0 0 -1\"/>") +
                        "  <link name=\"c\"/>\n"),
                  "t.urdf")
          .yaml;
  EXPECT_TRUE(has_line(yaml,
                       "coordinates: [free_x, free_y, free_z, free_e0, free_e1, free_e2, "
                       "free_e3, flat_x, flat_y, flat_theta]"))
      << yaml;
  EXPECT_TRUE(has_line(
      yaml,
      "    joint: {parent: a, floating: [free_x, free_y, free_z, free_e0, free_e1, free_e2, "
      "free_e3]}"));
  EXPECT_TRUE(has_line(yaml,
                       "    joint: {parent: b, planar: [flat_x, flat_y, flat_theta], axis: "
                       "[0, 0, -1]}"));
  EXPECT_TRUE(has_line(yaml, "initial: {free_e0: 1}"));
}

// Names that are not identifiers, reserved words and collisions are changed, with a note and a
// comment; the coordinates and bodies follow the tree depth-first, children in file order.
TEST(UrdfImport, ChangesNamesWithNotesAndKeepsDepthFirstOrder) {
  const std::string text = robot(
      "  <link name=\"base-link\"/>\n" + joint("t", "continuous", "base-link", "x") +
      "  <link name=\"x\"/>\n" + joint("second", "continuous", "base-link", "y") +
      "  <link name=\"y\"/>\n" + joint("x", "continuous", "x", "2nd") + "  <link name=\"2nd\"/>\n");
  const auto model = import_urdf(text, "t.urdf");
  EXPECT_TRUE(has_line(model.yaml, "coordinates: [t_, x_2, second]")) << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  base_link:  # link 'base-link' is named base_link in unidyn "
                       "(not a unidyn identifier)"))
      << model.yaml;
  EXPECT_LT(model.yaml.find("  _2nd:"), model.yaml.find("  y:"));
  ASSERT_GE(model.notes.size(), 4u);
  EXPECT_EQ(model.notes[0],
            "t.urdf:2:15: link 'base-link' is named base_link in unidyn (not a unidyn identifier)");
  EXPECT_EQ(model.notes[1],
            "t.urdf:3:16: joint 't' is named t_ in unidyn (not a unidyn identifier)");
  EXPECT_EQ(model.notes[2],
            "t.urdf:8:15: link '2nd' is named _2nd in unidyn (not a unidyn identifier)");
  EXPECT_EQ(model.notes[3],
            "t.urdf:7:16: joint 'x' is named x_2 in unidyn ('x' names something else)");
}

TEST(UrdfImport, NotesIgnoredElementsOnceEach) {
  const auto model = import_urdf(
      robot("  <mujoco><compiler fusestatic=\"false\"/></mujoco>\n"
            "  <link name=\"a\"><collision/><collision/></link>\n" +
            joint("j", "revolute", "a", "b", "<limit lower=\"-1\" upper=\"1\"/>") +
            "  <link name=\"b\"><visual><geometry><mesh filename=\"b.stl\"/></geometry></visual>"
            "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" "
            "iyz=\"0\" izz=\"1\"/></inertial></link>\n"
            "  <transmission name=\"tr\"/>\n"),
      "t.urdf");
  const std::vector<std::string> expected = {
      "t.urdf:5:18: <visual> not drawn: a mesh (b.stl); the link is drawn as its ellipsoid of "
      "inertia",
      "t.urdf:2:3: <mujoco> ignored",
      "t.urdf:6:3: <transmission> ignored",
      "t.urdf:3:18: <collision> ignored (2 in the file, the first here)",
      "t.urdf:4:70: <limit> not applied (--limits makes lower and upper two unilateral contacts)",
  };
  EXPECT_EQ(model.notes, expected);
}

// An inertia given on a turned <inertial> frame is written turned onto the link frame, R J Rᵀ
// (here a quarter turn about z exchanges the x and y moments), with a note and a comment.
TEST(UrdfImport, TurnsAnInertiaOntoTheLinkFrame) {
  const auto model =
      import_urdf(robot("  <link name=\"a\"><inertial><origin rpy=\"0 0 1.5707963267948966\"/>"
                        "<mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" "
                        "iyz=\"0\" izz=\"2.5\"/></inertial></link>\n"),
                  "t.urdf");
  const std::size_t at = model.yaml.find("inertia: {tensor: [[");
  ASSERT_NE(at, std::string::npos);
  const double ixx = std::stod(model.yaml.substr(at + 20));
  EXPECT_NEAR(ixx, 2, 1e-15);
  EXPECT_NE(model.yaml.find("    # the <inertia> on the <inertial> frame"), std::string::npos);
  ASSERT_EQ(model.notes.size(), 1u);
  EXPECT_EQ(model.notes[0].substr(0, 12), "t.urdf:2:41:");
}

TEST(UrdfImport, RefusesWithFileLineAndColumn) {
  expect_refused("<robot name=\"r\">\n  <link name=\"a\">\n  </robot>\n",
                 "t.urdf:2:3: malformed XML: XML_ERROR_MISMATCHED_ELEMENT");
  expect_refused(robot(kLinkA + joint("j", "hinge", "a", "b") + "  <link name=\"b\"/>\n"),
                 "t.urdf:3:25: unknown joint type 'hinge'");
  expect_refused(robot(kLinkA + joint("j", "fixed", "a", "nowhere")),
                 "t.urdf:3:63: no link is named 'nowhere'");
  expect_refused(robot(kLinkA + "  <link name=\"b\"/>\n"),
                 "t.urdf:3:3: several root links (no joint's child): a, b");
  expect_refused(robot(kLinkA + "  <link name=\"b\"/>\n  <link name=\"c\"/>\n" +
                       joint("ab", "fixed", "a", "b") + joint("cb", "fixed", "c", "b")),
                 "t.urdf:6:64: link 'b' is already the child of joint 'ab'");
  expect_refused(robot(kLinkA + "  <link name=\"b\"/>\n  <link name=\"c\"/>\n" +
                       joint("bc", "fixed", "b", "c") + joint("cb", "fixed", "c", "b")),
                 "t.urdf:6:3: joint 'cb' closes a cycle of links (b → c → b)");
  expect_refused(robot(kLinkA + joint("j", "revolute", "a", "b", "<origin xyz=\"0 0.1x 0\"/>") +
                       "  <link name=\"b\"/>\n"),
                 "t.urdf:3:85: origin xyz: '0.1x' is not a finite decimal number");
  expect_refused(robot("  <link name=\"a\"><inertial><mass value=\"-1\"/></inertial></link>\n"),
                 "t.urdf:2:41: a mass must be positive or 0");
  expect_refused(robot("  <link name=\"a\"><inertial><mass value=\"1\"/>\n"
                       "    <inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"3\"/>"
                       "</inertial></link>\n"),
                 "t.urdf:3:5: no body has this inertia: a principal moment exceeds the sum");
  expect_refused(robot(kLinkA + joint("j", "revolute", "a", "b", "<mimic joint=\"k\"/>") +
                       "  <link name=\"b\"/>\n"),
                 "t.urdf:3:70: <mimic> is not supported");
  expect_refused(robot(kLinkA + joint("j", "floating", "a", "b", "<dynamics damping=\"1\"/>") +
                       "  <link name=\"b\"/>\n"),
                 "t.urdf:3:89: joint damping on a floating joint is not supported yet");
  expect_refused(robot(kLinkA + joint("j", "revolute", "a", "b", "<axis xyz=\"0 0 0\"/>") +
                       "  <link name=\"b\"/>\n"),
                 "t.urdf:3:81: a joint's axis must not be zero");
  expect_refused(robot("  <link name=\"a\"><inertial><mass value=\"nan\"/></inertial></link>\n"),
                 "t.urdf:2:41: mass value: 'nan' is not a finite decimal number");
}

TEST(UrdfImport, TheSameTextGivesTheSameBytes) {
  const std::string text =
      robot(kLinkA + joint("j", "revolute", "a", "b", "<axis xyz=\"0 1 0\"/>") +
            "  <link name=\"b\"><inertial><origin rpy=\"0.1 0.2 0.3\"/><mass "
            "value=\"1\"/><inertia ixx=\"1\" ixy=\"0.1\" ixz=\"0\" iyy=\"1\" "
            "iyz=\"0\" izz=\"1\"/></inertial></link>\n");
  const auto first = import_urdf(text, "t.urdf");
  for (int k = 0; k < 3; ++k) {
    const auto again = import_urdf(text, "t.urdf");
    EXPECT_EQ(again.yaml, first.yaml);
    EXPECT_EQ(again.notes, first.notes);
  }
}

// The rotations of URDF's rpy written out here, not taken from unidyn or Eigen's geometry.
Eigen::Matrix3d about_x(double a) {
  Eigen::Matrix3d R;
  R << 1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a);
  return R;
}
Eigen::Matrix3d about_y(double a) {
  Eigen::Matrix3d R;
  R << std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a);
  return R;
}
Eigen::Matrix3d about_z(double a) {
  Eigen::Matrix3d R;
  R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
  return R;
}
// URDF: roll r about x, then pitch p about y, then yaw y about z, all fixed axes.
Eigen::Matrix3d rpy(double r, double p, double y) {
  return about_z(y) * about_y(p) * about_x(r);
}

// A pendulum from a URDF: a bob of mass m on a revolute joint about the joint frame's y axis, the
// joint frame turned by rpy (0.3, -0.4, 0.7) on the support, the bob's centre of mass at c on its
// link frame and its inertia J given on an <inertial> frame turned by rpy (0.2, 0.1, -0.3). By
// hand: the axis a = R0 E2, the centre r = Q c from the joint with Q = R0 Ry(q); the kinetic
// energy ½ (a·Q J' Qᵀ a + m |a × r|²) q̇² with J' = Ri J Riᵀ gives M; the potential m g E3·r gives
// f = −m g E3·(a × r) (M is constant: no rate terms).
TEST(UrdfImport, PendulumMassMatrixAndGravityMomentAgreeWithHandComputation) {
  const std::string text = R"(<robot name="pendulum">
  <link name="support"/>
  <joint name="swing" type="revolute">
    <parent link="support"/>
    <child link="bob"/>
    <origin xyz="0.1 -0.2 1.5" rpy="0.3 -0.4 0.7"/>
    <axis xyz="0 1 0"/>
  </joint>
  <link name="bob">
    <inertial>
      <origin xyz="0.05 0.02 -0.6" rpy="0.2 0.1 -0.3"/>
      <mass value="1.7"/>
      <inertia ixx="0.03" ixy="0.002" ixz="-0.001" iyy="0.025" iyz="0.003" izz="0.012"/>
    </inertial>
  </link>
</robot>
)";
  const double m = 1.7, g = 9.81;
  const Eigen::Vector3d c(0.05, 0.02, -0.6);
  Eigen::Matrix3d J;
  J << 0.03, 0.002, -0.001, 0.002, 0.025, 0.003, -0.001, 0.003, 0.012;
  const Eigen::Matrix3d R0 = rpy(0.3, -0.4, 0.7), Ri = rpy(0.2, 0.1, -0.3);
  const Eigen::Matrix3d J_link = Ri * J * Ri.transpose();

  const System system = parse_model(import_urdf(text, "pendulum.urdf").yaml, "pendulum (imported)");
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(system, {}).parameters;
  for (const double q : {0.0, 0.4, -1.3, 2.9}) {
    const Eigen::Matrix3d Q = R0 * about_y(q);
    const Eigen::Vector3d a = R0 * Eigen::Vector3d::UnitY(), r = Q * c;
    const double M = a.dot(Q * J_link * Q.transpose() * a) + m * a.cross(r).squaredNorm();
    const double f = -m * g * Eigen::Vector3d::UnitZ().dot(a.cross(r));
    Eigen::VectorXd qddot, lambda;
    const Eigen::VectorXd at = Eigen::VectorXd::Constant(1, q), rate = 0.7 - at.array();
    compiled.solve(0, at, rate, parameters, qddot, lambda, data);
    EXPECT_NEAR(qddot[0], f / M, 1e-12 * std::abs(f / M) + 1e-15) << "q = " << q;
    compiled.mass_and_forcing(0, at, rate, parameters, data);
    EXPECT_NEAR(data.mass_matrix(0, 0), M, 1e-13 * M) << "q = " << q;
    EXPECT_NEAR(data.forcing(0), f, 1e-12 * m * g * r.norm()) << "q = " << q;
  }
}

}  // namespace
}  // namespace unidyn
