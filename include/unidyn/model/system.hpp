// The System: what a model describes (book Ch. 1–2, 4–5). Immutable once built; simulation state
// lives elsewhere (as Pinocchio separates Model from Data).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "unidyn/model/tree_joint.hpp"
#include "unidyn/symbolic/coordinates.hpp"
#include "unidyn/symbolic/expression.hpp"
#include "unidyn/symbolic/rotation_expr.hpp"

namespace unidyn {

// A named number the model's expressions use; `--set NAME=VALUE` overrides its value.
struct Parameter {
  std::string name;
  GiNaC::realsymbol symbol;
  double value;
  SourcePosition where;
  // A parameter given as an expression of earlier parameters (L2: 2*L): that expression, whose
  // value is recomputed when --set changes one of them; 0 for one given as a number.
  Expr definition = 0;
  bool derived = false;
};

// A particle of mass m at r(q, t).
struct Particle {
  std::string name;
  Expr mass;
  VectorExpr position;
  SourcePosition where;
};

// A rigid body (Ch. 7): mass, inertia tensor about its centre of mass with components J0_ik on the
// body basis e_i = Q E_i (so J = Q J0 Qᵀ), rotation Q(q, t), centre of mass x̄(q, t).
// A body's rotation given by one Euler-angle set whose angles are three coordinates: the chart a
// simulation watches for gimbal lock (§6.8).
struct EulerChart {
  EulerSet set;
  std::array<std::size_t, 3> coordinates;
};

// How a viewer draws a body (the report): a uniform shape of kinematics/inertia.hpp's in the body's
// basis (its axis of symmetry along e3), its dimensions in shape_dimensions' order, and a colour
// ("#rrggbb", "" for the viewer's own). From `visual:`, else from an inertia given as a shape;
// no shape: the viewer draws the ellipsoid of inertia.
struct BodyVisual {
  std::string shape;
  std::vector<Expr> dimensions;
  std::string color;
};

struct Body {
  std::string name;
  Expr mass;
  GiNaC::matrix inertia;   // J0, components on e1, e2, e3
  GiNaC::matrix rotation;  // Q, components Q_ik = E_i · Q E_k
  VectorExpr center;
  SourcePosition where;
  std::optional<EulerChart> chart;
  BodyVisual visual;
  // Its frame's origin o (B.origin): where its joint places it, else its centre of mass.
  VectorExpr origin;
  // The joint that places it on its parent (a kinematic tree, tree_joint.hpp), if any.
  std::optional<TreeJoint> joint;
};

// A force F acting on a particle (the vector Newton's law sees).
struct ParticleForce {
  std::size_t particle;
  VectorExpr force;
};

// A force F on a body at the point x (x = x̄ for its centre), or a pure moment M on a body.
struct BodyForce {
  std::size_t body;
  VectorExpr point;
  VectorExpr force;
};
struct BodyMoment {
  std::size_t body;
  VectorExpr moment;
};

// One entry of `forces:`. A conservative element has a potential U whose forces on the particles
// are −∂U/∂r (listed in `forces` for Newton's form); a non-conservative element has only forces.
// A bare `potential:` in the coordinates has no force vectors: both forms see it through −∂U/∂q.
struct ForceElement {
  enum class Kind {
    gravity,
    spring,
    damper,
    force,
    potential,
    gravitation,
    moment,
    gravity_gradient,
    torsion_spring,
    torsion_damper,
    slide_damper
  };
  Kind kind;
  std::string label;
  SourcePosition where;
  Expr potential = 0;
  std::vector<ParticleForce> forces;
  bool conservative = false;
  // A `force:` or `moment:` whose potential unidyn proved and integrated (potential_check.hpp):
  // conservative, with that U, although the model gave none.
  bool potential_proven = false;
  std::vector<BodyForce> body_forces;
  std::vector<BodyMoment> moments;
  // What a recursive evaluation of a tree needs (numeric/tree_dynamics.hpp): gravity's uniform
  // field g; a torsion spring's or damper's angle (a coordinate; a slide damper's displacement) and
  // a damper's coefficient c.
  VectorExpr field;
  std::optional<std::size_t> angle;
  Expr coefficient = 0;
};

// Coulomb friction at a constraint's contact with particle or body `on` (equations/friction.hpp),
// a body touching at the point `at` (e.g. its centre − R E3 for a ball on a table); the surface
// moves at `surface_velocity` there (0 for a fixed one). On a curve the point is held by this
// constraint and those named in `with` (§2.6, §3.8): the normal force is all of theirs together.
// The dynamic coefficient may depend on the slip speed (slip_speed_symbol(); Ex. 9.13's
// μ_k + μ_v |v_P|); a viscous coefficient c adds −c v_t.
struct Friction {
  std::string on;
  Expr dynamic_coefficient;
  Expr static_coefficient;
  VectorExpr surface_velocity;
  VectorExpr at;
  std::vector<std::string> with;
  Expr viscous_coefficient = 0;
};

// The slip speed |v_t| inside a dynamic coefficient of friction (`slip_speed` in a model).
const GiNaC::realsymbol& slip_speed_symbol();

// (8.22) The Lagrange representation of a constraint's load on a body: with the constraint's
// velocity form Σ_B (f_B · v̄_B + h_B · ω_B) + e = 0, it exerts F_c = λ f_B and M_c = λ h_B (about
// the centre of mass) on body B. Joints know f and h in closed form; other constraints leave
// `loads` empty and unidyn solves for them (kinematics/constraint_gradient).
struct ConstraintLoad {
  std::size_t body;
  VectorExpr force;   // f_B
  VectorExpr moment;  // h_B
};

// (1.9)–(1.13) A constraint. position: Ψ(q, t) = 0; velocity: a(q, t) · q̇ + e(q, t) = 0.
// Its force on the system is λ ∂Ψ/∂q (generalised) — on a particle R = Σ λ ∂Ψ/∂r.
struct Constraint {
  enum class Kind { position, velocity };
  std::string name;
  Kind kind;
  Expr expression;
  GiNaC::realsymbol multiplier;  // λ, printed lambda(name)
  bool unilateral = false;
  std::optional<Friction> friction;
  SourcePosition where;
  // The joint this constraint is one row of (its own name when it stands alone), and its loads.
  std::string joint;
  std::vector<ConstraintLoad> loads;
  // A constraint of the description, not of the motion (the unit norm of a body's Euler
  // parameters): it exerts no force or moment on anything.
  bool parametrisation = false;
  // A unilateral constraint's coefficient of restitution at impact (§2.10): 0 is plastic.
  Expr restitution = 0;
  // A velocity constraint that is off while the unilateral contact of this name holds (book
  // §2.10, Fig. 2.10b: x ẏ = 0 as ẏ = 0 away from a wall at x = 0); it switches on, when the
  // contact is lost, with the impulse that makes it hold. Empty: always on.
  std::string off_while;
};

// A named scalar to report: an extra CSV column, or a quantity the summary checks for drift.
struct Output {
  std::string name;
  Expr expression;
  SourcePosition where;
};

// The integration methods a run may name: dopri5 and dop853 (Dormand–Prince 5(4) and 8(5,3)), rk4,
// cvode, rattle (second order), rattle4 and rattle6 (RATTLE composed to fourth and sixth order),
// alf (the index-3 augmented Lagrangian method, for position constraints).
inline constexpr std::array<std::string_view, 8> integration_method_names = {
    "dopri5", "dop853", "rk4", "cvode", "rattle", "rattle4", "rattle6", "alf"};
bool is_integration_method(std::string_view name);
// The names joined for messages ("dopri5, dop853, … or rattle6") and for --help ("dopri5 | …").
std::string integration_methods();
std::string integration_method_choices();

struct SimulationSettings {
  double t_end = 10.0;
  double output_step = 0.01;
  std::string method = "dopri5";
  bool method_chosen = false;  // `method:` given
  double rtol = 1e-10;
  double atol = 1e-12;
  double step = 0.0;  // fixed step of rk4; 0 means output_step / 10
};

// A named sub-expression of the model (`definitions:`), a scalar or a vector, usable in every
// expression read after it.
struct Definition {
  std::string name;
  bool is_vector = false;
  Expr scalar = 0;
  VectorExpr vector;
  SourcePosition where;
};

// `initial: {B.omega: [..]}` (or B.omega_body: components on the body's basis): the body's
// angular velocity at the start, turned into the rates of the coordinates of its rotation.
struct InitialOmega {
  std::size_t body;
  bool body_frame = false;
  VectorExpr omega;                      // numbers and parameters
  std::vector<std::size_t> coordinates;  // whose rates it gives
  SourcePosition where;
};

// An impulse applied at a given time (book §9.8, the cue's strike; (11.13)–(11.15)): Î at a
// particle, or at a material point of a body (`point` is where it acts, as a function of q). Its
// generalised impulses Φ̂_i = Î · ∂r_P/∂q^i jump the momenta: [[∂T/∂q̇^i]] = Φ̂_i (11.15).
struct AppliedImpulse {
  std::string name;    // "impulse 1", … in the order of the model's list
  Expr time;           // a number or an expression of the parameters
  VectorExpr impulse;  // Î on E1, E2, E3 (may depend on q)
  VectorExpr point;    // r_P(q, t)
  SourcePosition where;
};

struct System {
  std::string name;
  std::string source;  // the model file
  // The model file's `description:` and `reference:` (where in the book), as written.
  std::string description, reference;
  Configuration configuration;
  std::vector<Parameter> parameters;
  std::vector<Particle> particles;
  std::vector<Body> bodies;
  std::vector<ForceElement> forces;
  std::vector<Constraint> constraints;
  // Initial q and der(q) per coordinate, expressions in the parameters (0 when absent).
  std::vector<Expr> initial_values;
  std::vector<Expr> initial_rates;
  // Which of them the model gives (the others are computed from the constraints, from 0).
  std::vector<bool> initial_value_given;
  std::vector<bool> initial_rate_given;
  std::vector<InitialOmega> initial_omegas;
  SimulationSettings simulate;
  std::vector<Output> outputs;
  std::vector<Output> conserved;
  std::vector<Definition> definitions;
  // The run stops when one of these, non-zero at the start, reaches 0.
  std::vector<Output> stop_when;
  // Impulses applied during the run, at their times.
  std::vector<AppliedImpulse> impulses;
  // The model's expression with the largest power of a sum once expanded (largest_power_terms),
  // and where it is: named when an expansion of the derivation exceeds its budget.
  SourcePosition largest_expression;
  double largest_expression_terms = 0;

  const std::vector<CoordinateSymbols>& coordinates() const { return configuration.coordinates(); }
  const GiNaC::realsymbol& time() const { return configuration.time(); }

  std::optional<std::size_t> find_parameter(const std::string& name) const;
  std::optional<std::size_t> find_coordinate(const std::string& name) const;
  std::optional<std::size_t> find_particle(const std::string& name) const;
  std::optional<std::size_t> find_body(const std::string& name) const;
  std::optional<std::size_t> find_constraint(const std::string& name) const;
  std::optional<std::size_t> find_definition(const std::string& name) const;

  // v = dr/dt of particle p (1.7).
  VectorExpr velocity(std::size_t p) const;
  // a = dv/dt of particle p.
  VectorExpr acceleration(std::size_t p) const;
  // Body b: ω = axial(Q̇ Qᵀ) (§6.4), simplified; its body components ω0 = Qᵀ ω; the body basis
  // vector e_k = Q E_k; the velocity of its centre; H = J ω about the centre (7.x), J = Q J0 Qᵀ.
  VectorExpr angular_velocity(std::size_t b) const;
  // Every body's ω, made at once: their simplification shared among processes
  // (symbolic/process_map.hpp); angular_velocity then finds them made.
  void make_angular_velocities() const;
  VectorExpr body_angular_velocity(std::size_t b) const;
  VectorExpr body_basis_vector(std::size_t b, int k) const;
  VectorExpr center_velocity(std::size_t b) const;
  VectorExpr angular_momentum(std::size_t b) const;
  // (6.30)–(6.31) The Euler basis g_i = ∂ω/∂γ̇^i of a body with an Euler chart, and its dual
  // basis g^i (g^i · g_k = δ^i_k): g^1 = g_2 × g_3 / [g_1, g_2, g_3] and cyclic. Singular at
  // gimbal lock, where [g_1, g_2, g_3] = 0.
  std::array<VectorExpr, 3> euler_basis(std::size_t b) const;
  std::array<VectorExpr, 3> dual_euler_basis(std::size_t b) const;
  // The material point X = X_k e_k from the centre: x̄ + Q X.
  VectorExpr material_point(std::size_t b, const VectorExpr& X) const;
  // Total potential energy U of the conservative elements.
  Expr potential_energy() const;
  // T = ½ Σ m v · v over the particles + Koenig's ½ m v̄ · v̄ + ½ ω · J ω over the bodies (7.x).
  Expr kinetic_energy() const;
  // The parameters' values as a substitution (for numeric checks).
  GiNaC::exmap parameter_values() const;
  // The parameters' symbols at `values` (one per parameter, in order: a run's, with --set).
  GiNaC::exmap parameter_values(const std::vector<double>& values) const;

 private:
  // axial(Q̇ Qᵀ) of body b, not yet simplified.
  VectorExpr axial_rate(std::size_t b) const;
  // ω of each body with the rotation it was derived from: the derivation asks for ω many times,
  // and a copy whose rotation was edited (approach II) derives it anew.
  mutable std::map<std::size_t, std::pair<TensorExpr, VectorExpr>> angular_velocity_cache_;
};

}  // namespace unidyn
