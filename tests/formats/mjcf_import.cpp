// MJCF files imported as the model language (src/formats/mjcf*.cpp): what maps to what, line by
// line; refusals at the file, line and column of their cause; notes; and a free body whose
// acceleration is computed here by hand.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <string>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/formats/mjcf.hpp"
#include "unidyn/integrate/simulation.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"
#include "unidyn/symbolic/expression.hpp"

namespace unidyn {
namespace {

using formats::import_mjcf;

// A model of the given <worldbody> contents: <mujoco> is line 1, <worldbody> line 2, the
// contents start on line 3.
std::string world(const std::string& bodies, const std::string& before = "") {
  return "<mujoco model=\"m\">" + before + "\n<worldbody>\n" + bodies + "</worldbody>\n</mujoco>\n";
}

bool has_line(const std::string& yaml, const std::string& line) {
  return ("\n" + yaml).find("\n" + line + "\n") != std::string::npos;
}

void expect_refused(const std::string& text, const std::string& expected) {
  try {
    import_mjcf(text, "t.xml");
    ADD_FAILURE() << "not refused; expected " << expected;
  } catch (const ModelError& e) {
    EXPECT_EQ(std::string(e.what()).substr(0, expected.size()), expected) << e.what();
  }
}

const std::string kInertial = "<inertial pos=\"0 0 0\" mass=\"1\" diaginertia=\"0.1 0.1 0.1\"/>";

TEST(MjcfImport, MapsBodiesJointsInertialsAndGravity) {
  const std::string text = world(
      "  <body name=\"torso\" pos=\"0 0 1.5\">\n"
      "    <freejoint name=\"root\"/>\n"
      "    <inertial pos=\"0 0 0.1\" mass=\"4\" diaginertia=\"0.1 0.2 0.3\"/>\n"
      "    <body name=\"head\" pos=\"0 0 0.4\">\n"
      "      <joint name=\"neck\" type=\"ball\"/>\n"
      "      " +
          kInertial +
          "\n"
          "      <body name=\"jaw\" euler=\"0 0 90\">\n"
          "        <joint name=\"chew\" axis=\"1 0 0\" damping=\"0.2\"/>\n"
          "        <inertial pos=\"0.1 0 0\" quat=\"0 0 0 1\" mass=\"0.3\" "
          "fullinertia=\"0.01 0.02 0.02 0.001 0.002 0\"/>\n"
          "      </body>\n"
          "    </body>\n"
          "  </body>\n",
      "<option gravity=\"0 0 -9.8\"/>");
  const auto model = import_mjcf(text, "t.xml");
  for (const char* line : {
           "name: \"m\"",
           "description: \"Imported by unidyn from t.xml (MJCF)\"",
           "parameters: {g: 9.8}",
           "coordinates: [root_x, root_y, root_z, root_e0, root_e1, root_e2, root_e3, neck_e0, "
           "neck_e1, neck_e2, neck_e3, chew]",
           "  torso:",
           "    joint: {floating: [root_x, root_y, root_z, root_e0, root_e1, root_e2, root_e3]}",
           "    mass: 4",
           "    inertia: [0.1, 0.2, 0.3]",
           "    center: torso.frame_point([0, 0, 0.1])",
           "    joint: {parent: torso, origin: [0, 0, 0.4], ball: [neck_e0, neck_e1, neck_e2, "
           "neck_e3]}",
           "    joint: {parent: head, rotation: {axis: [0, 0, 1], angle: 90*deg}, revolute: chew, "
           "axis: [1, 0, 0]}",
           "    inertia: {tensor: [[0.01, 0.001, -0.002], [0.001, 0.02, 0], [-0.002, 0, 0.02]]}",
           "  - gravity: -g*E3",
           "  - torsion_damper: {angle: chew, coefficient: 0.2}",
           "initial: {root_z: 1.5, root_e0: 1, neck_e0: 1}",
       }) {
    EXPECT_TRUE(has_line(model.yaml, line)) << "missing: " << line << "\nin:\n" << model.yaml;
  }
  ASSERT_EQ(model.notes.size(), 1u);
  EXPECT_EQ(model.notes[0],
            "t.xml:11:72: the fullinertia on the turned <inertial> frame turned onto the body "
            "frame: R J R^T");
}

TEST(MjcfImport, NotesUnnamedJointsContactsAndIgnoredElements) {
  const std::string text =
      "<mujoco>\n<worldbody>\n  <geom type=\"plane\" size=\"1 1 1\"/>\n"
      "  <body>\n    <joint/>\n    " +
      kInertial +
      "\n  </body>\n</worldbody>\n<actuator><motor joint=\"joint0\"/></actuator>\n"
      "<sensor/>\n</mujoco>\n";
  const auto model = import_mjcf(text, "t.xml");
  EXPECT_TRUE(has_line(model.yaml, "coordinates: [joint0]")) << model.yaml;
  EXPECT_TRUE(has_line(model.yaml, "name: \"MuJoCo Model\"")) << model.yaml;
  ASSERT_EQ(model.notes.size(), 6u);
  EXPECT_EQ(model.notes[0],
            "t.xml:1:1: contacts between geoms are not modelled (the file's geoms collide in "
            "MuJoCo: contype and conaffinity are on)");
  EXPECT_EQ(model.notes[1], "t.xml:4:3: an unnamed body is named body1 (its MuJoCo id)");
  EXPECT_EQ(model.notes[2], "t.xml:5:5: an unnamed joint is named joint0 (its MuJoCo id)");
  EXPECT_EQ(model.notes[3],
            "t.xml:9:1: <actuator> ignored: it does not change the passive dynamics");
  EXPECT_EQ(model.notes[5], "t.xml:3:3: <geom> ignored");
}

TEST(MjcfImport, RefusesWithFileLineAndColumn) {
  expect_refused(world("  <body pos=\"0 0 1x\"/>\n"),
                 "t.xml:3:18: body pos: '1x' is not a finite decimal number");
  expect_refused(world("  <body><joint type=\"hinj\"/>" + kInertial + "</body>\n"),
                 "t.xml:3:22: unknown joint type 'hinj' (expected hinge, slide, ball or free)");
  expect_refused(world("  <body><geom type=\"plane\" size=\"0.1 0.2 1\"/></body>\n"),
                 "t.xml:3:21: a body's inertia from a plane geom is not supported yet");
  expect_refused(world("  <body><geom size=\"0.1\"/><geom size=\"0.2\"/></body>\n"),
                 "t.xml:3:27: a body's inertia from several geoms is not supported yet");
  expect_refused(world("  <body><body><freejoint/>" + kInertial + "</body></body>\n"),
                 "t.xml:3:15: a free joint moves a body of <worldbody> only");
  expect_refused(world("  <body euler=\"0 0 1\"/>\n", "<compiler eulerseq=\"zyx\"/>"),
                 "t.xml:1:39: only eulerseq=\"xyz\" (MuJoCo's default) is supported yet");
  // (found by the fuzzer: a geom's size read where it was missing)
  expect_refused(world("  <body><geom type=\"sphere\"/></body>\n"),
                 "t.xml:3:9: <geom> needs size=\"...\"");
  expect_refused(world("  <body name=\"a\"/>\n", "<equality><tendon tendon1=\"a\"/></equality>"),
                 "t.xml:1:29: <tendon> equality constraints are not supported yet (<connect>, "
                 "<weld> and <joint> are)");
  expect_refused(
      world("  <body name=\"a\"/>\n", "<equality><weld body1=\"a\" body2=\"a\"/></equality>"),
      "t.xml:1:29: a <weld> joins two different bodies (one may be the world)");
  expect_refused(world("  <body name=\"a\"/>\n", "<equality><weld body2=\"a\"/></equality>"),
                 "t.xml:1:29: <weld> needs body1=\"...\"");
  expect_refused(
      world("  <body/>\n", "<equality><connect body1=\"b\" anchor=\"0 0 0\"/></equality>"),
      "t.xml:1:45: no body named 'b' in <worldbody>");
  expect_refused(world("  <body name=\"a\"/>\n",
                       "<equality><connect body1=\"a\" body2=\"a\" "
                       "anchor=\"0 0 0\"/></equality>"),
                 "t.xml:1:29: a <connect> joins two different bodies");
  expect_refused(world("  <body name=\"a\"/>\n", "<equality><connect body1=\"a\"/></equality>"),
                 "t.xml:1:29: <connect> needs anchor=");
  expect_refused(
      world("  <body><joint name=\"s\" type=\"ball\"/>" + kInertial + "</body>\n",
            "<equality><joint joint1=\"s\"/></equality>"),
      "t.xml:1:44: a <joint> equality couples hinge and slide joints (this one is ball)");
  expect_refused(world("  <body/>\n", "<default><default/></default>"),
                 "t.xml:1:28: a nested <default> needs class=\"...\"");
  expect_refused(world("  <body/>\n", "<default/><default/>"),
                 "t.xml:1:29: <mujoco> has one top <default>");
  expect_refused(
      world("  <body/>\n", "<default><default class=\"a\"/><default class=\"a\"/></default>"),
      "t.xml:1:64: class 'a' is defined twice");
  // an attribute a class gives is refused where the <default> writes it
  expect_refused(world("  <body><joint/>" + kInertial + "</body>\n",
                       "<default><joint axis=\"0 x 1\"/></default>"),
                 "t.xml:1:43: joint axis: 'x' is not a finite decimal number");
  expect_refused(world("  <include file=\"other.xml\"/>\n"),
                 "t.xml:3:3: <include> is not supported: unidyn reads one file");
  expect_refused(world("  <body childclass=\"arm\"/>\n"),
                 "t.xml:3:21: class 'arm' is not defined in <default>");
  expect_refused(world("  <body><joint class=\"leg\"/>" + kInertial + "</body>\n"),
                 "t.xml:3:23: class 'leg' is not defined in <default>");
  expect_refused(world("  <body><joint stiffness=\"2\"/>" + kInertial + "</body>\n"),
                 "t.xml:3:27: joint stiffness is not supported yet");
  expect_refused(world("  <body><joint type=\"ball\" damping=\"1\"/>" + kInertial + "</body>\n"),
                 "t.xml:3:37: joint damping on a ball joint is not supported yet");
  expect_refused("<robot name=\"r\"/>\n", "t.xml:1:1: expected <mujoco>, found <robot>");
}

// <equality>: a <connect> to another body (its point on that body where body1's anchor is at
// qpos0, computed and said) and to the ground, a <joint> coupling, an inactive one left out.
TEST(MjcfImport, EqualitiesAsPositionConstraints) {
  const std::string text = world(
      "  <body name=\"a\" pos=\"0 0 1\"><joint name=\"qa\"/>" + kInertial +
          "</body>\n"
          "  <body name=\"b\" pos=\"1 2 0\"><joint name=\"qb\" type=\"slide\"/>" +
          kInertial + "</body>\n",
      "<equality>\n"
      "  <connect name=\"loop\" body1=\"a\" body2=\"b\" anchor=\"0.5 0 0\" solref=\"0.01 1\"/>\n"
      "  <connect body1=\"a\" anchor=\"0 0 -1\"/>\n"
      "  <joint name=\"gear\" joint1=\"qb\" joint2=\"qa\" polycoef=\"0.1 -2 0 0 0.5\"/>\n"
      "  <joint joint1=\"qa\" active=\"false\"/>\n"
      "</equality>");
  const auto model = import_mjcf(text, "t.xml");
  const std::string loop = "dot(a.frame_point([0.5, 0, 0]) - b.frame_point([-0.5, -2, 1]), E";
  EXPECT_TRUE(has_line(model.yaml, "  - name: loop_1\n    position: " + loop + "1)")) << model.yaml;
  EXPECT_TRUE(has_line(model.yaml, "  - name: loop_3\n    position: " + loop + "3)")) << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: equality1_2\n    position: dot(a.frame_point([0, "
                       "0, -1]) - [0, 0, 0], E2)"))
      << model.yaml;
  EXPECT_TRUE(has_line(model.yaml, "  - name: gear\n    position: qb - (0.1 + (-2)*qa + 0.5*qa^4)"))
      << model.yaml;
  EXPECT_EQ(model.yaml.find("equality3"), std::string::npos) << model.yaml;
  ASSERT_EQ(model.notes.size(), 5u);
  EXPECT_EQ(model.notes[0], "t.xml:2:3: solref not applied: unidyn holds the constraint exactly");
  EXPECT_EQ(model.notes[1],
            "t.xml:2:3: <connect> 'loop' holds a.frame_point([0.5, 0, 0]) on b.frame_point([-0.5, "
            "-2, 1]), the point where it is at qpos0 (computed)");
  EXPECT_EQ(model.notes[2], "t.xml:3:3: an unnamed <connect> is named equality1 (its MuJoCo id)");
  EXPECT_EQ(model.notes[4],
            "t.xml:5:3: <joint> with active=\"false\": left out, as MuJoCo leaves it off");
}

// <weld>: to the ground with the pose at qpos0 (body1's point where the ground's anchor is, and
// R0 = R1ᵀ: the body turned half a turn about E3, so R0 = diag(-1, -1, 1)), and to another body
// with a typed relpose (R0 = I); torquescale noted.
TEST(MjcfImport, WeldsAsSixPositionConstraints) {
  const std::string text =
      world("  <body name=\"a\" pos=\"0 0 1\" quat=\"0 0 0 1\"><joint name=\"qa\"/>" + kInertial +
                "\n    <body name=\"b\" pos=\"0 0 -1\"><joint name=\"qb\"/>" + kInertial +
                "</body>\n  </body>\n",
            "<equality>\n"
            "  <weld name=\"fix\" body1=\"a\" anchor=\"0 0 0.5\"/>\n"
            "  <weld name=\"glue\" body1=\"a\" body2=\"b\" relpose=\"0.1 0 0 1 0 0 0\" "
            "torquescale=\"3\"/>\n"
            "</equality>");
  const auto model = import_mjcf(text, "t.xml");
  const std::string fix = "dot(a.frame_point([0, 0, -0.5]) - [0, 0, 0.5], E";
  EXPECT_TRUE(has_line(model.yaml, "  - name: fix_1\n    position: " + fix + "1)")) << model.yaml;
  EXPECT_TRUE(has_line(model.yaml, "  - name: fix_3\n    position: " + fix + "3)")) << model.yaml;
  // E23, E31, E12 of R1ᵀ R2 R0ᵀ: dot(f1_i, R2 R0ᵀ Ej), R0's rows on the ground's basis
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: fix_4\n    position: dot(a.frame_point([0, 1, 0]) - a.origin, "
                       "[0, 0, 1])"))
      << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: fix_5\n    position: dot(a.frame_point([0, 0, 1]) - a.origin, "
                       "[-1, 0, 0])"))
      << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: fix_6\n    position: dot(a.frame_point([1, 0, 0]) - a.origin, "
                       "[0, -1, 0])"))
      << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: glue_2\n    position: dot(a.frame_point([0.1, 0, 0]) - "
                       "b.frame_point([0, 0, 0]), E2)"))
      << model.yaml;
  EXPECT_TRUE(has_line(model.yaml,
                       "  - name: glue_4\n    position: dot(a.frame_point([0, 1, 0]) - a.origin, "
                       "b.frame_point([0, 0, 1]) - b.origin)"))
      << model.yaml;
  ASSERT_EQ(model.notes.size(), 3u);
  EXPECT_EQ(model.notes[0],
            "t.xml:2:3: <weld> 'fix' holds a.frame_point([0, 0, -0.5]) on [0, 0, 0.5] and the "
            "ground's frame turned from a's by the rotation at qpos0 (computed): rows 4-6 are the "
            "error rotation's E23, E31, E12");
  EXPECT_EQ(model.notes[1],
            "t.xml:3:3: torquescale not applied: unidyn holds the constraint exactly");
}

// <default> classes: the file imports as the same file with every class's attributes written
// out by hand where MuJoCo applies them — the top class on every joint and geom, a body's
// childclass on its subtree, a joint's own class over it, a nested class over its parent's, and
// an attribute an element sets itself kept.
TEST(MjcfImport, DefaultClassesAsIfWrittenOut) {
  const std::string classes =
      "<default><joint axis=\"0 1 0\" damping=\"0.1\"/><geom density=\"500\"/>"
      "<default class=\"leg\"><joint axis=\"1 0 0\"/><default class=\"knee\">"
      "<joint damping=\"0.3\"/></default></default></default>";
  const std::string with_classes = world(
      "  <body name=\"a\" childclass=\"leg\">\n"
      "    <joint name=\"hip\"/>\n    <geom size=\"0.1\"/>\n"
      "    <body name=\"b\" pos=\"0 0 -1\">\n"
      "      <joint name=\"knee\" class=\"knee\"/>\n      <geom size=\"0.1\"/>\n"
      "      <body name=\"c\" pos=\"0 0 -1\" childclass=\"main\">\n"
      "        <joint name=\"ankle\" damping=\"0.5\"/>\n        <geom size=\"0.05\"/>\n"
      "      </body>\n    </body>\n  </body>\n",
      classes);
  const std::string written_out = world(
      "  <body name=\"a\">\n"
      "    <joint name=\"hip\" axis=\"1 0 0\" damping=\"0.1\"/>\n"
      "    <geom size=\"0.1\" density=\"500\"/>\n"
      "    <body name=\"b\" pos=\"0 0 -1\">\n"
      "      <joint name=\"knee\" axis=\"1 0 0\" damping=\"0.3\"/>\n"
      "      <geom size=\"0.1\" density=\"500\"/>\n"
      "      <body name=\"c\" pos=\"0 0 -1\">\n"
      "        <joint name=\"ankle\" axis=\"0 1 0\" damping=\"0.5\"/>\n"
      "        <geom size=\"0.05\" density=\"500\"/>\n"
      "      </body>\n    </body>\n  </body>\n");
  const std::string yaml = import_mjcf(with_classes, "t.xml").yaml;
  EXPECT_EQ(yaml, import_mjcf(written_out, "t.xml").yaml);
  EXPECT_TRUE(has_line(yaml, "  - torsion_damper: {angle: knee, coefficient: 0.3}")) << yaml;
}

// A free body falls: on the Euler parameters' constraint its centre accelerates at the
// gravity of <option> (here along −E2), turned or not, and its rotation does not accelerate
// when it does not turn. By hand: ẍ = g_vector, ë = 0 at ω = 0.
TEST(MjcfImport, FreeBodyFallsWithTheOptionsGravity) {
  const std::string text = world(
      "  <body name=\"b\" pos=\"1 2 3\" quat=\"0.6 0 0.8 0\">\n    "
      "<freejoint name=\"f\"/>\n    <inertial pos=\"0.1 0 0\" "
      "mass=\"2\" diaginertia=\"0.1 0.2 0.25\"/>\n  </body>\n",
      "<option gravity=\"0 -3.5 0\"/>");
  const auto model = import_mjcf(text, "t.xml");
  EXPECT_TRUE(has_line(model.yaml,
                       "initial: {f_x: 1, f_y: 2, f_z: 3, f_e0: 0.59999999999999998, "
                       "f_e2: 0.80000000000000004}"))
      << model.yaml;
  const System system = parse_model(model.yaml, "t.xml (imported)");
  const CompiledSystem compiled(system, lagrange_equations(system));
  CompiledSystemData data = compiled.make_data();
  const std::vector<double> parameters = initial_state(system, {}).parameters;
  Eigen::VectorXd q(7), qdot = Eigen::VectorXd::Zero(7), qddot, lambda;
  q << 1, 2, 3, 0.6, 0, 0.8, 0;
  compiled.solve(0, q, qdot, parameters, qddot, lambda, data);
  // the centre of mass is off the frame: the origin's acceleration is g too at ω = 0, α = 0
  EXPECT_NEAR(qddot[0], 0, 1e-12);
  EXPECT_NEAR(qddot[1], -3.5, 1e-12);
  EXPECT_NEAR(qddot[2], 0, 1e-12);
  for (int i = 3; i < 7; ++i) EXPECT_NEAR(qddot[i], 0, 1e-12) << i;
}

}  // namespace
}  // namespace unidyn
