// Natural conservative systems: the checks that make them so, and their compiled M, ∂L/∂q, Ψ, G.
#include "unidyn/numeric/natural_system.hpp"

#include <algorithm>
#include <stdexcept>

#include "unidyn/symbolic/derivative.hpp"
#include "unidyn/symbolic/expansion_budget.hpp"
#include "unidyn/symbolic/printing.hpp"

namespace unidyn {
namespace {

bool vanishes(const Expr& e) {
  return expand_within_budget(e, "a natural system").is_zero() || simplify(e).is_zero();
}

// Why the system is not natural (empty when it is).
std::string obstacle(const System& system, const EquationsOfMotion& eq) {
  const Expr t = system.time();
  for (const Constraint& c : system.constraints) {
    if (c.kind != Constraint::Kind::position) return "velocity constraint " + c.name;
    if (c.unilateral || c.friction) return "unilateral or rough constraint " + c.name;
    if (c.expression.has(t)) return "constraint " + c.name + " depends on t";
  }
  for (const Expr& phi : eq.generalized_force) {
    if (!vanishes(phi)) return "a non-conservative force";
  }
  if (eq.kinetic_energy.has(t) || eq.potential_energy.has(t)) return "T or U depends on t";
  // T = T2 + T1 + T0 (quadratic in q̇, book §4.x): T0 = T at q̇ = 0 and T1's coefficients
  // ∂T/∂q̇ at q̇ = 0 must vanish, and M free of q̇ — checks that do not depend on the form of T
  const auto& q = system.coordinates();
  GiNaC::exmap at_rest;
  for (const auto& c : q) at_rest[c.rate] = 0;
  if (!vanishes(eq.kinetic_energy.subs(at_rest))) return "T0 (T at rest is not 0)";
  for (const auto& c : q) {
    if (!vanishes(derivative(eq.kinetic_energy, c.rate).subs(at_rest)))
      return "T1 (gyroscopic terms)";
  }
  for (const Expr& mij : eq.mass_matrix.data) {
    for (const auto& c : q) {
      if (mij.has(c.rate)) return "M depends on the rates";
    }
  }
  return {};
}

std::vector<Expr> inputs_of(const System& system) {
  std::vector<Expr> inputs;
  for (const auto& q : system.coordinates()) inputs.push_back(q.value);
  for (const auto& q : system.coordinates()) inputs.push_back(q.rate);
  for (const auto& p : system.parameters) inputs.push_back(p.symbol);
  return inputs;
}

}  // namespace

CompiledNaturalSystem::CompiledNaturalSystem(const System& system, const EquationsOfMotion& eq)
    : n_(system.coordinates().size()), m_(system.constraints.size()), p_(system.parameters.size()) {
  if (const std::string why = obstacle(system, eq); !why.empty()) {
    throw std::invalid_argument(
        "a symplectic integrator needs a natural conservative system (T = ½ q̇ᵀ M(q) q̇, forces "
        "from potentials, position constraints, nothing explicit in t); this one has " +
        why);
  }
  const auto& q = system.coordinates();
  // M, and ∂L/∂q = ∂T/∂q − ∂U/∂q
  mass_ = Tape::compile(eq.mass_matrix.data, inputs_of(system));
  std::vector<Expr> outputs;
  const Expr lagrangian = eq.kinetic_energy - eq.potential_energy;
  for (const auto& c : q) outputs.push_back(derivative(lagrangian, c.value));
  gradient_ = Tape::compile(outputs, inputs_of(system));
  // Ψ and G = ∂Ψ/∂q
  outputs.clear();
  for (const Constraint& c : system.constraints) outputs.push_back(c.expression);
  for (const Constraint& c : system.constraints) {
    for (const auto& coordinate : q) outputs.push_back(derivative(c.expression, coordinate.value));
  }
  constraints_ = Tape::compile(outputs, inputs_of(system));
}

NaturalSystemData CompiledNaturalSystem::make_data() const {
  NaturalSystemData data;
  data.workspace.reserve(mass_);
  data.workspace.reserve(gradient_);
  data.workspace.reserve(constraints_);
  data.inputs.resize(2 * n_ + p_);
  data.outputs.resize(
      std::max({mass_.output_count(), gradient_.output_count(), constraints_.output_count()}));
  return data;
}

void CompiledNaturalSystem::load(const Eigen::VectorXd& q, const Eigen::VectorXd* qdot,
                                 std::span<const double> parameters,
                                 NaturalSystemData& data) const {
  if (parameters.size() != p_) throw std::invalid_argument("wrong number of parameter values");
  for (std::size_t i = 0; i < n_; ++i) {
    const auto I = static_cast<Eigen::Index>(i);
    data.inputs[i] = q[I];
    data.inputs[n_ + i] = qdot != nullptr ? (*qdot)[I] : 0.0;
  }
  for (std::size_t k = 0; k < p_; ++k) data.inputs[2 * n_ + k] = parameters[k];
}

void CompiledNaturalSystem::mass_matrix(const Eigen::VectorXd& q,
                                        std::span<const double> parameters, Eigen::MatrixXd& mass,
                                        NaturalSystemData& data) const {
  load(q, nullptr, parameters, data);
  mass_.evaluate(data.inputs, std::span(data.outputs.data(), mass_.output_count()), data.workspace);
  const auto N = static_cast<Eigen::Index>(n_);
  mass = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
      data.outputs.data(), N, N);
}

void CompiledNaturalSystem::lagrangian_gradient(const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& qdot,
                                                std::span<const double> parameters,
                                                Eigen::VectorXd& gradient,
                                                NaturalSystemData& data) const {
  load(q, &qdot, parameters, data);
  gradient_.evaluate(data.inputs, std::span(data.outputs.data(), gradient_.output_count()),
                     data.workspace);
  gradient = Eigen::Map<const Eigen::VectorXd>(data.outputs.data(), static_cast<Eigen::Index>(n_));
}

void CompiledNaturalSystem::constraints(const Eigen::VectorXd& q,
                                        std::span<const double> parameters, Eigen::VectorXd& psi,
                                        Eigen::MatrixXd& jacobian, NaturalSystemData& data) const {
  load(q, nullptr, parameters, data);
  constraints_.evaluate(data.inputs, std::span(data.outputs.data(), constraints_.output_count()),
                        data.workspace);
  const auto N = static_cast<Eigen::Index>(n_), Mc = static_cast<Eigen::Index>(m_);
  psi = Eigen::Map<const Eigen::VectorXd>(data.outputs.data(), Mc);
  jacobian =
      Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
          data.outputs.data() + m_, Mc, N);
}

}  // namespace unidyn
