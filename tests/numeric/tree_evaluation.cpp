// A model of tree joints evaluated recursively (numeric/tree_evaluation.hpp) against the same
// model's compiled Lagrange's equations (equations/lagrange.hpp: the book's (3.7) derived
// symbolically, M and f on the tape), with parameters, a torsion spring and damper on joint angles,
// a potential in the coordinates and a fixed joint; and the systems the recursive path refuses,
// with the reason.
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
)";

// The recursive algorithms at every size (recursive), or the compiled equations.
CompileOptions options(bool recursive) {
  CompileOptions options;
  options.recursive_tree = recursive;
  options.recursive_from_coordinates = 0;
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

// q̈, M and f at random states and two sets of parameters (the tree's numbers evaluated again when
// they change): the recursive algorithms agree with the compiled equations to rounding.
TEST(TreeEvaluation, AgreesWithTheCompiledLagrangesEquations) {
  const Both both(kTree);
  ASSERT_TRUE(both.recursive.recursive()) << both.recursive.why_not_recursive();
  ASSERT_FALSE(both.compiled.recursive());
  EXPECT_EQ(both.recursive.evaluation().rfind("articulated-body algorithm over the tree", 0), 0u);
  CompiledSystemData data = both.recursive.make_data(), other = both.compiled.make_data();
  test::Random random;
  double worst = 0;
  for (const std::vector<double>& parameters : {std::vector<double>{1.4, 0.6, 3.0, 0.2, 9.81},
                                                std::vector<double>{2.1, 0.9, 5.0, 0.7, 3.7}}) {
    for (int k = 0; k < 10; ++k) {
      Eigen::VectorXd q(4), qdot(4), ours, theirs, lambda;
      for (int i = 0; i < 4; ++i) {
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

// What the recursive path does not take goes to the compiled equations, saying why.
TEST(TreeEvaluation, OtherSystemsKeepTheCompiledEquationsWithTheReason) {
  const auto why_not = [](const std::string& text) {
    const System system = parse_model(text, "tree.yaml");
    return CompiledSystem(system, lagrange_equations(system), options(true)).why_not_recursive();
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
}

}  // namespace
}  // namespace unidyn
