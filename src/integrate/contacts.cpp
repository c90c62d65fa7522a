// Unilateral constraints: phases, event functions, contact loss and impacts.
#include "unidyn/integrate/contacts.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "unidyn/integrate/impulsive_jump.hpp"
#include "unidyn/numeric/number_text.hpp"
#include "unidyn/symbolic/real_value.hpp"

namespace unidyn {

Contacts::Contacts(const System& system, const CompiledSystem& compiled,
                   std::span<const double> parameters)
    : system_(system),
      compiled_(compiled),
      parameters_(parameters),
      data_(compiled.make_data()),
      active_(system.constraints.size(), true) {
  GiNaC::exmap values;
  for (std::size_t p = 0; p < system.parameters.size(); ++p) {
    values[system.parameters[p].symbol] = parameters[p];
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const Constraint& c = system.constraints[k];
    if (!c.unilateral) continue;
    unilateral_.push_back(k);
    const double r = real_value(c.restitution, values).value_or(-1.0);
    if (!(r >= 0.0 && r <= 1.0)) {
      throw std::invalid_argument("the restitution of '" + c.name + "' must be in [0, 1]");
    }
    restitution_.push_back(r);
  }
  for (std::size_t k = 0; k < system.constraints.size(); ++k) {
    const std::string& contact = system.constraints[k].off_while;
    if (contact.empty()) continue;
    if (const auto j = system.find_constraint(contact)) switched_.emplace_back(k, *j);
  }
}

void Contacts::switch_by(std::size_t k, bool holds) {
  for (const auto& [c, contact] : switched_) {
    if (contact == k) active_[c] = !holds;
  }
}

std::string Contacts::switch_on(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot,
                                std::size_t k) {
  std::string text;
  for (const auto& [c, contact] : switched_) {
    if (contact != k || active_[c]) continue;
    active_[c] = true;
    // c's rate jumps to 0, the rows that hold keep theirs
    const double nu = impulse(t, q, qdot, c, 0.0);
    if (nu != 0.0) ++dissipative_impacts_;
    text += "; '" + system_.constraints[c].name + "' switches on: impulse " + detail::to_text(nu);
  }
  return text;
}

std::vector<std::string> Contacts::start(double t, const Eigen::VectorXd& q,
                                         const Eigen::VectorXd& qdot) {
  std::vector<std::string> lines;
  if (unilateral_.empty()) return lines;
  compiled_.constraints(t, q, qdot, parameters_, data_);
  const double tolerance = 1e-9 * (1.0 + q.cwiseAbs().maxCoeff());
  // in contact: Ψ ≈ 0 and not separating
  for (const std::size_t k : unilateral_) {
    const auto K = static_cast<Eigen::Index>(k);
    const double psi = data_.constraint_position[K];
    const double rate =
        data_.constraint_matrix.row(K).dot(qdot) + data_.constraint_velocity_term[K];
    if (psi < -tolerance) {
      throw std::runtime_error("the unilateral constraint '" + system_.constraints[k].name +
                               "' is violated at the start (Ψ = " + detail::to_text(psi) + " < 0)");
    }
    active_[k] = std::abs(psi) <= tolerance && rate <= tolerance;
  }
  // a contact whose force would pull is not one: drop the most negative until all push
  Eigen::VectorXd qddot, lambda;
  for (std::size_t round = 0; round < unilateral_.size(); ++round) {
    for (const std::size_t k : unilateral_) switch_by(k, active_[k]);
    data_.active = active_;
    compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);
    std::size_t worst = system_.constraints.size();
    for (const std::size_t k : unilateral_) {
      if (active_[k] && lambda[static_cast<Eigen::Index>(k)] < 0 &&
          (worst == system_.constraints.size() ||
           lambda[static_cast<Eigen::Index>(k)] < lambda[static_cast<Eigen::Index>(worst)])) {
        worst = k;
      }
    }
    if (worst == system_.constraints.size()) break;
    active_[worst] = false;
  }
  for (const std::size_t k : unilateral_) switch_by(k, active_[k]);
  for (const std::size_t k : unilateral_) {
    lines.push_back("'" + system_.constraints[k].name + "' " +
                    (active_[k] ? "in contact" : "free"));
  }
  for (const auto& [c, contact] : switched_) {
    if (!active_[c]) lines.push_back("'" + system_.constraints[c].name + "' off");
  }
  return lines;
}

void Contacts::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                      std::span<double> g) {
  Eigen::VectorXd qddot, lambda;
  data_.active = active_;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);
  compiled_.constraints(t, q, qdot, parameters_, data_);
  for (std::size_t i = 0; i < unilateral_.size(); ++i) {
    const auto K = static_cast<Eigen::Index>(unilateral_[i]);
    g[i] = active_[unilateral_[i]] ? lambda[K] : data_.constraint_position[K];
  }
}

std::string Contacts::handle(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot,
                             std::size_t which) {
  const std::size_t k = unilateral_.at(which);
  const std::string name = "'" + system_.constraints[k].name + "'";
  if (active_[k]) {
    active_[k] = false;
    return "contact " + name + " lost (its force reached 0)" + switch_on(t, q, qdot, k);
  }
  compiled_.constraints(t, q, qdot, parameters_, data_);
  const auto K = static_cast<Eigen::Index>(k);
  const double rate = data_.constraint_matrix.row(K).dot(qdot) + data_.constraint_velocity_term[K];
  const double e = restitution_[which];
  // rate ≥ 0: back at Ψ = 0 right after leaving it, too soon to resolve — a resting contact
  if (rate < 0.0 && e * std::abs(rate) > kRestingRebound) {
    const double nu = impulse(t, q, qdot, k, -e * rate);
    if (e < 1.0) ++dissipative_impacts_;
    return "impact on " + name + ": rate " + detail::to_text(rate) + " -> " +
           detail::to_text(-e * rate) + " (restitution " + detail::to_text(e) + "), impulse " +
           detail::to_text(nu);
  }
  // a plastic impact: the constraints it switches off take no part
  switch_by(k, true);
  const double nu = impulse(t, q, qdot, k, 0.0);
  if (nu != 0.0) ++dissipative_impacts_;
  if (try_hold(t, q, qdot, k)) {
    std::string text = "contact " + name + " made (approach rate " + detail::to_text(rate) +
                       ", impulse " + detail::to_text(nu) + ")";
    for (const auto& [c, contact] : switched_) {
      if (contact == k) text += "; '" + system_.constraints[c].name + "' switches off";
    }
    return text;
  }
  return name + " touched and left" + switch_on(t, q, qdot, k);
}

double Contacts::impulse(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot, std::size_t k,
                         double target) {
  // the rows that hold keep their rates, row k's goes to `target` (impulsive_jump.hpp)
  Eigen::VectorXd qddot, lambda;
  data_.active = active_;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);  // fills M
  compiled_.constraints(t, q, qdot, parameters_, data_);
  std::vector<Eigen::Index> rows;
  for (std::size_t j = 0; j < active_.size(); ++j) {
    if (active_[j] || j == k) rows.push_back(static_cast<Eigen::Index>(j));
  }
  const Eigen::MatrixXd A = data_.constraint_matrix(rows, Eigen::all);
  const Eigen::VectorXd rates = A * qdot + data_.constraint_velocity_term(rows);
  Eigen::VectorXd change = -rates;
  const auto row = std::find(rows.begin(), rows.end(), static_cast<Eigen::Index>(k)) - rows.begin();
  change[row] += target;
  const auto jump =
      impulsive_jump(data_.mass_matrix, A, Eigen::VectorXd::Zero(qdot.size()), change);
  if (!jump) {
    throw std::runtime_error("the impact on '" + system_.constraints[k].name +
                             "' cannot be resolved (dependent constraints)");
  }
  qdot += jump->rate_change;
  // ν of row k: the impulse ν ∂Ψ/∂r it gives a particle (∂Ψ/∂x̄, ∂Ψ/∂ω a body)
  return jump->constraint_impulse[row];
}

bool Contacts::try_hold(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                        std::size_t k) {
  active_[k] = true;
  switch_by(k, true);
  data_.active = active_;
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data_);
  if (lambda[static_cast<Eigen::Index>(k)] >= 0.0) return true;
  active_[k] = false;
  return false;
}

}  // namespace unidyn
