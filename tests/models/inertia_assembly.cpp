// Kane's M and c summed numerically from the partial velocities (numeric/inertia_assembly.hpp)
// against the symbolic M and f of the same equations, against Lagrange's equations (derived
// independently, without partial velocities), and native code against the tape, bit for bit.
#include "unidyn/numeric/inertia_assembly.hpp"

#include <filesystem>
#include <random>

#include "../../bench/compare/pendulum_model.hpp"
#include "support/model_run.hpp"
#include "unidyn/equations/kane.hpp"

namespace unidyn {
namespace {

CompileOptions assembled_from(std::size_t coordinates) {
  CompileOptions options;
  options.assemble_from_coordinates = coordinates;
  return options;
}

// Random states near the model's start (q and q̇ each moved by up to ±0.5).
std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> random_states(const SimulationStart& start,
                                                                       int count) {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.5, 0.5);
  std::vector<std::pair<Eigen::VectorXd, Eigen::VectorXd>> states;
  for (int k = 0; k < count; ++k) {
    Eigen::VectorXd q = start.q, qdot = start.qdot;
    for (Eigen::Index i = 0; i < q.size(); ++i) {
      q[i] += shift(random);
      qdot[i] += shift(random);
    }
    states.emplace_back(q, qdot);
  }
  return states;
}

// M, f, A and b as a solve leaves them in data (solved or not: a state may be singular).
void fill(const CompiledSystem& compiled, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
          const SimulationStart& start, CompiledSystemData& data) {
  Eigen::VectorXd qddot, lambda;
  try {
    compiled.solve(0.2, q, qdot, start.parameters, qddot, lambda, data);
  } catch (const std::runtime_error&) {
  }
}

class InertiaAssemblyModels : public ::testing::TestWithParam<std::string> {};

// The same M and f as the symbolic ones to round-off (1e-12 of their largest entry), and the
// same constraint rows, at random states; particles, bodies (their rotations' J0 ω̇⁰ +
// ω0 × J0 ω0), Euler parameters and constraints.
TEST_P(InertiaAssemblyModels, SameMassMatrixAndForcingAsTheSymbolic) {
  const System system = load_model(test::model_path(GetParam()));
  const EquationsOfMotion equations = kane_equations(system);
  const CompiledSystem assembled(system, equations, assembled_from(1));
  const CompiledSystem symbolic(system, equations, assembled_from(1000));
  ASSERT_TRUE(assembled.assembles_inertia());
  ASSERT_FALSE(symbolic.assembles_inertia());
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData a = assembled.make_data(), s = symbolic.make_data();
  for (const auto& [q, qdot] : random_states(start, 10)) {
    fill(assembled, q, qdot, start, a);
    fill(symbolic, q, qdot, start, s);
    const double scale = 1 + s.mass_matrix.cwiseAbs().maxCoeff() + s.forcing.cwiseAbs().maxCoeff();
    EXPECT_LT((a.mass_matrix - s.mass_matrix).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_LT((a.forcing - s.forcing).cwiseAbs().maxCoeff(), 1e-12 * scale);
    EXPECT_EQ(a.mass_matrix, a.mass_matrix.transpose());
    // the rows too, to round-off: a tape's shared subexpressions depend on all of its outputs
    if (s.constraint_matrix.size() == 0) continue;
    const double rows =
        1 + s.constraint_matrix.cwiseAbs().maxCoeff() + s.constraint_bias.cwiseAbs().maxCoeff();
    EXPECT_LT((a.constraint_matrix - s.constraint_matrix).cwiseAbs().maxCoeff(), 1e-12 * rows);
    EXPECT_LT((a.constraint_bias - s.constraint_bias).cwiseAbs().maxCoeff(), 1e-12 * rows);
  }
  // the deferred M, f, A, b tape is the symbolic system's
  EXPECT_EQ(assembled.dynamics().instruction_count(), symbolic.dynamics().instruction_count());
}

INSTANTIATE_TEST_SUITE_P(Models, InertiaAssemblyModels,
                         ::testing::Values("double-pendulum", "heavy-top", "heavy-top-socket",
                                           "rolling-disk", "braking-cart", "hinged-bodies-pinned",
                                           "bicycle", "gravity-gradient-satellite",
                                           "lagrange-triangle", "spring-chain"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name) c = c == '-' ? '_' : c;
                           return name;
                         });

// A planar chain of `links` point masses in relative angles: bench/'s pendulum-N.
System chain(int links) {
  return parse_model(bench::pendulum_text(links), "chain.yaml");
}

// A 12-link chain assembles M by default (CompileOptions: from 10 coordinates), on a tape less
// than half the symbolic M's, and its q̈ are those of Lagrange's equations, derived from T without
// partial velocities, to round-off.
TEST(InertiaAssembly, TwelveLinkChainAgreesWithLagrange) {
  const System system = chain(12);
  const EquationsOfMotion equations = kane_equations(system);
  const CompiledSystem kane(system, equations);
  const CompiledSystem lagrange(system, lagrange_equations(system));
  EXPECT_TRUE(kane.assembles_inertia());
  EXPECT_FALSE(lagrange.assembles_inertia());
  EXPECT_LT(2 * kane.instruction_count(),
            CompiledSystem(system, equations, assembled_from(1000)).instruction_count());
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData a = kane.make_data(), b = lagrange.make_data();
  for (const auto& [q, qdot] : random_states(start, 10)) {
    Eigen::VectorXd qddot_kane, qddot_lagrange, lambda;
    kane.solve(0.0, q, qdot, start.parameters, qddot_kane, lambda, a);
    lagrange.solve(0.0, q, qdot, start.parameters, qddot_lagrange, lambda, b);
    EXPECT_LT((qddot_kane - qddot_lagrange).cwiseAbs().maxCoeff(),
              1e-9 * (1 + qddot_lagrange.cwiseAbs().maxCoeff()));
  }
}

// Native code runs the assembly's tape; the sums are the same code: q̈ and λ bit for bit.
TEST(InertiaAssembly, NativeAsTheTape) {
  const System system = load_model(test::model_path("hinged-bodies-pinned"));
  const EquationsOfMotion equations = kane_equations(system);
  CompileOptions options = assembled_from(1);
  options.native = true;
  options.native_options.cache_directory = ::testing::TempDir() + "unidyn-native-assembly";
  std::filesystem::remove_all(options.native_options.cache_directory);
  const CompiledSystem native(system, equations, options);
  const CompiledSystem tape(system, equations, assembled_from(1));
  ASSERT_TRUE(native.native()) << native.evaluation();
  ASSERT_TRUE(native.assembles_inertia());
  const SimulationStart start = initial_state(system, {});
  CompiledSystemData a = native.make_data(), b = tape.make_data();
  for (const auto& [q, qdot] : random_states(start, 5)) {
    Eigen::VectorXd qddot_native, lambda_native, qddot_tape, lambda_tape;
    native.solve(0.0, q, qdot, start.parameters, qddot_native, lambda_native, a);
    tape.solve(0.0, q, qdot, start.parameters, qddot_tape, lambda_tape, b);
    EXPECT_EQ(qddot_native, qddot_tape);
    EXPECT_EQ(lambda_native, lambda_tape);
  }
}

}  // namespace
}  // namespace unidyn
