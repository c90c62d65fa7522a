// Unilateral constraints Ψ ≥ 0 (book §2.6, §2.10, §5.x): a contact holds while its force pushes
// (λ ≥ 0, the force λ ∂Ψ/∂r pointing to Ψ > 0) and is lost when λ reaches 0; a free constraint is
// met when Ψ reaches 0, with an impact of restitution e: the impulse P = ν ∂Ψ/∂q (with the other
// active constraints' impulses keeping them) takes the approach rate Ψ̇⁻ to Ψ̇⁺ = −e Ψ̇⁻; e = 0 (or a
// rebound too slow to matter) makes the contact hold from then on, if its force pushes.
// A velocity constraint with `off_while: contact` is off while that contact holds, and switches on
// when it is lost, with the impulse ν that makes it hold (the rows that hold keep their rates):
// book §2.10, Fig. 2.10b, the jumps I_c1 (the wall) and I_c2 (the constraint ẏ = 0).
#pragma once

#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "unidyn/model/system.hpp"
#include "unidyn/numeric/compiled_system.hpp"

namespace unidyn {

class Contacts {
 public:
  Contacts(const System& system, const CompiledSystem& compiled,
           std::span<const double> parameters);

  // Whether each constraint holds now (bilateral ones always); give it to the solver's data.
  const std::vector<bool>& active() const { return active_; }
  bool any() const { return !unilateral_.empty(); }

  // The phase at the start: a unilateral constraint holds when Ψ ≈ 0, Ψ̇ ≈ 0 and its force pushes.
  // Returns a line for the run summary per contact ("'table' in contact").
  std::vector<std::string> start(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot);

  // One event function per unilateral constraint: λ while it holds, Ψ while free.
  std::size_t event_count() const { return unilateral_.size(); }
  void events(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, std::span<double> g);

  // Event `which` at (t, q, q̇): the contact is lost, or met (impact). Changes q̇ for an impact;
  // returns what happened, for the run summary ("contact 'table' lost ...").
  std::string handle(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot, std::size_t which);

  // The impulses so far that took kinetic energy away: impacts with restitution < 1, contacts
  // made (plastic) and constraints switched on with a jump.
  std::size_t dissipative_impacts() const { return dissipative_impacts_; }

 private:
  // q̇ after an impulse that sets the rates of the rows to `target` (others active: 0 change);
  // returns row k's impulse ν.
  double impulse(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot, std::size_t k,
                 double target);
  // Activates k if its force then pushes; returns whether it does.
  bool try_hold(double t, const Eigen::VectorXd& q, const Eigen::VectorXd& qdot, std::size_t k);
  // The constraints switched by contact k: off while it holds (`holds`), on otherwise.
  void switch_by(std::size_t k, bool holds);
  // Switches on, with the jump that makes them hold, the constraints contact k has released;
  // returns "; 'c' switches on: impulse ν" for each.
  std::string switch_on(double t, const Eigen::VectorXd& q, Eigen::VectorXd& qdot, std::size_t k);

  const System& system_;
  const CompiledSystem& compiled_;
  std::span<const double> parameters_;
  CompiledSystemData data_;
  std::vector<std::size_t> unilateral_;  // constraint index per event function
  std::vector<double> restitution_;
  std::vector<bool> active_;
  std::vector<std::pair<std::size_t, std::size_t>> switched_;  // (constraint, its contact)
  std::size_t dissipative_impacts_ = 0;
};

// Below this rebound rate (of Ψ̇, in the constraint's units per second) an impact ends in contact:
// the bounces of a ball coming to rest would otherwise never end (Zeno).
inline constexpr double kRestingRebound = 1e-6;

}  // namespace unidyn
