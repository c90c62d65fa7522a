// Stick and slip of the rough contacts (book §2.11, (2.27)–(2.30); §5.6): each slides or sticks,
// and events switch it.
//   sliding: the event is ĉ · v_t − |v_t|/2 reaching 0, ĉ the slip's direction when the phase
//            began or was last re-armed: the slip stopped (1-D: it would reverse) — then the
//            contact sticks if the force that holds it is inside the static cone |R_t| ≤ μ_s |N|,
//            and slides on along −R_t otherwise — or it turned by 60°, which re-arms ĉ (a new
//            start without a row, before the friction would fall back on ĉ at 90°);
//   sticking: the event is μ_s |N| − |R_t| reaching 0; the contact then slides along −R_t.
// An event decides its contact together with the other contacts at rest — stuck, or sliding with
// a slip that stopped at the same instant — that a constraint couples to it (e.g. ẋ2 = x2 ẋ1: the
// slips stop together, and the other's event function is ≤ 0 before it could be handled): all stick
// if every holding force is inside its static cone; else all slide, each along the slip
// acceleration the motion starts with when their friction is off, if every slip then accelerates
// along it with the friction on (a stuck one that is not held: no); else they are held together —
// one contact's share of a coupled holding force is not its own (the stick rows are dependent) —
// and their event is the instant sliding together becomes consistent. A contact alone is decided as
// above.
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

  // Event `which` at (t, q, q̇): the new phases; what happened, a line per contact decided (none
  // when only the slip turned).
  std::vector<std::string> handle(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                  std::size_t which, CompiledSystemData& data);

 private:
  // Sticks contact c if its holding force is inside the static cone, else slides along −R_t.
  std::string stick_or_slide(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                             std::size_t c, CompiledSystemData& data);
  // The contacts decided with contact c: c and those at rest (stuck, or sliding with a slip that
  // stopped) coupled to it, directly or through others.
  std::vector<std::size_t> group_of(std::size_t c, const CompiledSystemData& data) const;
  // The new phases of contacts `group` (above); a line for each change.
  std::vector<std::string> decide(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                                  const std::vector<std::size_t>& group, CompiledSystemData& data);
  // Sets `group` sliding together, each along its slip acceleration with their friction off (or
  // stuck without one); the least slip acceleration along its direction with the friction on,
  // negative if a stuck one is not held or none moves: > 0 when sliding together is consistent.
  double slide_together(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot,
                        const std::vector<std::size_t>& group, CompiledSystemData& data);
  // Whether a constraint that holds couples the slips of contacts c and o: the tangent rows t·J of
  // the two are dependent given the constraint rows (their stick rows cannot all be kept).
  bool coupled(std::size_t c, std::size_t o, const CompiledSystemData& data) const;
  // t·J for each tangent t of contact c
  Eigen::MatrixXd tangent_rows(std::size_t c, const CompiledSystemData& data) const;
  // Whether the holding force of contact c (stuck) is inside its static cone |R_t| ≤ μ_s |N|.
  bool held(std::size_t c, const CompiledSystemData& data) const;
  // The slip acceleration of contact c: the tangential part of J q̈ + the acceleration bias.
  Eigen::Vector3d slip_acceleration(std::size_t c, const Eigen::VectorXd& qddot,
                                    const CompiledSystemData& data) const;
  // "'name'" of contact c
  std::string name_of(std::size_t c) const;
  // |R_t| and |N| of contact c from the last solve
  std::pair<double, double> tangential_and_normal(std::size_t c,
                                                  const CompiledSystemData& data) const;
  // −R_t/|R_t|: the way contact c slides when its static friction cannot hold it
  Eigen::Vector3d against_holding_force(std::size_t c, const CompiledSystemData& data) const;

  const System& system_;
  const CompiledSystem& compiled_;
  std::span<const double> parameters_;
  // Contacts stuck together that do not each hold alone: their event is the slide_together margin.
  std::vector<bool> held_together_;
};

}  // namespace unidyn
