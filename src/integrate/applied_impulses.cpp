// Impulses applied at given times: their events and the jumps of the rates (11.15).
#include "unidyn/integrate/applied_impulses.hpp"

#include <stdexcept>

#include "unidyn/equations/impulses.hpp"
#include "unidyn/integrate/impulsive_jump.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {
namespace {

// Φ̂ of every impulse, one after the other.
std::vector<Expr> all_generalized_impulses(const System& system) {
  std::vector<Expr> outputs;
  for (const AppliedImpulse& impulse : system.impulses) {
    const std::vector<Expr> phi = generalized_impulses(system, impulse);
    outputs.insert(outputs.end(), phi.begin(), phi.end());
  }
  return outputs;
}

}  // namespace

AppliedImpulses::AppliedImpulses(const System& system, const CompiledSystem& compiled,
                                 std::span<const double> parameters, double t0)
    : system_(system),
      compiled_(compiled),
      parameters_(parameters),
      data_(compiled.make_data()),
      tape_(Tape::compile(all_generalized_impulses(system), tape_inputs(system, false))),
      workspace_(tape_) {
  GiNaC::exmap values;
  for (std::size_t p = 0; p < system.parameters.size(); ++p) {
    values[system.parameters[p].symbol] = parameters[p];
  }
  for (const AppliedImpulse& impulse : system.impulses) {
    const std::optional<double> time = real_value(impulse.time, values);
    if (!time || !(*time > t0)) {
      throw std::invalid_argument(impulse.name +
                                  "'s time must be after the start t = " + detail::to_text(t0) +
                                  " (a change of the rates at the start is their initial value)");
    }
    times_.push_back(*time);
  }
  applied_.assign(times_.size(), false);
}

void AppliedImpulses::events(double t, std::span<double> g) const {
  for (std::size_t k = 0; k < times_.size(); ++k) g[k] = applied_[k] ? 1.0 : times_[k] - t;
}

std::string AppliedImpulses::apply(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot,
                                   std::size_t k, const std::vector<bool>& active) {
  const std::size_t n = compiled_.coordinate_count();
  // M and the rows of the constraints that hold
  Eigen::VectorXd qddot, lambda;
  data_.active = active;
  try {
    compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);
  } catch (const std::runtime_error&) {
    // M is filled before the solve can fail; the jump's own system says whether it is regular
  }
  compiled_.constraints(t, q, qdot, parameters_, data_);
  std::vector<Eigen::Index> rows;
  for (std::size_t j = 0; j < compiled_.constraint_count(); ++j) {
    if (active.empty() || active[j]) rows.push_back(static_cast<Eigen::Index>(j));
  }
  // Φ̂ of impulse k at (t, q)
  std::vector<double> inputs{t};
  inputs.insert(inputs.end(), q.data(), q.data() + n);
  inputs.insert(inputs.end(), qdot.data(), qdot.data() + n);
  inputs.insert(inputs.end(), parameters_.begin(), parameters_.end());
  std::vector<double> all(tape_.output_count());
  tape_.evaluate(inputs, all, workspace_);
  const Eigen::VectorXd phi =
      Eigen::Map<const Eigen::VectorXd>(all.data() + k * n, static_cast<Eigen::Index>(n));
  const auto jump =
      impulsive_jump(data_.mass_matrix, data_.constraint_matrix(rows, Eigen::all), phi,
                     Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size())));
  if (!jump) {
    throw std::runtime_error(system_.impulses[k].name +
                             " cannot be resolved (dependent constraints)");
  }
  qdot += jump->rate_change;
  applied_[k] = true;
  std::string line = system_.impulses[k].name + " applied: generalised impulses [";
  for (std::size_t i = 0; i < n; ++i) {
    const double value = phi[static_cast<Eigen::Index>(i)];
    line += (i ? ", " : "") + detail::to_text(value == 0.0 ? 0.0 : value);  // no "-0"
  }
  return line + "]";
}

}  // namespace unidyn
