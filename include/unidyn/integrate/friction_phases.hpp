// Stick and slip of the rough contacts (book §2.11, (2.27)–(2.30); §5.6): each slides or sticks,
// and events switch it.
//   sliding: the event is ĉ · v_t − |v_t|/2 reaching 0, ĉ the slip's direction when the phase
//            began or was last re-armed: the slip stopped (1-D: it would reverse) — then the
//            contact sticks if the force that holds it is inside the static cone |R_t| ≤ μ_s |N|,
//            and slides on along −R_t otherwise — or it turned by 60°, which re-arms ĉ (a new
//            start without a row, before the friction would fall back on ĉ at 90°);
//   sticking: the event is μ_s |N| − |R_t| reaching 0; the contact then slides along −R_t.
#pragma once

#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

class FrictionPhases {
 public:
  FrictionPhases(const System& system, const CompiledSystem& compiled,
                 std::span<const double> parameters);

  std::size_t event_count() const { return compiled_.friction_constraints().size(); }

  // Each contact's phase at the start (into data.friction_phase); a summary line per contact.
  std::vector<std::string> start(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                 CompiledSystemData& data);

  // One event function per contact, for the phases in data.
  void events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
              CompiledSystemData& data, std::span<double> g);

  // Event `which` at (t, q, q̇): the new phase; what happened (empty when only the slip turned).
  std::string handle(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                     std::size_t which, CompiledSystemData& data);

 private:
  // Sticks contact c if its holding force is inside the static cone, else slides along −R_t.
  std::string stick_or_slide(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                             std::size_t c, CompiledSystemData& data);
  // |R_t| and |N| of contact c from the last solve
  std::pair<double, double> tangential_and_normal(std::size_t c,
                                                  const CompiledSystemData& data) const;
  // −R_t/|R_t|: the way contact c slides when its static friction cannot hold it
  Eigen::Vector3d against_holding_force(std::size_t c, const CompiledSystemData& data) const;

  const System& system_;
  const CompiledSystem& compiled_;
  std::span<const double> parameters_;
};

}  // namespace unidyn
