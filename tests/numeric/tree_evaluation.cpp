// A model of tree joints evaluated recursively (numeric/tree_evaluation.hpp) against the same
// model's compiled Lagrange's equations (equations/lagrange.hpp: the book's (3.7) derived
// symbolically, M and f on the tape), with parameters, a torsion spring and damper on joint angles,
// a potential in the coordinates and a fixed joint (also recorded as generated code); ball and
// floating joints against Kane's equations in Euler parameters; and the systems the recursive path
// refuses, with the reason.
#include <gtest/gtest.h>

#include "support/oracles.hpp"
#include "unidyn/equations/lagrange.hpp"
#include "unidyn/io/model_file.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {
namespace {

// A branching arm in three dimensions: a turntable, a shoulder with a fixed bracket, an elbow, a
// slide on the shoulder's link, off-axis centres and a full inertia tensor.
const std::string kTree = R"(unidyn: 1
name: tree
parameters: {m: 1.4, L: 0.6, K: 3.0, c: 0.2, g: 9.81}
coordinates: [yaw, shoulder, elbow, slide]
bodies:
  turntable:
    joint: {revolute: yaw, axis: [0, 0, 1]}
    mass: 2
    inertia: [0.1, 0.1, 0.15]
  upper:
    joint: {parent: turntable, origin: [0.1, 0, 0.3], rpy: [0.3, -0.2, 0.5], revolute: shoulder, axis: [0, 1, 0]}
    mass: m
    inertia: {tensor: [[0.05, 0.002, 0], [0.002, 0.045, 0.003], [0, 0.003, 0.01]]}
    center: upper.frame_point([0.02, 0.01, -L/2])
  bracket:
    joint: {parent: upper, origin: [0, 0.05, -0.1], rpy: [0, 0, 0.7]}
    mass: 0.3
    inertia: [0.001, 0.002, 0.002]
    center: bracket.frame_point([0.03, 0, 0])
  fore:
    joint: {parent: upper, origin: [0, 0, -L], revolute: elbow, axis: [0.6, 0, 0.8]}
    mass: 0.8
    inertia: [0.02, 0.02, 0.003]
    center: fore.frame_point([0, 0, -0.2])
  carriage:
    joint: {parent: upper, origin: [0, 0.1, 0], prismatic: slide, axis: [0, 0, -1]}
    mass: 0.5
    inertia: [0.001, 0.001, 0.001]
forces:
  - gravity: -g*E3
  - torsion_spring: {angle: elbow, stiffness: K, rest_angle: 0.2}
  - torsion_damper: {angle: shoulder, coefficient: c}
  - potential: 40*slide^2/2
  - slide_damper: {displacement: slide, coefficient: 3*c}
)";

// The recursive algorithms at every size (recursive), or the compiled equations.
CompileOptions options(bool recursive) {
  CompileOptions options;
  options.recursive_tree = recursive;
  options.recursive_from_coordinates = 0;
  options.recursive_loops_from_coordinates = 0;
  return options;
}

struct Both {
  System system;
  EquationsOfMotion equations;
  CompiledSystem recursive, compiled;
  explicit Both(const std::string& text)
      : system(parse_model(text, "tree.yaml")),
        equations(lagrange_equations(system)),
        recursive(system, equations, options(true)),
        compiled(system, equations, options(false)) {}
};

// q̈, M, f, T and U at random states and the sets of parameters (the tree's numbers evaluated
// again when they change), the recursive algorithms against the compiled equations: the largest
// relative difference.
double worst_difference(const std::string& text,
                        const std::vector<std::vector<double>>& parameter_sets) {
  const Both both(text);
  EXPECT_TRUE(both.recursive.recursive()) << both.recursive.why_not_recursive();
  EXPECT_FALSE(both.compiled.recursive());
  EXPECT_EQ(both.recursive.evaluation().rfind("articulated-body algorithm over the tree", 0), 0u);
  CompiledSystemData data = both.recursive.make_data(), other = both.compiled.make_data();
  const auto n = static_cast<Eigen::Index>(both.system.coordinates().size());
  test::Random random;
  double worst = 0;
  for (const std::vector<double>& parameters : parameter_sets) {
    for (int k = 0; k < 10; ++k) {
      Eigen::VectorXd q(n), qdot(n), ours, theirs, lambda;
      for (Eigen::Index i = 0; i < n; ++i) {
        q[i] = random.uniform(-2, 2);
        qdot[i] = random.uniform(-2, 2);
      }
      both.recursive.solve(0, q, qdot, parameters, ours, lambda, data);
      both.compiled.solve(0, q, qdot, parameters, theirs, lambda, other);
      worst = std::max(worst, (ours - theirs).norm() / theirs.norm());
      both.recursive.mass_and_forcing(0, q, qdot, parameters, data);
      worst =
          std::max(worst, (data.mass_matrix - other.mass_matrix).norm() / other.mass_matrix.norm());
      worst = std::max(worst, (data.forcing - other.forcing).norm() / other.forcing.norm());
      // T and U: the tree's own against the compiled equations' (from T's and U's expressions)
      std::vector<double> energies(2), reference(2);
      both.recursive.observe(0, q, qdot, ours, lambda, parameters, energies, data);
      both.compiled.observe(0, q, qdot, theirs, lambda, parameters, reference, other);
      for (int e = 0; e < 2; ++e) {
        worst = std::max(worst, std::abs(energies[e] - reference[e]) / std::abs(reference[e]));
      }
    }
  }
  return worst;
}

TEST(TreeEvaluation, AgreesWithTheCompiledLagrangesEquations) {
  const double worst =
      worst_difference(kTree, {{1.4, 0.6, 3.0, 0.2, 9.81}, {2.1, 0.9, 5.0, 0.7, 3.7}});
  test::record("relative_error", worst);
  EXPECT_LT(worst, 1e-12);
}

CompileOptions native_tree() {
  CompileOptions options;
  options.native = true;
  options.recursive_from_coordinates = 0;
  return options;
}

// The largest relative difference of q̈ at 20 random states: the recorded algorithm (or, at other
// parameters, the numeric one) against the compiled Lagrange's equations.
double recorded_difference(const CompiledSystem& recorded, const CompiledSystem& equations,
                           const std::vector<double>& parameters) {
  CompiledSystemData data = recorded.make_data(), other = equations.make_data();
  const auto n = static_cast<Eigen::Index>(recorded.coordinate_count());
  test::Random random;
  double worst = 0;
  for (int k = 0; k < 20; ++k) {
    Eigen::VectorXd q(n), qdot(n), ours, theirs, lambda;
    for (Eigen::Index i = 0; i < n; ++i) {
      q[i] = random.uniform(-2, 2);
      qdot[i] = random.uniform(-2, 2);
    }
    recorded.solve(0, q, qdot, parameters, ours, lambda, data);
    equations.solve(0, q, qdot, parameters, theirs, lambda, other);
    worst = std::max(worst, (ours - theirs).norm() / theirs.norm());
  }
  return worst;
}

// The algorithm recorded as generated code (numeric/recorded_tree.hpp), as `simulate` runs it
// (with native code): q̈ against the compiled Lagrange's equations at the parameters it was
// recorded at and at others (then the numeric algorithm).
TEST(TreeEvaluation, RecordedAlgorithmAgreesWithTheCompiledLagrangesEquations) {
  const System system = parse_model(kTree, "tree.yaml");
  const EquationsOfMotion equations = lagrange_equations(system);
  CompileOptions compiled_options;
  compiled_options.recursive_tree = false;
  const CompiledSystem recorded(system, native_tree()),
      compiled(system, equations, compiled_options);
  EXPECT_EQ(recorded.evaluation().rfind("articulated-body algorithm over the tree, recorded", 0),
            0u)
      << recorded.evaluation();
  // the parameters it was recorded at, then others (the numeric algorithm)
  const double at_recording = recorded_difference(recorded, compiled, {1.4, 0.6, 3.0, 0.2, 9.81});
  const double elsewhere = recorded_difference(recorded, compiled, {2.1, 0.9, 5.0, 0.7, 3.7});
  test::record("relative_error", std::max(at_recording, elsewhere));
  EXPECT_LT(at_recording, 1e-12);
  EXPECT_LT(elsewhere, 1e-12);
}

// A carriage of no mass on the slide: the inertia along its joint is 0, a number when recorded. No
// recording then; the solve refuses with the numeric algorithm's reason.
TEST(TreeEvaluation, RecordedAlgorithmRefusesAJointWithNothingBeyondIt) {
  std::string text = kTree;
  const std::string carriage = "mass: 0.5\n    inertia: [0.001, 0.001, 0.001]";
  text.replace(text.find(carriage), carriage.size(), "mass: 0\n    inertia: [0, 0, 0]");
  const System system = parse_model(text, "massless-carriage.yaml");
  const CompiledSystem recorded(system, native_tree());
  EXPECT_EQ(recorded.evaluation().find("recorded"), std::string::npos) << recorded.evaluation();
  CompiledSystemData data = recorded.make_data();
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(4, 0.3), qdot = Eigen::VectorXd::Zero(4);
  Eigen::VectorXd qddot, lambda;
  const std::vector<double> parameters{1.4, 0.6, 3.0, 0.2, 9.81};
  try {
    recorded.solve(0, q, qdot, parameters, qddot, lambda, data);
    ADD_FAILURE() << "solved";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(
        std::string(error.what()).find("joint of coordinate 3 about its axis is not positive"),
        std::string::npos)
        << error.what();
  }
}

// A planar joint (three links: slides along E3 and E1 of a turned joint frame, a turn about −E2)
// carrying a puck with a pendulum: the same agreement.
TEST(TreeEvaluation, PlanarJointAgreesWithTheCompiledLagrangesEquations) {
  const std::string sled = R"(unidyn: 1
name: sled
parameters: {k: 5.0, g: 9.81}
coordinates: [x, y, th, swing]
bodies:
  puck:
    joint: {origin: [0.1, 0.2, 0.3], rpy: [0.4, 0.2, 0.1], planar: [x, y, th], axis: [0, -1, 0]}
    mass: 1.5
    inertia: {tensor: [[0.02, 0.001, 0.002], [0.001, 0.03, 0], [0.002, 0, 0.025]]}
    center: puck.frame_point([0.05, -0.02, 0.01])
  bob:
    joint: {parent: puck, origin: [0.1, 0, 0], revolute: swing, axis: [1, 0, 0]}
    mass: 0.4
    inertia: [0.002, 0.002, 0.001]
    center: bob.frame_point([0, 0.1, -0.3])
forces:
  - gravity: -g*E3
  - potential: k*x^2/2 + k*(y - 0.1)^2
)";
  const double worst = worst_difference(sled, {{5.0, 9.81}, {2.0, 3.0}});
  test::record("relative_error", worst);
  EXPECT_LT(worst, 1e-12);
}

// Without equations given, a tree derives none until the dynamics tape is asked for; that tape is
// then Kane's equations, the same M and f.
TEST(TreeEvaluation, DerivesNoEquationsUntilAskedFor) {
  const System system = parse_model(kTree, "tree.yaml");
  const CompiledSystem lazy(system, options(true));
  ASSERT_TRUE(lazy.recursive());
  CompiledSystemData data = lazy.make_data();
  const Eigen::VectorXd q = Eigen::Vector4d(0.3, -0.7, 1.1, 0.2),
                        qdot = Eigen::Vector4d(1, 2, -1, 0.5);
  const std::vector<double> parameters{1.4, 0.6, 3.0, 0.2, 9.81};
  std::vector<double> inputs{0.0};
  inputs.insert(inputs.end(), q.begin(), q.end());
  inputs.insert(inputs.end(), qdot.begin(), qdot.end());
  inputs.insert(inputs.end(), parameters.begin(), parameters.end());
  const std::vector<double> tape = lazy.dynamics().evaluate(inputs);
  lazy.mass_and_forcing(0, q, qdot, parameters, data);
  const Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> M(tape.data());
  const Eigen::Map<const Eigen::Vector4d> f(tape.data() + 16);
  EXPECT_LT((M - data.mass_matrix).norm(), 1e-13 * M.norm());
  EXPECT_LT((f - data.forcing).norm(), 1e-13 * f.norm());
}

// A floating torso (seven coordinates: x, y, z and Euler parameters), a ball-jointed head with
// its centre off the joint, a hinged arm on a turned bracket, and a torsion spring on the arm.
const std::string kFloatingTree = R"(unidyn: 1
name: floating
parameters: {g: 9.81}
coordinates: [x, y, z, e0, e1, e2, e3, b0, b1, b2, b3, arm]
bodies:
  torso:
    joint: {floating: [x, y, z, e0, e1, e2, e3]}
    mass: 5
    inertia: {tensor: [[0.3, 0.01, 0], [0.01, 0.2, 0.02], [0, 0.02, 0.25]]}
    center: torso.frame_point([0.05, -0.02, 0.1])
  head:
    joint: {parent: torso, origin: [0, 0, 0.4], rpy: [pi/2, 0, 0], ball: [b0, b1, b2, b3]}
    mass: 1.2
    inertia: [0.01, 0.012, 0.008]
    center: head.frame_point([0.02, 0.01, 0.12])
  bracket:
    joint: {parent: torso, origin: [0.1, 0.2, 0.3], rpy: [0, 0, pi/2]}
    mass: 0.2
    inertia: [0.001, 0.001, 0.001]
  limb:
    joint: {parent: bracket, origin: [0, 0.05, 0], revolute: arm, axis: [0, 1, 0]}
    mass: 0.7
    inertia: [0.02, 0.02, 0.002]
    center: limb.frame_point([0, 0, -0.25])
forces:
  - gravity: -g*E3
  - torsion_spring: {angle: arm, stiffness: 4, rest_angle: 0.3}
)";

// The floating tree by the recursive algorithms and by Kane's equations (derived once).
struct FloatingTree {
  System system = parse_model(kFloatingTree, "floating.yaml");
  CompiledSystem recursive{system, options(true)}, compiled{system, options(false)};
};
const FloatingTree& floating_tree() {
  static const FloatingTree tree;
  return tree;
}

// A unit e and a rate ė with e · ė = 0, at random.
void random_euler_parameters(test::Random& random, Eigen::Ref<Eigen::VectorXd> e,
                             Eigen::Ref<Eigen::VectorXd> edot) {
  for (int i = 0; i < 4; ++i) {
    e[i] = random.uniform(-1, 1);
    edot[i] = random.uniform(-1, 1);
  }
  e.normalize();
  edot -= e.dot(edot) * e;
}

// Ball and floating joints: q̈ of the articulated-body algorithm over the links' twists equals
// that of Kane's equations derived symbolically in the Euler parameters (M semi-definite, solved
// with their unit norms), at random states on the constraints; the norms' multipliers are 0 in
// both; T and U agree.
TEST(TreeEvaluation, BallAndFloatingJointsAgreeWithKanesEquations) {
  const CompiledSystem& recursive = floating_tree().recursive;
  const CompiledSystem& compiled = floating_tree().compiled;
  ASSERT_TRUE(recursive.recursive()) << recursive.why_not_recursive();
  ASSERT_EQ(recursive.constraint_count(), 2u);
  CompiledSystemData data = recursive.make_data(), other = compiled.make_data();
  const std::vector<double> parameters{9.81};
  test::Random random;
  double worst = 0, lambda_compiled = 0;
  for (int k = 0; k < 10; ++k) {
    Eigen::VectorXd q(12), qdot(12), ours, theirs, lambda, lambda_reference;
    for (int i = 0; i < 12; ++i) {
      q[i] = random.uniform(-1, 1);
      qdot[i] = random.uniform(-2, 2);
    }
    random_euler_parameters(random, q.segment(3, 4), qdot.segment(3, 4));
    random_euler_parameters(random, q.segment(7, 4), qdot.segment(7, 4));
    recursive.solve(0, q, qdot, parameters, ours, lambda, data);
    compiled.solve(0, q, qdot, parameters, theirs, lambda_reference, other);
    worst = std::max(worst, (ours - theirs).norm() / theirs.norm());
    EXPECT_EQ(lambda, Eigen::VectorXd::Zero(2));
    lambda_compiled = std::max(lambda_compiled, lambda_reference.cwiseAbs().maxCoeff());
    std::vector<double> energies(2), reference(2);
    recursive.observe(0, q, qdot, ours, lambda, parameters, energies, data);
    compiled.observe(0, q, qdot, theirs, lambda_reference, parameters, reference, other);
    for (int e = 0; e < 2; ++e) {
      worst = std::max(worst, std::abs(energies[e] - reference[e]) / std::abs(reference[e]));
    }
  }
  test::record("relative_error", worst);
  std::printf(
      "recursive against Kane's equations: relative error %.3g; compiled |lambda| <= %.3g\n", worst,
      lambda_compiled);
  EXPECT_LT(worst, 1e-11);
  EXPECT_LT(lambda_compiled, 1e-10);
}

// Off the constraints (|e| ≠ 1, e · ė ≠ 0) the rotation sees only e / |e|: the recursive q̈
// keeps the constraints' second derivative e · ë + ė · ė = 0, as the compiled solve does.
TEST(TreeEvaluation, EulerParametersOffTheUnitSphereKeepTheConstraintsRate) {
  const CompiledSystem& recursive = floating_tree().recursive;
  const CompiledSystem& compiled = floating_tree().compiled;
  CompiledSystemData data = recursive.make_data(), other = compiled.make_data();
  Eigen::VectorXd q(12), qdot(12), ours, theirs, lambda;
  q << 0.1, 0.2, 0.3, 0.9, 0.2, -0.3, 0.4, 1.1, 0.1, 0.2, -0.1, 0.5;
  qdot << 1, -1, 0.5, 0.3, 0.2, 0.1, -0.4, 0.2, 0.5, -0.3, 0.1, 1.5;
  const std::vector<double> parameters{9.81};
  recursive.solve(0, q, qdot, parameters, ours, lambda, data);
  compiled.solve(0, q, qdot, parameters, theirs, lambda, other);
  for (const Eigen::Index a : {3, 7}) {
    EXPECT_NEAR(q.segment(a, 4).dot(ours.segment(a, 4)) + qdot.segment(a, 4).squaredNorm(), 0,
                1e-13);
  }
  EXPECT_LT((ours - theirs).norm(), 1e-10 * theirs.norm());
}

// What the recursive path does not take goes to the compiled equations, saying why.
TEST(TreeEvaluation, OtherSystemsKeepTheCompiledEquationsWithTheReason) {
  const auto why_not = [](const std::string& text) {
    return plan_tree(parse_model(text, "tree.yaml")).why_not;
  };
  const std::string arm =
      "unidyn: 1\nname: arm\ncoordinates: [a]\nbodies:\n  link:\n"
      "    joint: {revolute: a, axis: [0, 0, 1]}\n    mass: 1\n"
      "    inertia: [1, 1, 1]\n    center: link.frame_point([1, 0, 0])\n";
  EXPECT_EQ(why_not(arm + "forces:\n  - gravity: -9.81*E2\n"), "");
  EXPECT_EQ(why_not(arm + "forces:\n  - force: {on: link, point: [1, 0, 0], value: E2}\n"),
            "its force 'force' (line 11) acts at points");
  EXPECT_EQ(why_not(arm + "particles:\n  p: {mass: 1, position: [a, 0, 0]}\n"), "it has particles");
  EXPECT_EQ(
      why_not(
          "unidyn: 1\nname: top\ncoordinates: [a]\nbodies:\n  b:\n    mass: 1\n"
          "    inertia: [1, 1, 2]\n    rotation: {axis: E3, angle: a}\n    center: [0, 0, 0]\n"),
      "body 'b' is not placed by a joint");
  EXPECT_EQ(why_not(kFloatingTree + "  - potential: 3*e1^2\n"),
            "a force acts on the coordinates of body 'torso''s ball or floating joint");
  EXPECT_EQ(why_not(kFloatingTree + "constraints:\n  - {name: level, position: arm - 0.1}\n"),
            "it has the constraint 'level'");
  // a loop closed over a tree without Euler parameters is the tree's (CompiledSystem::solve_loops)
  EXPECT_EQ(why_not(arm + "constraints:\n  - {name: stop, position: a - 0.1}\n"), "");
  EXPECT_EQ(why_not(arm + "constraints:\n  - {name: stop, position: a - 0.1, unilateral: true}\n"),
            "its constraint 'stop' is unilateral");
}

}  // namespace
}  // namespace unidyn
