// The constraints' forces on the particles and bodies, from the multipliers.
#include "unidyn/numeric/constraint_forces.hpp"

#include "unidyn/kinematics/constraint_gradient.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

ConstraintForces::ConstraintForces(const System& system) {
  const std::size_t np = system.particles.size(), nb = system.bodies.size();
  // Σ_k λ_k f_k per particle, then per body
  std::vector<VectorExpr> sums(np + nb);
  std::vector<bool> acted_on(np + nb, false);
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    ConstraintLoads loads;
    try {
      loads = constraint_loads(system, k);
    } catch (const std::invalid_argument& e) {
      // the loads are not determined by these coordinates: no columns
      unavailable_ = e.what();
      return;
    }
    const Expr lambda = system.constraints[k].multiplier;
    for (std::size_t n = 0; n < np + nb; ++n) {
      const VectorExpr& f = n < np ? loads.particle_force[n] : loads.body_force[n - np];
      if (f[0].is_zero() && f[1].is_zero() && f[2].is_zero()) continue;
      sums[n] = sums[n] + lambda * f;
      acted_on[n] = true;
    }
  }
  std::vector<GiNaC::ex> outputs;
  for (std::size_t n = 0; n < np + nb; ++n) {
    if (!acted_on[n]) continue;
    owners_.push_back(n < np ? system.particles[n].name : system.bodies[n - np].name);
    for (const char* c : {".Fc.x", ".Fc.y", ".Fc.z"}) columns_.push_back(owners_.back() + c);
    for (int i = 0; i < 3; ++i) outputs.push_back(sums[n][i]);
  }
  std::vector<Expr> inputs = tape_inputs(system, false);
  for (const Constraint& c : system.constraints) inputs.push_back(c.multiplier);
  tape_ = Tape::compile(outputs, inputs);
  workspace_.reserve(tape_);
  inputs_.assign(tape_.input_count(), 0.0);
  outputs_.assign(tape_.output_count(), 0.0);
}

void ConstraintForces::append(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                              const Eigen::VectorXd& lambda, const std::vector<double>& parameters,
                              std::vector<double>& row) {
  std::size_t at = 0;
  inputs_[at++] = t;
  for (const double v : q) inputs_[at++] = v;
  for (const double v : qdot) inputs_[at++] = v;
  for (const double v : parameters) inputs_[at++] = v;
  for (const double v : lambda) inputs_[at++] = v;
  tape_.evaluate(inputs_, outputs_, workspace_);
  row.insert(row.end(), outputs_.begin(), outputs_.end());
}

}  // namespace unidyn
