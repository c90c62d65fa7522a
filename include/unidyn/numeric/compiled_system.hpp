// The derived equations compiled for fast evaluation, and the constrained system solved for q̈
// and the multipliers λ at a state (DESIGN.md "Equations and numerics").
//
//   M(q, t) q̈ = f(q, q̇, t) + Aᵀ λ,     A q̈ + b = 0
//
// solved through the Schur complement: with M = L Lᵀ, (A M⁻¹ Aᵀ) λ = −b − A M⁻¹ f, then
// q̈ = M⁻¹ (f + Aᵀ λ); when M is only semi-definite (redundant coordinates such as Euler
// parameters), through the whole saddle-point system instead.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "unidyn/equations/lagrange.hpp"
#include "unidyn/model/system.hpp"
#include "unidyn/numeric/inertia_assembly.hpp"
#include "unidyn/numeric/native_code.hpp"
#include "unidyn/numeric/tape.hpp"
#include "unidyn/numeric/tree_evaluation.hpp"

namespace unidyn {

// The phase of a rough contact (equations/friction.hpp): sliding, or stuck.
struct FrictionPhase {
  bool stick = false;
  // The slip direction to use while the slip velocity is too small to give one.
  Eigen::Vector3d direction = Eigen::Vector3d::Zero();
  // The direction N̂ of the normal force found by the last solve (|N| = N̂ · N keeps the solve
  // linear); zero before the first.
  Eigen::Vector3d normal_direction = Eigen::Vector3d::Zero();
};

// A rough contact's numbers at a state: J (3 × n), e, the acceleration bias, the normals g_j (one
// column per constraint), μ_d (at the slip speed), μ_s, the viscous c.
struct FrictionValues {
  Eigen::MatrixXd jacobian;
  Eigen::Vector3d velocity_term, acceleration_bias;
  Eigen::Matrix3Xd normals;
  double dynamic = 0.0, static_coefficient = 0.0, viscous = 0.0;
  // An orthonormal basis of the normals' span, and one of the tangents off it (two on a surface,
  // one on a curve)
  Eigen::Matrix3Xd normal_basis, tangents;
  // v_rel = J q̇ + e and its tangential part (the slip)
  Eigen::Vector3d relative_velocity, slip;
  // The part of a vector along the normals, and off them
  Eigen::Vector3d normal_part(const Eigen::Vector3d& v) const {
    return normal_basis * (normal_basis.transpose() * v);
  }
  Eigen::Vector3d tangential_part(const Eigen::Vector3d& v) const { return v - normal_part(v); }
};

// The mutable side: registers and matrices one evaluation needs (one per thread).
// A vector argument of the evaluations: a VectorXd or a contiguous segment of one (y.head(n)),
// taken without a copy.
using StateRef = Eigen::Ref<const Eigen::VectorXd>;

struct CompiledSystemData {
  TapeWorkspace workspace;
  std::vector<double> inputs;
  std::vector<double> outputs;
  Eigen::MatrixXd mass_matrix;
  // M's L D Lᵀ factors (numeric/ldlt.hpp, row-major) and M⁻¹ Aᵀ, of the last solve
  std::vector<double> mass_factor;
  Eigen::MatrixXd inverse_mass_transposed_constraints;
  Eigen::VectorXd forcing;
  // the convective terms c and the scratch of an assembled M (numeric/inertia_assembly.hpp)
  Eigen::VectorXd convective;
  std::vector<double> assembly_scratch;
  Eigen::MatrixXd constraint_matrix;
  Eigen::VectorXd constraint_bias;
  Eigen::VectorXd constraint_velocity_term;
  Eigen::VectorXd constraint_position;
  // The solves that found the constraints' rows dependent (redundant, or a singular position).
  std::size_t dependent_solves = 0;
  // ... and, at the last of them, how many rows depended on the others (rows − rank).
  std::size_t rank_deficiency = 0;
  // The last solve's smallest pivot of A M⁻¹ Aᵀ's L D Lᵀ over its largest diagonal term (1 without
  // constraints, 0 when the rows were dependent): near a singular position it falls like the
  // square of the distance.
  double pivot_ratio = 1.0;
  // Which constraints hold now (unilateral contact made or lost); empty: all of them.
  std::vector<bool> active;
  // Rough contacts: their phases (set by the caller), numbers, and the contact force on the
  // particle found by the last solve (normal plus friction).
  std::vector<FrictionPhase> friction_phase;
  std::vector<FrictionValues> friction;
  std::vector<Eigen::Vector3d> contact_force;
  // the tree's numbers, when the recursive algorithms evaluate the dynamics
  TreeEvaluationData tree;
};

// The equations are not finite at a state (M with a NaN or an ∞: outside the model's domain, a
// square root of a negative number): thrown by CompiledSystem::solve. An integrator that proposed
// the state on its way (a trial stage, a Newton iterate inside CVODE) takes it as a step to shrink,
// not as the end of the run (integrate/simulation.cpp).
class NotFiniteState : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The constraints' rows lose rank at a state and no acceleration satisfies them all (a singular
// position met with rates off its branches, or rows that contradict each other): thrown by
// CompiledSystem::solve. An index-1 integrator cannot go on there (integrate/simulation.cpp hands
// the run to an index-3 one, or stops with the reason).
class ConstraintRankLoss : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// How the compiled equations are evaluated.
struct CompileOptions {
  // Native code (numeric/native_code.hpp) when a compiler is at hand, else the tape.
  bool native = false;
  // When the native code is not cached: compile it in a thread of its own and evaluate on the
  // tape until it is ready (the same numbers, bit for bit, so a run does not depend on when the
  // switch happens); the CompiledSystem's end waits for the compilation, which fills the cache.
  bool background = false;
  NativeOptions native_options;
  // M and c summed numerically from the partial velocities (numeric/inertia_assembly.hpp) when
  // the equations carry them (Kane's) and have at least this many coordinates; below it the
  // symbolic M, simplified, is cheaper (bench/: pendulum-N, heavy top).
  std::size_t assemble_from_coordinates = 10;
  // A kinematic tree's q̈ by the articulated-body algorithm (numeric/tree_evaluation.hpp) rather
  // than from the compiled M and f.
  bool recursive_tree = true;
  // ... from this many coordinates: below, the compiled equations are faster (bench/ part 10,
  // native code: the acrobot's 76 ns against the recorded algorithm's 92 ns, a planar 3-link
  // arm's 106 against 124 ns; the 7-DoF arm's 1175 ns against 545 ns).
  std::size_t recursive_from_coordinates = 5;
  // ... and, for a tree closed by constraints (its M and f by the numeric algorithms), also from
  // this many: below, the compiled equations are faster (a welded 7-joint loop: 1.9 µs against
  // 3.1 µs).
  std::size_t recursive_loops_from_coordinates = 10;
  // With native code, a tree's articulated-body algorithm recorded as generated code at the
  // parameters' given values (numeric/recorded_tree.hpp), its tape evaluated until the native
  // code is ready (the same numbers); other parameter values, and a pivot that is not positive,
  // take the numeric algorithm.
  bool recorded_tree = true;
  // Told the name of each phase as it ends ("derive (kane)" when the equations are derived here).
  std::function<void(std::string_view)> phase_ended;
};

// Native code being compiled in the background (compiled_system.cpp).
struct BackgroundCompilation;
// A tape compiled at its first use (compiled_system.cpp).
struct DeferredTape;

// Tape inputs [t, q, q̇, p] (with_accelerations: [t, q, q̇, q̈, λ, p]).
std::vector<Expr> tape_inputs(const System& system, bool with_accelerations);

// The dynamics as a tape of inputs [t, q, q̇, p] (tape_inputs) and outputs M (row by row), f, A
// (row by row) and b of M q̈ = f + Aᵀ λ, A q̈ + b = 0, in their evaluation form
// (numeric/evaluation_form.hpp).
Tape dynamics_tape(const System& system, const EquationsOfMotion& eq);

class CompiledSystem {
 public:
  CompiledSystem(const System& system, const EquationsOfMotion& equations,
                 const CompileOptions& options = {});
  // The equations derived as they are needed: none for a kinematic tree that the articulated-body
  // algorithm evaluates (until dynamics() asks for them), Kane's (equations/kane.hpp) otherwise.
  explicit CompiledSystem(const System& system, const CompileOptions& options = {});

  // Whether native code evaluates the equations, and how that came about: "tape", "native code
  // (compiled in 0.41 s: PATH)", "native code (cached: PATH)" or "tape (native code failed: ...)".
  bool native() const { return native_ != nullptr; }
  std::string evaluation() const;
  // How the tapes are evaluated (the evaluation() of a system that is not a tree).
  std::string tape_evaluation() const;
  // The size of the compiled equations: tape instructions, and bytes of native source (0 without).
  std::size_t instruction_count() const;
  std::size_t native_source_bytes() const { return native_ ? native_->source_bytes() : 0; }

  std::size_t coordinate_count() const { return n_; }
  std::size_t constraint_count() const { return m_; }
  std::size_t parameter_count() const { return p_; }
  std::size_t observation_count() const { return observation_names_.size(); }
  // Names of what observe() returns: kinetic_energy, potential_energy, then the outputs, the
  // conserved quantities and the stop_when expressions of the model.
  const std::vector<std::string>& observation_names() const { return observation_names_; }
  // Which constraints are position constraints (the others are velocity constraints).
  const std::vector<bool>& is_position_constraint() const { return is_position_; }
  // The rough constraint of each rough contact, and all the constraints that hold its point (the
  // rough one first, then those of its `with:`).
  const std::vector<std::size_t>& friction_constraints() const { return friction_constraint_; }
  const std::vector<std::vector<std::size_t>>& friction_contact_constraints() const {
    return friction_rows_;
  }

  // The tapes of inputs [t, q, q̇, p] (tape_inputs): the dynamics → M (row by row), f, A (row by
  // row), b; the constraints → A, e (A q̇ + e = 0), Ψ (position constraints; 0 for the others).
  // When M is assembled from the partial velocities, the dynamics tape is compiled at its first
  // use (the right-hand side does not need it).
  const Tape& dynamics() const;
  // Whether M and c are summed from the partial velocities (CompileOptions).
  bool assembles_inertia() const { return assembly_ != nullptr; }
  // Whether solve() takes a kinematic tree's q̈ from the articulated-body algorithm, and why not
  // when the system is not such a tree.
  bool recursive() const { return tree_.tree != nullptr; }
  const std::string& why_not_recursive() const { return tree_.why_not; }
  // Whether the tree's loops are closed by constraints: q̈ and λ then come from the tree's M
  // (composite-rigid-body algorithm), its f (Newton–Euler) and the constraint rows.
  bool closes_loops() const {
    return tree_.tree != nullptr && m_ > 0 && tree_.tree->forms_mass_matrix();
  }
  const Tape& constraint_tape() const { return constraints_; }

  // The rough contacts' numbers at (t, q, q̇) into data.friction.
  void evaluate_friction(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                         CompiledSystemData& data) const;

  CompiledSystemData make_data() const;

  // q̈ and λ at (t, q, q̇): where the constraints' rows are dependent (A M⁻¹ Aᵀ singular:
  // redundant rows, a singular position) the unique q̈ and the minimum-norm λ (numeric/
  // dependent_constraints.hpp). Throws std::runtime_error when M is not positive definite,
  // ConstraintRankLoss when the rows are inconsistent.
  void solve(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
             Eigen::VectorXd& qddot, Eigen::VectorXd& lambda, CompiledSystemData& data) const;

  // M and f of M q̈ = f + Aᵀ λ at (t, q, q̇) into data.mass_matrix and data.forcing, which solve()
  // leaves as they were when the articulated-body algorithm solved (recursive()).
  void mass_and_forcing(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                        CompiledSystemData& data) const;

  // (3.8)'s M q̈ = f + Aᵀ λ with the rows A q̈ + b = 0, unsolved, at (t, q, q̇): M, f, A, b into
  // data.mass_matrix, forcing, constraint_matrix and constraint_bias (the index-3 integrators
  // solve them their own way: integrate/augmented_lagrangian.hpp).
  void equations(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                 CompiledSystemData& data) const;

  // Fills data.constraint_matrix, constraint_velocity_term and constraint_position at (t, q, q̇).
  void constraints(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                   CompiledSystemData& data) const;

  // Energies, outputs and conserved quantities at a solved state.
  void observe(double t, StateRef q, StateRef qdot, StateRef qddot, StateRef lambda,
               std::span<const double> parameters, std::span<double> values,
               CompiledSystemData& data) const;

 private:
  // q̈ and λ of M q̈ = f + C λ, A q̈ + b = 0 for the given rows A, b and columns C (Aᵀ when
  // null; friction makes them differ); M and f in data.
  void solve_with(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                  const Eigen::MatrixXd* C, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                  CompiledSystemData& data) const;
  // q̈ and the minimum-norm λ when the rows A are dependent there (numeric/
  // dependent_constraints.hpp); throws when they are inconsistent.
  void solve_dependent(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                       Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                       CompiledSystemData& data) const;
  // The full (n + rows) system when M is only semi-definite.
  void solve_saddle_point(double t, const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                          const Eigen::MatrixXd& C, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                          CompiledSystemData& data) const;
  // The solve with rough contacts: stick rows in place of their normal rows, friction columns.
  void solve_with_friction(double t, Eigen::VectorXd& qddot, Eigen::VectorXd& lambda,
                           CompiledSystemData& data) const;
  // equations null: derived as they are needed
  CompiledSystem(const System& system, const EquationsOfMotion* equations,
                 const CompileOptions& options);
  // Starts the native compilation in a thread of its own (background_); false when no thread
  // could be created.
  bool compile_in_background(const NativeOptions& native_options);
  void load_state(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                  CompiledSystemData& data) const;
  // M, f, A and b at the state from the dynamics tape (or its assembly) into data.
  void evaluate_dynamics(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                         CompiledSystemData& data) const;
  // solve() over a tree closed by constraints (closes_loops()).
  void solve_loops(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                   Eigen::VectorXd& qddot, Eigen::VectorXd& lambda, CompiledSystemData& data) const;
  // solve() by the articulated-body algorithm (recursive()).
  void solve_tree(double t, StateRef q, StateRef qdot, std::span<const double> parameters,
                  Eigen::VectorXd& qddot, Eigen::VectorXd& lambda, CompiledSystemData& data) const;
  // Evaluates a tape of inputs [t, q, q̇, p] at the state; returns its outputs (in data).
  const double* evaluate_at(const Tape& tape, double t, StateRef q, StateRef qdot,
                            std::span<const double> parameters, CompiledSystemData& data) const;

  // q̈ by the recorded articulated-body algorithm's native code; false where it does not hold
  // (other parameters, no native code yet, a state that is not finite, a pivot not positive).
  bool recorded_accelerations(double t, StateRef q, StateRef qdot,
                              std::span<const double> parameters, Eigen::VectorXd& qddot,
                              CompiledSystemData& data) const;
  // The native functions, once built (null until then).
  const std::array<NativeFunction, 4>* ready_native_functions() const;
  // outputs = tape(inputs), by its native function when there is one.
  void run(const Tape& tape, std::span<const double> inputs, std::span<double> outputs,
           CompiledSystemData& data) const;

  std::size_t n_ = 0, m_ = 0, p_ = 0;
  // a kinematic tree's recursive dynamics; null: the compiled M and f
  TreePlan tree_;
  // M and c from the partial velocities; null: M and f on the tape
  std::shared_ptr<const InertiaAssembly> assembly_;
  // [t, q, q̇, p] → M, f, A, b; or, with assembly_, → Φ − ∂U/∂q, the assembly's values, A, b; of
  // a tree closed by constraints (closes_loops()) → A, b; of another tree, with native code, its
  // recorded articulated-body algorithm → q̈, the pivots (at recorded_parameters_), else none
  Tape dynamics_;
  std::vector<double> recorded_parameters_;
  // with assembly_: the M, f, A, b tape, compiled at the first call of dynamics()
  std::shared_ptr<DeferredTape> full_dynamics_;
  Tape constraints_;  // [t, q, q̇, p] → A, e, Ψ
  Tape observer_;     // [t, q, q̇, q̈, λ, p] → T, U, outputs, conserved, stop_when
  Tape friction_;     // [t, q, q̇, p] → per rough contact J, e, bias, the g_j, μ_d, μ_s, c
  std::vector<std::size_t> friction_constraint_;
  std::vector<std::vector<std::size_t>> friction_rows_;
  std::vector<std::string> observation_names_;
  std::vector<bool> is_position_;
  // Some coordinates are redundant (Euler parameters): M is semi-definite, whatever round-off
  // makes of its L D Lᵀ factors, and the saddle-point system is solved instead.
  bool redundant_coordinates_ = false;
  // The tapes as native functions (dynamics, constraints, observer, friction), when built.
  std::shared_ptr<const NativeLibrary> native_;
  std::array<NativeFunction, 4> native_functions_{};
  // The native code compiled in the background (CompileOptions::background), shared by copies.
  std::shared_ptr<BackgroundCompilation> background_;
  std::string evaluation_ = "tape";
};

}  // namespace unidyn
