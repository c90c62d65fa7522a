// Stick–slip phases of the rough contacts.
#include "unidyn/integrate/friction_phases.hpp"

namespace unidyn {
namespace {

// Slip slower than this (relative to the contact's relative speed scale) counts as none.
bool slipping(const FrictionValues& f) {
  return f.slip.norm() > 1e-9 * (1.0 + f.relative_velocity.norm());
}

}  // namespace

FrictionPhases::FrictionPhases(const System& system, const CompiledSystem& compiled,
                               std::span<const double> parameters)
    : system_(system), compiled_(compiled), parameters_(parameters) {}

std::pair<double, double> FrictionPhases::tangential_and_normal(
    std::size_t c, const CompiledSystemData& data) const {
  const Eigen::Vector3d& R = data.contact_force[c];
  return {data.friction[c].tangential_part(R).norm(), data.friction[c].normal_part(R).norm()};
}

Eigen::Vector3d FrictionPhases::against_holding_force(std::size_t c,
                                                      const CompiledSystemData& data) const {
  return -data.friction[c].tangential_part(data.contact_force[c]).normalized();
}

std::vector<std::string> FrictionPhases::start(double t, const Eigen::VectorXd& q,
                                               const Eigen::VectorXd& qdot,
                                               CompiledSystemData& data) {
  std::vector<std::string> lines;
  compiled_.evaluate_friction(t, q, qdot, parameters_, data);
  for (std::size_t c = 0; c < event_count(); ++c) {
    const FrictionValues& f = data.friction[c];
    const std::size_t k = compiled_.friction_constraints()[c];
    const std::string name = "'" + system_.constraints[k].name + "'";
    std::string line;
    if (slipping(f)) {
      data.friction_phase[c].stick = false;
      data.friction_phase[c].direction = f.slip.normalized();
      line = name + " slides";
    } else {
      line = stick_or_slide(t, q, qdot, c, data);
    }
    // a unilateral contact that is apart neither sticks nor slides: its phase is set, not said
    if (data.active.empty() || data.active[k]) lines.push_back(std::move(line));
  }
  return lines;
}

void FrictionPhases::events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                            CompiledSystemData& data, std::span<double> g) {
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  for (std::size_t c = 0; c < event_count(); ++c) {
    const FrictionPhase& phase = data.friction_phase[c];
    if (phase.stick) {
      const auto [tangential, normal] = tangential_and_normal(c, data);
      g[c] = data.friction[c].static_coefficient * normal - tangential;
    } else {
      // ĉ · v_t − |v_t|/2: zero when the slip stops, or has turned by 60° (re-armed then, while
      // the friction still follows the slip itself: past 90° it would keep ĉ)
      const Eigen::Vector3d& slip = data.friction[c].slip;
      g[c] = slip.dot(phase.direction) - 0.5 * slip.norm();
    }
  }
}

std::string FrictionPhases::handle(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                   std::size_t which, CompiledSystemData& data) {
  compiled_.evaluate_friction(t, q, qdot, parameters_, data);
  FrictionPhase& phase = data.friction_phase[which];
  const std::string name =
      "'" + system_.constraints[compiled_.friction_constraints()[which]].name + "'";
  if (phase.stick) {
    // the static bound is exceeded: slide along −R_t
    Eigen::VectorXd qddot, lambda;
    compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
    phase.stick = false;
    phase.direction = against_holding_force(which, data);
    return "contact " + name + " slips (static friction exceeded)";
  }
  if (slipping(data.friction[which])) {
    phase.direction = data.friction[which].slip.normalized();  // the slip turned: re-arm
    return "";
  }
  return stick_or_slide(t, q, qdot, which, data);
}

std::string FrictionPhases::stick_or_slide(double t, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& qdot, std::size_t c,
                                           CompiledSystemData& data) {
  const std::string name =
      "'" + system_.constraints[compiled_.friction_constraints()[c]].name + "'";
  FrictionPhase& phase = data.friction_phase[c];
  phase.stick = true;
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  const auto [tangential, normal] = tangential_and_normal(c, data);
  if (tangential <= data.friction[c].static_coefficient * normal) {
    return "contact " + name + " sticks";
  }
  phase.stick = false;
  phase.direction = against_holding_force(c, data);
  return "contact " + name + " slides on (static friction too weak to hold it)";
}

}  // namespace unidyn
