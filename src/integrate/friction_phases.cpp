// Stick–slip phases of the rough contacts.
#include "unidyn/integrate/friction_phases.hpp"

#include <algorithm>
#include <limits>

namespace unidyn {
namespace {

// Slip slower than this (relative to the contact's relative speed scale) counts as none.
bool slipping(const FrictionValues& f) {
  return f.slip.norm() > 1e-9 * (1.0 + f.relative_velocity.norm());
}

}  // namespace

FrictionPhases::FrictionPhases(const System& system, const CompiledSystem& compiled,
                               std::span<const double> parameters)
    : system_(system),
      compiled_(compiled),
      parameters_(parameters),
      held_together_(compiled.friction_constraints().size(), false) {}

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
  held_together_.assign(event_count(), false);
  for (std::size_t c = 0; c < event_count(); ++c) {
    const FrictionValues& f = data.friction[c];
    const std::size_t k = compiled_.friction_constraints()[c];
    std::string line;
    if (slipping(f)) {
      data.friction_phase[c].stick = false;
      data.friction_phase[c].direction = f.slip.normalized();
      line = name_of(c) + " slides";
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
  std::vector<std::size_t> together;
  for (std::size_t c = 0; c < event_count(); ++c) {
    const FrictionPhase& phase = data.friction_phase[c];
    if (phase.stick && held_together_[c]) {
      together.push_back(c);
    } else if (phase.stick) {
      const auto [tangential, normal] = tangential_and_normal(c, data);
      g[c] = data.friction[c].static_coefficient * normal - tangential;
    } else {
      // ĉ · v_t − |v_t|/2: zero when the slip stops, or has turned by 60° (re-armed then, while
      // the friction still follows the slip itself: past 90° it would keep ĉ)
      const Eigen::Vector3d& slip = data.friction[c].slip;
      g[c] = slip.dot(phase.direction) - 0.5 * slip.norm();
    }
  }
  // contacts held together: zero when sliding together becomes consistent
  if (together.empty()) return;
  const std::vector<FrictionPhase> phases = data.friction_phase;
  const double margin = slide_together(t, q, qdot, together, data);
  data.friction_phase = phases;
  for (const std::size_t c : together) g[c] = -margin;
}

std::vector<std::string> FrictionPhases::handle(double t, const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& qdot, std::size_t which,
                                                CompiledSystemData& data) {
  compiled_.evaluate_friction(t, q, qdot, parameters_, data);
  FrictionPhase& phase = data.friction_phase[which];
  if (!phase.stick && slipping(data.friction[which])) {
    phase.direction = data.friction[which].slip.normalized();  // the slip turned: re-arm
    return {};
  }
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);  // A at (t, q)
  return decide(t, q, qdot, group_of(which, data), data);
}

Eigen::MatrixXd FrictionPhases::tangent_rows(std::size_t c, const CompiledSystemData& data) const {
  const FrictionValues& f = data.friction[c];
  return f.tangents.transpose() * f.jacobian;
}

bool FrictionPhases::coupled(std::size_t c, std::size_t o, const CompiledSystemData& data) const {
  // rank([A; T_c; T_o]) < rank([A; T_c]) + rank([A; T_o]) − rank(A), A the constraints that hold
  std::vector<Eigen::Index> holding;
  for (Eigen::Index k = 0; k < data.constraint_matrix.rows(); ++k) {
    if (data.active.empty() || data.active[std::size_t(k)]) holding.push_back(k);
  }
  const Eigen::MatrixXd A = data.constraint_matrix(holding, Eigen::all);
  const auto rank = [&](std::initializer_list<const Eigen::MatrixXd*> parts) {
    Eigen::Index rows = 0;
    for (const auto* part : parts) rows += part->rows();
    Eigen::MatrixXd stacked(rows, A.cols());
    rows = 0;
    for (const auto* part : parts) {
      stacked.middleRows(rows, part->rows()) = *part;
      rows += part->rows();
    }
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(stacked);
    qr.setThreshold(1e-9);
    return qr.rank();
  };
  const Eigen::MatrixXd T_c = tangent_rows(c, data), T_o = tangent_rows(o, data);
  return rank({&A, &T_c, &T_o}) < rank({&A, &T_c}) + rank({&A, &T_o}) - rank({&A});
}

std::vector<std::size_t> FrictionPhases::group_of(std::size_t c,
                                                  const CompiledSystemData& data) const {
  // the contacts at rest: stuck, or sliding with a slip that stopped
  std::vector<std::size_t> at_rest;
  for (std::size_t o = 0; o < event_count(); ++o) {
    const bool touching = data.active.empty() || data.active[compiled_.friction_constraints()[o]];
    if (o != c && touching && (data.friction_phase[o].stick || !slipping(data.friction[o]))) {
      at_rest.push_back(o);
    }
  }
  // c and those coupled to it, directly or through others
  std::vector<std::size_t> group{c};
  for (std::size_t i = 0; i < group.size(); ++i) {
    for (auto o = at_rest.begin(); o != at_rest.end();) {
      if (coupled(group[i], *o, data)) {
        group.push_back(*o);
        o = at_rest.erase(o);
      } else {
        ++o;
      }
    }
  }
  return group;
}

std::vector<std::string> FrictionPhases::decide(double t, const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& qdot,
                                                const std::vector<std::size_t>& group,
                                                CompiledSystemData& data) {
  std::vector<bool> was_stuck;
  for (const std::size_t c : group) {
    was_stuck.push_back(data.friction_phase[c].stick);
    held_together_[c] = false;
  }
  const auto said = [&](std::size_t i, const std::string& slides) {
    const FrictionPhase& phase = data.friction_phase[group[i]];
    if (phase.stick)
      return was_stuck[i] ? std::string() : "contact " + name_of(group[i]) + " sticks";
    return "contact " + name_of(group[i]) +
           (was_stuck[i] ? " slips (static friction exceeded)" : slides);
  };
  std::vector<std::string> lines;
  const auto say = [&](const std::string& slides) {
    for (std::size_t i = 0; i < group.size(); ++i) {
      if (std::string line = said(i, slides); !line.empty()) lines.push_back(std::move(line));
    }
    return lines;
  };
  // alone: stick if held, else slide along −R_t
  if (group.size() == 1) {
    FrictionPhase& phase = data.friction_phase[group[0]];
    if (!phase.stick) return {stick_or_slide(t, q, qdot, group[0], data)};
    Eigen::VectorXd qddot, lambda;
    compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
    phase.stick = false;
    phase.direction = against_holding_force(group[0], data);
    return say("");
  }
  // all stick, if each holding force is inside its static cone
  Eigen::VectorXd qddot, lambda;
  for (const std::size_t c : group) data.friction_phase[c].stick = true;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  if (std::ranges::all_of(group, [&](std::size_t c) { return held(c, data); })) return say("");
  // else slide together, if consistent
  if (slide_together(t, q, qdot, group, data) > 0) {
    return say(" slides on (static friction too weak to hold it)");
  }
  // else neither: their frictions hold them together (a constraint couples them, and one
  // contact's share of the holding force is not its own), until sliding together is consistent
  for (const std::size_t c : group) data.friction_phase[c].stick = true;
  std::string names;
  for (const std::size_t c : group) names += (names.empty() ? "" : ", ") + name_of(c);
  say("");
  for (const std::size_t c : group) held_together_[c] = true;
  lines.push_back(
      "contacts " + names +
      " are held together (no one of them holds alone, and sliding together is not consistent)");
  return lines;
}

double FrictionPhases::slide_together(double t, const Eigen::VectorXd& q,
                                      const Eigen::VectorXd& qdot,
                                      const std::vector<std::size_t>& group,
                                      CompiledSystemData& data) {
  // the slip accelerations with their friction off (sliding along a zero direction) ...
  for (const std::size_t c : group) {
    data.friction_phase[c].stick = false;
    data.friction_phase[c].direction.setZero();
  }
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  std::vector<Eigen::Vector3d> direction;
  for (const std::size_t c : group) direction.push_back(slip_acceleration(c, qddot, data));
  // ... give each its direction (one with none sticks); each slip must then accelerate along it
  // with the friction on, and each stuck one be held
  for (std::size_t i = 0; i < group.size(); ++i) {
    const double size = direction[i].norm();
    data.friction_phase[group[i]].stick = !(size > 1e-12);
    if (size > 1e-12) data.friction_phase[group[i]].direction = direction[i] / size;
  }
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  double margin = std::numeric_limits<double>::infinity();
  bool moves = false;
  for (const std::size_t c : group) {
    const FrictionPhase& phase = data.friction_phase[c];
    if (phase.stick && !held(c, data)) margin = std::min(margin, -1.0);
    if (phase.stick) continue;
    moves = true;
    margin = std::min(margin, slip_acceleration(c, qddot, data).dot(phase.direction));
  }
  return moves ? margin : -1.0;
}

bool FrictionPhases::held(std::size_t c, const CompiledSystemData& data) const {
  const auto [tangential, normal] = tangential_and_normal(c, data);
  return tangential <= data.friction[c].static_coefficient * normal;
}

Eigen::Vector3d FrictionPhases::slip_acceleration(std::size_t c, const Eigen::VectorXd& qddot,
                                                  const CompiledSystemData& data) const {
  const FrictionValues& f = data.friction[c];
  return f.tangential_part(f.jacobian * qddot + f.acceleration_bias);
}

std::string FrictionPhases::name_of(std::size_t c) const {
  return "'" + system_.constraints[compiled_.friction_constraints()[c]].name + "'";
}

std::string FrictionPhases::stick_or_slide(double t, const Eigen::VectorXd& q,
                                           const Eigen::VectorXd& qdot, std::size_t c,
                                           CompiledSystemData& data) {
  FrictionPhase& phase = data.friction_phase[c];
  phase.stick = true;
  Eigen::VectorXd qddot, lambda;
  compiled_.solve(t, q, qdot, parameters_, qddot, lambda, data);
  if (held(c, data)) return "contact " + name_of(c) + " sticks";
  phase.stick = false;
  phase.direction = against_holding_force(c, data);
  return "contact " + name_of(c) + " slides on (static friction too weak to hold it)";
}

}  // namespace unidyn
