// Compiled equations of motion and the solution for q̈ and λ.
#include "unidyn/numeric/compiled_system.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <thread>

#include "unidyn/equations/friction.hpp"
#include "unidyn/equations/kane.hpp"
#include "unidyn/numeric/dependent_constraints.hpp"
#include "unidyn/numeric/evaluation_form.hpp"
#include "unidyn/numeric/ldlt.hpp"

namespace unidyn {

// Tape inputs [t, q, q̇, p] (with_accelerations: [t, q, q̇, q̈, λ, p]).
std::vector<Expr> tape_inputs(const System& system, bool with_accelerations) {
  std::vector<Expr> inputs{system.time()};
  for (const auto& q : system.coordinates()) inputs.push_back(q.value);
  for (const auto& q : system.coordinates()) inputs.push_back(q.rate);
  if (with_accelerations) {
    for (const auto& q : system.coordinates()) inputs.push_back(q.acceleration);
    for (const auto& c : system.constraints) inputs.push_back(c.multiplier);
  }
  for (const auto& p : system.parameters) inputs.push_back(p.symbol);
  return inputs;
}

namespace {

// outputs, then A (row by row) and b in their evaluation form, on a tape of inputs [t, q, q̇, p]
Tape with_constraint_rows(std::vector<Expr> outputs, const EquationsOfMotion& eq,
                          const std::vector<Expr>& inputs) {
  outputs.insert(outputs.end(), eq.constraint_matrix.data.begin(), eq.constraint_matrix.data.end());
  outputs.insert(outputs.end(), eq.constraint_bias.begin(), eq.constraint_bias.end());
  return Tape::compile(outputs, inputs);
}

Tape dynamics_tape(const std::vector<Expr>& inputs, const EquationsOfMotion& derived) {
  const EquationsOfMotion eq = evaluation_form(derived);
  std::vector<Expr> outputs = eq.mass_matrix.data;
  outputs.insert(outputs.end(), eq.forcing.begin(), eq.forcing.end());
  return with_constraint_rows(std::move(outputs), eq, inputs);
}

// Φ − ∂U/∂q, the assembly's values (m or J0, J, h per term), A, b
Tape assembled_dynamics_tape(const std::vector<Expr>& inputs, const EquationsOfMotion& derived,
                             const InertiaAssembly& assembly) {
  EquationsOfMotion applied = derived;
  applied.mass_matrix = ExprMatrix();
  applied.forcing = derived.applied_forcing;
  const EquationsOfMotion eq = evaluation_form(applied);
  std::vector<Expr> outputs = eq.forcing;
  outputs.insert(outputs.end(), assembly.outputs().begin(), assembly.outputs().end());
  return with_constraint_rows(std::move(outputs), eq, inputs);
}

}  // namespace

Tape dynamics_tape(const System& system, const EquationsOfMotion& derived) {
  return dynamics_tape(tape_inputs(system, false), derived);
}

// The M, f, A, b tape of a system whose right-hand side assembles M: compiled when first asked
// for, from copies of what it needs (the System need not outlive the CompiledSystem).
struct DeferredTape {
  std::vector<Expr> inputs;
  EquationsOfMotion equations;
  // when set, the equations are derived from it (Kane's) at the first use
  std::shared_ptr<const System> system;
  std::once_flag once;
  Tape tape;
};

namespace {

// Whether every entry is finite: one pass without early exit, which the compiler vectorises.
bool all_finite(const double* x, std::size_t count) {
  bool finite = true;
  for (std::size_t i = 0; i < count; ++i) finite &= std::isfinite(x[i]);
  return finite;
}

Tape compile_constraints(const System& system, const EquationsOfMotion& derived) {
  const EquationsOfMotion eq = evaluation_form(derived);
  std::vector<Expr> outputs = eq.constraint_matrix.data;
  outputs.insert(outputs.end(), eq.constraint_velocity_term.begin(),
                 eq.constraint_velocity_term.end());
  outputs.insert(outputs.end(), eq.constraint_position.begin(), eq.constraint_position.end());
  return Tape::compile(outputs, tape_inputs(system, false));
}

// T, U (0 without energies), the outputs, the conserved quantities, the stop_when expressions.
Tape compile_observer(const System& system, const EquationsOfMotion& eq, bool energies) {
  std::vector<Expr> outputs{energies ? eq.kinetic_energy : 0, energies ? eq.potential_energy : 0};
  for (const auto& o : system.outputs) outputs.push_back(o.expression);
  for (const auto& o : system.conserved) outputs.push_back(o.expression);
  for (const auto& o : system.stop_when) outputs.push_back(o.expression);
  return Tape::compile(outputs, tape_inputs(system, true));
}

// Per rough contact: J (3 × n, row-major), e, the acceleration bias, the g_j, μ_d, μ_s, c.
Tape compile_friction(const System& system, const std::vector<FrictionContact>& contacts) {
  std::vector<Expr> outputs;
  const auto push = [&](const VectorExpr& v) {
    for (int k = 0; k < 3; ++k) outputs.push_back(v[k]);
  };
  for (const auto& c : contacts) {
    for (int k = 0; k < 3; ++k) {
      for (const auto& column : c.jacobian) outputs.push_back(column[k]);
    }
    push(c.velocity_term);
    push(c.acceleration_bias);
    for (const VectorExpr& g : c.normals) push(g);
    outputs.push_back(c.dynamic_coefficient);
    outputs.push_back(c.static_coefficient);
    outputs.push_back(c.viscous_coefficient);
  }
  return Tape::compile(outputs, tape_inputs(system, false));
}

// The four tapes as one library of functions unidyn_dynamics, _constraints, _observer, _friction.
std::shared_ptr<const NativeLibrary> build_native(const std::array<const Tape*, 4>& tapes,
                                                  const NativeOptions& options) {
  return NativeLibrary::build({{"unidyn_dynamics", tapes[0]},
                               {"unidyn_constraints", tapes[1]},
                               {"unidyn_observer", tapes[2]},
                               {"unidyn_friction", tapes[3]}},
                              options);
}

std::array<NativeFunction, 4> native_functions(const NativeLibrary& library) {
  return {library.function("unidyn_dynamics"), library.function("unidyn_constraints"),
          library.function("unidyn_observer"), library.function("unidyn_friction")};
}

// "native code (cached: PATH)", "native code (compiled in 0.41 s[how]: PATH)", and the notes.
std::string native_evaluation(const NativeLibrary& library, const std::string& how) {
  const std::string compiled =
      "compiled in " + std::to_string(library.compile_seconds()) + " s" + how;
  std::string text = "native code (" +
                     (library.cached() ? "cached: " + library.path()
                      : library.kept() ? compiled + ": " + library.path()
                                       : compiled) +
                     ")";
  if (!library.notes().empty()) text += "; " + library.notes();
  return text;
}

}  // namespace

// Native code compiled in a thread of its own, from copies of the tapes; `state` is published
// after the library, its functions and the evaluation text are in place.
struct BackgroundCompilation {
  enum State { compiling, ready, failed };
  std::array<Tape, 4> tapes;
  std::shared_ptr<const NativeLibrary> library;
  std::array<NativeFunction, 4> functions{};
  std::string evaluation;
  std::atomic<int> state{compiling};
  std::thread thread;
  // the compilation is waited for: it fills the cache for the next run
  ~BackgroundCompilation() {
    if (thread.joinable()) thread.join();
  }
};

CompiledSystem::CompiledSystem(const System& system, const EquationsOfMotion& equations,
                               const CompileOptions& options)
    : CompiledSystem(system, &equations, options) {}

CompiledSystem::CompiledSystem(const System& system, const CompileOptions& options)
    : CompiledSystem(system, nullptr, options) {}

CompiledSystem::CompiledSystem(const System& system, const EquationsOfMotion* given,
                               const CompileOptions& options)
    : n_(system.coordinates().size()),
      m_(system.constraints.size()),
      p_(system.parameters.size()),
      tree_(options.recursive_tree && n_ >= options.recursive_from_coordinates
                ? plan_tree(system)
                : TreePlan{nullptr, "fewer than " +
                                        std::to_string(options.recursive_from_coordinates) +
                                        " coordinates: the compiled equations are faster"}) {
  if (!options.recursive_tree) tree_.why_not = "not asked for";
  if (closes_loops() && n_ < options.recursive_loops_from_coordinates) {
    tree_ = {nullptr, "a tree closed by constraints of fewer than " +
                          std::to_string(options.recursive_loops_from_coordinates) +
                          " coordinates: the compiled equations are faster"};
  }
  // a tree's dynamics tape is compiled only when asked for (dynamics()), from the equations given
  // or, with none, Kane's derived then
  if (tree_.tree) {
    full_dynamics_ = std::make_shared<DeferredTape>();
    full_dynamics_->inputs = tape_inputs(system, false);
    if (given) full_dynamics_->equations = *given;
    if (!given) full_dynamics_->system = std::make_shared<const System>(system);
  }
  // with no equations given, Kane's (what the numerics take: the same as Lagrange's, derived
  // faster) unless the tree needs none
  EquationsOfMotion derived;
  if (!given && !tree_.tree) {
    derived = kane_equations(system);
    if (options.phase_ended) options.phase_ended("derive (kane)");
  } else if (!given) {
    constraint_rows(system, derived);  // a tree's (its Euler parameters' unit norms)
  }
  const EquationsOfMotion& equations = given ? *given : derived;
  if (!tree_.tree && !equations.partial_velocity_terms.empty() &&
      n_ >= options.assemble_from_coordinates) {
    assembly_ = std::make_shared<const InertiaAssembly>(equations.partial_velocity_terms, n_);
    full_dynamics_ = std::make_shared<DeferredTape>();
    full_dynamics_->inputs = tape_inputs(system, false);
    full_dynamics_->equations = equations;
    dynamics_ = assembled_dynamics_tape(tape_inputs(system, false), equations, *assembly_);
  } else if (!tree_.tree) {
    dynamics_ = dynamics_tape(system, equations);
  } else if (closes_loops()) {
    // loops closed over a tree: the dynamics tape gives the rows A and b alone (M and f are the
    // tree's)
    EquationsOfMotion rows;
    rows.constraint_matrix = equations.constraint_matrix;
    rows.constraint_bias = equations.constraint_bias;
    dynamics_ = with_constraint_rows({}, evaluation_form(rows), tape_inputs(system, false));
  } else if (options.native && options.recorded_tree) {
    // the articulated-body algorithm as generated code at the parameters' values (none where a
    // pivot is a number that is not positive: the numeric algorithm then says so at the solve)
    for (const Parameter& p : system.parameters) recorded_parameters_.push_back(p.value);
    try {
      dynamics_ = tree_.tree->recorded_accelerations(recorded_parameters_);
    } catch (const std::domain_error&) {
      recorded_parameters_.clear();
    }
  }
  constraints_ = compile_constraints(system, equations);
  // a tree's energies are its own (TreeEvaluation::energies): the tape computes the outputs
  observer_ = compile_observer(system, equations, !tree_.tree);
  const std::vector<FrictionContact> contacts = friction_contacts(system);
  friction_ = compile_friction(system, contacts);
  for (const auto& c : contacts) {
    friction_constraint_.push_back(c.constraints.front());
    friction_rows_.push_back(c.constraints);
  }
  observation_names_ = {"kinetic_energy", "potential_energy"};
  for (const auto& o : system.outputs) observation_names_.push_back(o.name);
  for (const auto& o : system.conserved) observation_names_.push_back(o.name);
  for (const auto& o : system.stop_when) observation_names_.push_back("stop_when " + o.name);
  for (const auto& c : system.constraints) {
    is_position_.push_back(c.kind == Constraint::Kind::position);
    redundant_coordinates_ = redundant_coordinates_ || c.parametrisation;
  }
  if (!options.native) return;
  // a tree with no outputs leaves the tapes without an instruction: nothing to compile
  if (instruction_count() == 0) {
    evaluation_ = "tape (nothing to compile)";
    return;
  }
  // the four tapes as one library; the tape stays when it cannot be had
  NativeOptions native_options = options.native_options;
  native_options.only_cached = options.background;
  const auto build_now = [&] {
    native_ = build_native({&dynamics_, &constraints_, &observer_, &friction_}, native_options);
    native_functions_ = native_functions(*native_);
    evaluation_ = native_evaluation(*native_, "");
  };
  try {
    try {
      build_now();
    } catch (const NotCached&) {
      // not in the cache: compiled in a thread of its own while the tape evaluates, or here when
      // no thread can be had
      native_options.only_cached = false;
      if (!compile_in_background(native_options)) build_now();
    }
  } catch (const NativeCodeError& error) {
    native_.reset();
    evaluation_ = std::string("tape (") + error.what() + ")";
  }
}

bool CompiledSystem::compile_in_background(const NativeOptions& native_options) {
  background_ = std::make_shared<BackgroundCompilation>();
  BackgroundCompilation& job = *background_;
  job.tapes = {dynamics_, constraints_, observer_, friction_};
  try {
    job.thread = std::thread([&job, native_options] {
      try {
        job.library = build_native({&job.tapes[0], &job.tapes[1], &job.tapes[2], &job.tapes[3]},
                                   native_options);
        job.functions = native_functions(*job.library);
        job.evaluation = native_evaluation(*job.library, " in the background, the tape until then");
        job.state.store(BackgroundCompilation::ready, std::memory_order_release);
      } catch (const std::exception& error) {
        job.evaluation = std::string("tape (") + error.what() + ")";
        job.state.store(BackgroundCompilation::failed, std::memory_order_release);
      }
    });
  } catch (const std::system_error&) {
    // a process or thread limit reached
    background_.reset();
    return false;
  }
  return true;
}

std::string CompiledSystem::evaluation() const {
  const std::string tree =
      closes_loops() ? "composite-rigid-body M and Newton-Euler forces over the tree, loops "
                       "closed by the constraints, rows and outputs by "
      : tree_.tree && dynamics_.output_count() > 0
          ? "articulated-body algorithm over the tree, recorded at the parameters' values "
            "(generated code), it and the outputs by "
      : tree_.tree ? "articulated-body algorithm over the tree, outputs by "
                   : "";
  return tree + tape_evaluation();
}

std::string CompiledSystem::tape_evaluation() const {
  if (!background_) return evaluation_;
  if (background_->state.load(std::memory_order_acquire) == BackgroundCompilation::compiling) {
    // the process waits for it at its end (~BackgroundCompilation): said here, not left to look
    // like a hang after the summary
    return "tape (the native code was still compiling in the background when asked; the command "
           "ends when it is compiled, for the next run: Ctrl-C does not wait)";
  }
  return background_->evaluation;
}

const Tape& CompiledSystem::dynamics() const {
  if (!full_dynamics_) return dynamics_;
  DeferredTape& deferred = *full_dynamics_;
  std::call_once(deferred.once, [&] {
    if (deferred.system) deferred.equations = kane_equations(*deferred.system);
    deferred.tape = dynamics_tape(deferred.inputs, deferred.equations);
  });
  return deferred.tape;
}

std::size_t CompiledSystem::instruction_count() const {
  return dynamics_.instruction_count() + constraints_.instruction_count() +
         observer_.instruction_count() + friction_.instruction_count();
}

const std::array<NativeFunction, 4>* CompiledSystem::ready_native_functions() const {
  // built at once, or by the background compilation once it is ready
  if (native_) return &native_functions_;
  if (background_ &&
      background_->state.load(std::memory_order_acquire) == BackgroundCompilation::ready) {
    return &background_->functions;
  }
  return nullptr;
}

void CompiledSystem::run(const Tape& tape, std::span<const double> inputs,
                         std::span<double> outputs, CompiledSystemData& data) const {
  if (const std::array<NativeFunction, 4>* functions = ready_native_functions()) {
    const Tape* tapes[] = {&dynamics_, &constraints_, &observer_, &friction_};
    for (std::size_t k = 0; k < 4; ++k) {
      if (tapes[k] != &tape) continue;
      if (inputs.size() != tape.input_count() || outputs.size() != tape.output_count()) break;
      (*functions)[k](inputs.data(), outputs.data());
      return;
    }
  }
  tape.evaluate(inputs, outputs, data.workspace);
}

CompiledSystemData CompiledSystem::make_data() const {
  CompiledSystemData data;
  data.workspace.reserve(dynamics_);
  data.workspace.reserve(constraints_);
  data.workspace.reserve(observer_);
  data.workspace.reserve(friction_);
  data.friction_phase.resize(friction_constraint_.size());
  data.friction.resize(friction_constraint_.size());
  data.contact_force.assign(friction_constraint_.size(), Eigen::Vector3d::Zero());
  data.inputs.resize(1 + 4 * n_ + m_ + p_);
  data.outputs.resize(std::max({dynamics_.output_count(), constraints_.output_count(),
                                observer_.output_count(), friction_.output_count()}));
  data.mass_matrix.setZero(n_, n_);  // never garbage, though the recursive solve leaves it
  data.mass_factor.resize(n_ * n_);
  data.forcing.resize(n_);
  data.convective.resize(n_);
  data.assembly_scratch.resize(assembly_ ? assembly_->scratch_size() : 0);
  if (tree_.tree) data.tree = tree_.tree->make_data();
  data.constraint_matrix.resize(m_, n_);
  data.constraint_bias.resize(m_);
  data.constraint_velocity_term.resize(m_);
  data.constraint_position.resize(m_);
  return data;
}

void CompiledSystem::load_state(double t, StateRef q, StateRef qdot,
                                std::span<const double> parameters,
                                CompiledSystemData& data) const {
  if (parameters.size() != p_) throw std::invalid_argument("wrong number of parameter values");
  data.inputs[0] = t;
  for (std::size_t i = 0; i < n_; ++i) {
    data.inputs[1 + i] = q[static_cast<Eigen::Index>(i)];
    data.inputs[1 + n_ + i] = qdot[static_cast<Eigen::Index>(i)];
  }
  for (std::size_t k = 0; k < p_; ++k) data.inputs[1 + 2 * n_ + k] = parameters[k];
}

const double* CompiledSystem::evaluate_at(const Tape& tape, double t, StateRef q, StateRef qdot,
                                          std::span<const double> parameters,
                                          CompiledSystemData& data) const {
  load_state(t, q, qdot, parameters, data);
  const std::span<const double> inputs(data.inputs.data(), 1 + 2 * n_ + p_);
  run(tape, inputs, std::span(data.outputs.data(), tape.output_count()), data);
  return data.outputs.data();
}

void CompiledSystem::evaluate_dynamics(double t, StateRef q, StateRef qdot,
                                       std::span<const double> parameters,
                                       CompiledSystemData& data) const {
  const double* out = evaluate_at(dynamics_, t, q, qdot, parameters, data);
  const auto N = static_cast<Eigen::Index>(n_);
  const auto Mc = static_cast<Eigen::Index>(m_);
  // M (row-major) into the factor's buffer and f: read off the tape, or summed from the partial
  // velocities with f = (Φ − ∂U/∂q) − c
  const double* constraint_rows = nullptr;
  if (assembly_) {
    assembly_->assemble(out + n_, data.mass_factor.data(), data.convective.data(),
                        data.assembly_scratch);
    data.forcing = Eigen::Map<const Eigen::VectorXd>(out, N) - data.convective;
    constraint_rows = out + n_ + assembly_->outputs().size();
  } else {
    std::copy(out, out + n_ * n_, data.mass_factor.begin());
    data.forcing = Eigen::Map<const Eigen::VectorXd>(out + n_ * n_, N);
    constraint_rows = out + n_ * n_ + n_;
  }
  const double* M = data.mass_factor.data();
  data.mass_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(M, N,
                                                                                               N);
  data.constraint_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          constraint_rows, Mc, N);
  data.constraint_bias = Eigen::Map<const Eigen::VectorXd>(constraint_rows + m_ * n_, Mc);
}

void CompiledSystem::mass_and_forcing(double t, StateRef q, StateRef qdot,
                                      std::span<const double> parameters,
                                      CompiledSystemData& data) const {
  if (!tree_.tree) {
    evaluate_dynamics(t, q, qdot, parameters, data);
    return;
  }
  if (tree_.tree->forms_mass_matrix()) {
    tree_.tree->mass_and_forcing(t, q, qdot, parameters, data.mass_matrix, data.forcing, data.tree);
    return;
  }
  // Euler parameters: M and f of the equations (derived at the first call)
  const Tape& tape = dynamics();
  load_state(t, q, qdot, parameters, data);
  const std::vector<double> out =
      tape.evaluate(std::span<const double>(data.inputs.data(), 1 + 2 * n_ + p_));
  const auto N = static_cast<Eigen::Index>(n_);
  data.mass_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          out.data(), N, N);
  data.forcing = Eigen::Map<const Eigen::VectorXd>(out.data() + n_ * n_, N);
}

void CompiledSystem::equations(double t, StateRef q, StateRef qdot,
                               std::span<const double> parameters, CompiledSystemData& data) const {
  if (!tree_.tree) {
    evaluate_dynamics(t, q, qdot, parameters, data);
    return;
  }
  const auto N = static_cast<Eigen::Index>(n_), Mc = static_cast<Eigen::Index>(m_);
  const double* rows = nullptr;
  std::vector<double> out;
  if (tree_.tree->forms_mass_matrix()) {
    // M by the composite-rigid-body algorithm, f by Newton–Euler, the rows from their tape
    tree_.tree->mass_and_forcing(t, q, qdot, parameters, data.mass_matrix, data.forcing, data.tree);
    rows = evaluate_at(dynamics_, t, q, qdot, parameters, data);
  } else {
    // Euler parameters: M, f, A, b of the equations (derived at the first call)
    load_state(t, q, qdot, parameters, data);
    out = dynamics().evaluate(std::span<const double>(data.inputs.data(), 1 + 2 * n_ + p_));
    data.mass_matrix =
        Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            out.data(), N, N);
    data.forcing = Eigen::Map<const Eigen::VectorXd>(out.data() + n_ * n_, N);
    rows = out.data() + n_ * n_ + n_;
  }
  data.constraint_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          rows, Mc, N);
  data.constraint_bias = Eigen::Map<const Eigen::VectorXd>(rows + m_ * n_, Mc);
}

void CompiledSystem::solve_tree(double t, StateRef q, StateRef qdot,
                                std::span<const double> parameters, Eigen::VectorXd& qddot,
                                Eigen::VectorXd& lambda, CompiledSystemData& data) const {
  if (closes_loops()) {
    solve_loops(t, q, qdot, parameters, qddot, lambda, data);
    return;
  }
  // the only constraints of a tree with Euler parameters are their unit norms: their multipliers
  // are 0 (tree/euler_parameter_joint.hpp)
  lambda.setZero(static_cast<Eigen::Index>(m_));
  if (recorded_accelerations(t, q, qdot, parameters, qddot, data)) return;
  try {
    tree_.tree->accelerations(t, q, qdot, parameters, qddot, data.tree);
  } catch (const std::domain_error& error) {
    if (!q.allFinite() || !qdot.allFinite()) {
      throw NotFiniteState("the state is not finite at t = " + std::to_string(t));
    }
    throw std::runtime_error("the mass matrix is not positive definite at t = " +
                             std::to_string(t) + ": " + error.what());
  }
  if (!qddot.allFinite()) {
    throw NotFiniteState("the accelerations are not finite at t = " + std::to_string(t));
  }
}

bool CompiledSystem::recorded_accelerations(double t, StateRef q, StateRef qdot,
                                            std::span<const double> parameters,
                                            Eigen::VectorXd& qddot,
                                            CompiledSystemData& data) const {
  // (by the native code, or the tape until it is ready: the same numbers, so a run does not
  // depend on when it switches)
  if (recorded_parameters_.size() != parameters.size() || dynamics_.output_count() < n_ ||
      !q.allFinite() || !qdot.allFinite() ||
      !std::equal(parameters.begin(), parameters.end(), recorded_parameters_.begin())) {
    return false;
  }
  const double* out = evaluate_at(dynamics_, t, q, qdot, parameters, data);
  // q̈, then the pivots: each positive, or the numeric algorithm says which is not
  for (std::size_t k = n_; k < dynamics_.output_count(); ++k) {
    if (!(out[k] > 0)) return false;
  }
  qddot = Eigen::Map<const Eigen::VectorXd>(out, static_cast<Eigen::Index>(n_));
  return qddot.allFinite();
}

void CompiledSystem::solve_loops(double t, StateRef q, StateRef qdot,
                                 std::span<const double> parameters, Eigen::VectorXd& qddot,
                                 Eigen::VectorXd& lambda, CompiledSystemData& data) const {
  // M by the composite-rigid-body algorithm and f = τ − b by Newton–Euler over the tree
  tree_.tree->mass_and_forcing(t, q, qdot, parameters, data.mass_matrix, data.forcing, data.tree);
  if (!data.mass_matrix.allFinite() || !data.forcing.allFinite()) {
    throw NotFiniteState("the mass matrix is not finite at t = " + std::to_string(t));
  }
  const auto N = static_cast<Eigen::Index>(n_), Mc = static_cast<Eigen::Index>(m_);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      data.mass_factor.data(), N, N) = data.mass_matrix;
  // the rows A q̈ + b = 0, then (3.8)'s M q̈ = f + Aᵀ λ solved with them
  const double* rows = evaluate_at(dynamics_, t, q, qdot, parameters, data);
  data.constraint_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          rows, Mc, N);
  data.constraint_bias = Eigen::Map<const Eigen::VectorXd>(rows + m_ * n_, Mc);
  solve_with(t, data.constraint_matrix, data.constraint_bias, nullptr, qddot, lambda, data);
}

void CompiledSystem::solve(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                           Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                           CompiledSystemData& data) const {
  if (tree_.tree) {
    solve_tree(t, q, qdot, parameters, qddot, lambda, data);
    return;
  }
  evaluate_dynamics(t, q, qdot, parameters, data);
  const double* M = data.mass_factor.data();
  const auto Mc = static_cast<Eigen::Index>(m_);
  if (!all_finite(M, n_ * n_)) {
    throw NotFiniteState("the mass matrix is not finite at t = " + std::to_string(t));
  }
  if (!friction_constraint_.empty()) {
    evaluate_friction(t, q, qdot, parameters, data);
    solve_with_friction(t, qddot, lambda, data);
    return;
  }
  // only the active constraints take part; an inactive one's λ is 0
  if (data.active.empty() ||
      std::find(data.active.begin(), data.active.end(), false) == data.active.end()) {
    solve_with(t, data.constraint_matrix, data.constraint_bias, nullptr, qddot, lambda, data);
    return;
  }
  std::vector<Eigen::Index> rows;
  for (std::size_t k = 0; k < m_; ++k) {
    if (data.active[k]) rows.push_back(static_cast<Eigen::Index>(k));
  }
  Eigen::VectorXd active_lambda;
  solve_with(t, data.constraint_matrix(rows, Eigen::all), data.constraint_bias(rows), nullptr,
             qddot, active_lambda, data);
  lambda = Eigen::VectorXd::Zero(Mc);
  lambda(rows) = active_lambda;
}

void CompiledSystem::solve_with(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                const Eigen::MatrixXd* C, Eigen::VectorXd& qddot,
                                Eigen::VectorXd& lambda, CompiledSystemData& data) const {
  if (redundant_coordinates_) {
    solve_saddle_point(t, A, b, C ? *C : Eigen::MatrixXd(A.transpose()), qddot, lambda, data);
    return;
  }
  // M = L D Lᵀ: the mass matrix of a well-posed model is positive definite
  double* factor = data.mass_factor.data();
  if (!ldlt_factor(factor, n_)) {
    // M is only semi-definite when coordinates are redundant (the four Euler parameters of a
    // body); the constraints then make the saddle-point system regular.
    solve_saddle_point(t, A, b, C ? *C : Eigen::MatrixXd(A.transpose()), qddot, lambda, data);
    return;
  }
  // M⁻¹ X, column by column
  const auto solve_columns = [&](Eigen::MatrixXd& X) {
    for (Eigen::Index j = 0; j < X.cols(); ++j) ldlt_solve(factor, n_, X.col(j).data());
  };
  qddot = data.forcing;
  ldlt_solve(factor, n_, qddot.data());
  lambda.resize(A.rows());
  if (C && A.rows() > 0) {
    // (A M⁻¹ C) λ = −b − A M⁻¹ f, then q̈ = M⁻¹ (f + C λ): not symmetric
    Eigen::MatrixXd MinvC = *C;
    solve_columns(MinvC);
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A * MinvC);
    if (!lu.isInvertible()) {
      throw std::runtime_error("the constraints are dependent at t = " + std::to_string(t) +
                               " (A M⁻¹ C is singular)");
    }
    lambda = lu.solve(-b - A * qddot);
    qddot += MinvC * lambda;
  } else if (A.rows() > 0) {
    // (A M⁻¹ Aᵀ) λ = −b − A M⁻¹ f, then q̈ = M⁻¹ (f + Aᵀ λ)
    Eigen::MatrixXd& MinvAt = data.inverse_mass_transposed_constraints;
    MinvAt = A.transpose();
    solve_columns(MinvAt);
    const Eigen::MatrixXd schur = A * MinvAt;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(schur);
    const double scale = schur.diagonal().cwiseAbs().maxCoeff();
    data.pivot_ratio = ldlt.info() == Eigen::Success && scale > 0.0
                           ? ldlt.vectorD().cwiseAbs().minCoeff() / scale
                           : 0.0;
    if (!(data.pivot_ratio > 1e-12)) {
      // dependent rows (redundant, or a singular position): Gauss's principle by the SVD
      data.pivot_ratio = 0.0;
      solve_dependent(t, A, b, qddot, lambda, data);
      return;
    }
    lambda = ldlt.solve(-b - A * qddot);
    qddot += MinvAt * lambda;
  }
}

void CompiledSystem::solve_dependent(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                     Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                                     CompiledSystemData& data) const {
  const MinimumNormSolution s = minimum_norm_solve(data.mass_matrix, data.forcing, A, b);
  data.rank_deficiency = static_cast<std::size_t>(A.rows() - s.rank);
  if (s.inconsistency > kInconsistentRows) {
    char part[32];
    std::snprintf(part, sizeof part, "%.3g", s.inconsistency);
    throw ConstraintRankLoss(
        "the constraints lose rank at t = " + std::to_string(t) + ": " + std::to_string(s.rank) +
        " of their " + std::to_string(A.rows()) +
        " rows are independent there (a singular position, or rows that contradict each other), "
        "and no acceleration satisfies them all (the part of A q'' + b = 0 no multiplier reaches "
        "is " +
        part +
        " of its terms); dependent rows are followed where they are consistent, but a singular "
        "position met with rates off its branches stops an index-1 method (--method alf, which "
        "holds the positions themselves, passes it)");
  }
  qddot = s.qddot;
  lambda = s.lambda;
  ++data.dependent_solves;
}

void CompiledSystem::solve_saddle_point(double t, const Eigen::MatrixXd& A,
                                        const Eigen::VectorXd& b, const Eigen::MatrixXd& C,
                                        Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                                        CompiledSystemData& data) const {
  const auto N = static_cast<Eigen::Index>(n_), Mc = A.rows();
  // [M  −C; A  0] [q̈; λ] = [f; −b]
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(N + Mc, N + Mc);
  K.topLeftCorner(N, N) = data.mass_matrix;
  K.topRightCorner(N, Mc) = -C;
  K.bottomLeftCorner(Mc, N) = A;
  Eigen::VectorXd rhs(N + Mc);
  rhs << data.forcing, -b;
  const Eigen::FullPivLU<Eigen::MatrixXd> lu(K);
  if (Mc == 0 || !lu.isInvertible()) {
    throw std::runtime_error("the mass matrix is singular or not positive definite at t = " +
                             std::to_string(t) + " (a singular configuration of the coordinates?)");
  }
  const Eigen::VectorXd x = lu.solve(rhs);
  qddot = x.head(N);
  lambda = x.tail(Mc);
}

void CompiledSystem::constraints(double t, StateRef q, StateRef qdot,
                                 std::span<const double> parameters,
                                 CompiledSystemData& data) const {
  const double* out = evaluate_at(constraints_, t, q, qdot, parameters, data);
  const auto N = static_cast<Eigen::Index>(n_);
  const auto Mc = static_cast<Eigen::Index>(m_);
  data.constraint_matrix =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          out, Mc, N);
  data.constraint_velocity_term = Eigen::Map<const Eigen::VectorXd>(out + m_ * n_, Mc);
  data.constraint_position = Eigen::Map<const Eigen::VectorXd>(out + m_ * n_ + m_, Mc);
}

void CompiledSystem::observe(double t, StateRef q, StateRef qdot, StateRef qddot, StateRef lambda,
                             std::span<const double> parameters, std::span<double> values,
                             CompiledSystemData& data) const {
  // Inputs [t, q, q̇, q̈, λ, p]
  std::vector<double>& in = data.inputs;
  in[0] = t;
  std::size_t k = 1;
  for (const StateRef* v : {&q, &qdot, &qddot}) {
    for (Eigen::Index i = 0; i < v->size(); ++i) in[k++] = (*v)[i];
  }
  for (Eigen::Index i = 0; i < lambda.size(); ++i) in[k++] = lambda[i];
  for (double p : parameters) in[k++] = p;
  run(observer_, std::span<const double>(in.data(), k), values, data);
  if (tree_.tree) tree_.tree->energies(t, q, qdot, parameters, values[0], values[1], data.tree);
}

}  // namespace unidyn
